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

#include "slab3D.H"
#include "forEachSphereOverlap.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidageModels
{
    defineTypeNameAndDebug(slab3D, 0);
    addToRunTimeSelectionTable(voidageModel, slab3D, grid);
}
}


Foam::voidageModels::slab3D::slab3D
(
    const dictionary& dict,
    const cartesianGrid& grid,
    const scalar voidageMin
)
:
    voidageModel(grid, voidageMin)
{
    requireOneCellThick(dict);
}


Foam::voidageModels::slab3D::slab3D
(
    const cartesianGrid& grid,
    const scalar voidageMin,
    const label stride
)
:
    voidageModel(grid, voidageMin, stride)
{}


Foam::string Foam::voidageModels::slab3D::description() const
{
    OStringStream os;
    os  << "voidage model slab3D: spheres in a slab " << grid_.depth()
        << " m deep (the mesh's thickness), eps = 1 - (sphere volume in the"
        << " cell column)/(cell volume), used as it is";
    return os.str();
}


void Foam::voidageModels::slab3D::checkDiameters
(
    const dictionary& dict,
    const scalarList& diameters
) const
{
    const scalar depth = grid_.depth();
    for (const scalar d : diameters)
    {
        if (!(d < depth))
        {
            FatalIOErrorInFunction(dict)
                << "voidageModel slab3D in " << dict.name() << ": particles"
                << " of diameter " << d << " m do not fit in the slab, whose"
                << " depth is the mesh's thickness " << depth
                << " m (system/bedGeometry depth); each class's 'diameter'"
                << " must be less than the depth" << exit(FatalIOError);
        }
    }
}


void Foam::voidageModels::slab3D::updateOverlaps
(
    const label n,
    const double* x,
    const double* y,
    const double*,
    const double* d,
    const label nThreads
)
{
    storeOverlaps
    (
        n, d, nThreads,
        [this, x, y](const label i, const scalar r, const auto& op)
        {
            forEachSphereOverlap(grid_, x[i], y[i], r, op);
        },
        [](const scalar r) { return 4*constant::mathematical::pi*r*r*r/3; }
    );
}


void Foam::voidageModels::slab3D::updateFields
(
    const label n,
    const double* d,
    scalarField& voidage,
    scalarField& phiP
)
{
    const scalar Vc = grid_.cellVolume();

    phiP = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar r = 0.5*d[i];
        const scalar VpByVc = 4*constant::mathematical::pi*r*r*r/(3*Vc);
        for (label k = stride_*i; k < stride_*i + counts_[i]; ++k)
        {
            phiP[cells_[k]] += VpByVc*fractions_[k];
        }
    }

    forAll(voidage, c)
    {
        voidage[c] = max(1 - phiP[c], voidageMin_);
    }
}


void Foam::voidageModels::slab3D::reportBalance
(
    Ostream& os,
    const label n,
    const double* d,
    const scalarField& phiP
) const
{
    scalar particleVolume = 0;
    for (label i = 0; i < n; ++i)
    {
        particleVolume += constant::mathematical::pi*d[i]*d[i]*d[i]/6;
    }

    os  << "Exchange: particle volume " << particleVolume
        << " m3, mapped to cells " << gSum(phiP)*grid_.cellVolume()
        << " m3" << endl;
}


// ************************************************************************* //
