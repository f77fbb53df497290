/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"

#include <exception>
#include <omp.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The values of a field (internal, then its boundary conditions) as a time
// directory holds them under the field's name
template<class FieldType>
void readSavedValues(FieldType& field, const Foam::fvMesh& mesh)
{
    using namespace Foam;
    const FieldType saved
    (
        IOobject
        (
            field.name(),
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false               // the field itself is registered
        ),
        mesh
    );
    field.primitiveFieldRef() = saved.primitiveField();
    field.correctBoundaryConditions();
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpmCloud::readExchange()
{
    // Kc, Fp and U* are written only by a concurrent run; with them, the
    // voidage of the time is the one its gas took (a step behind the
    // particles), the old-time level of the next step
    IOobject probe
    (
        Kc_.name(),
        mesh_.time().timeName(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!probe.typeHeaderOk<volScalarField>(true))
    {
        Info<< "Coupling: no reaction saved at time "
            << mesh_.time().timeName() << "; the first step is sequential"
            << endl;
        return;
    }
    readSavedValues(Kc_, mesh_);
    readSavedValues(Fp_, mesh_);
    readSavedValues(Ustar_, mesh_);
    readSavedValues(voidage_, mesh_);
    exchangeReady_ = true;
    Info<< "Coupling: the reaction and the gas's voidage of time "
        << mesh_.time().timeName() << " read (Kc, Fp, Ustar, voidage); the"
        << " concurrent schedule continues from them" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::dpmCloud::advanceBeside(const std::function<void()>& gasStep)
{
    // One team of the threads that run the coupling's loops: its worker,
    // which would otherwise spin idle through the gas step on the core the
    // DEM needs, runs the DEM (its own loops nested inside, on nThreads);
    // the gas stays on the main thread. The DEM touches only its own
    // arrays and the inputs interpolateGas gave it, the gas only the
    // cells' fields: nothing is shared. An exception must not leave the
    // parallel region: the DEM's is kept and thrown after it.
    std::exception_ptr demError;
    omp_set_max_active_levels(2);
    #pragma omp parallel num_threads(2)
    {
        // A team cut to one thread (OMP_THREAD_LIMIT) runs both in turn
        const int thread = omp_get_thread_num();
        if (thread == 0)
        {
            gasStep();
        }
        if (thread == 1 || omp_get_num_threads() == 1)
        {
            try
            {
                advanceParticles();
            }
            catch (...)
            {
                demError = std::current_exception();
            }
        }
    }
    if (demError)
    {
        guarded(advanceError, [&]{ std::rethrow_exception(demError); });
    }
}


// ************************************************************************* //
