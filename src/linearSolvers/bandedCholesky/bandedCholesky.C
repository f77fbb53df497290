/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
-------------------------------------------------------------------------------
    bandedCholesky: direct banded Cholesky solver by LAPACK (see the header).
\*---------------------------------------------------------------------------*/

#include "bandedCholesky.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"

#include <cstddef>
#include <limits>

// * * * * * * * * * * * * * * * * LAPACK  * * * * * * * * * * * * * * * * * //

// LAPACK's banded Cholesky (Fortran; the trailing arguments are the
// lengths of the character arguments, gfortran's convention). The sizes are
// Fortran integers: the project's labels are 32-bit (etc/bashrc)
static_assert(sizeof(Foam::label) == sizeof(int), "LAPACK takes int sizes");

extern "C"
{
    void dpbtrf_
    (
        const char* uplo, const int* n, const int* kd, double* ab,
        const int* ldab, int* info, std::size_t uploLen
    );

    void dpbtrs_
    (
        const char* uplo, const int* n, const int* kd, const int* nrhs,
        const double* ab, const int* ldab, double* b, const int* ldb,
        int* info, std::size_t uploLen
    );
}

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bandedCholesky, 0);

    lduMatrix::solver::addsymMatrixConstructorToTable<bandedCholesky>
        addbandedCholeskySymMatrixConstructorToTable_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bandedCholesky::bandedCholesky
(
    const word& fieldName,
    const lduMatrix& matrix,
    const FieldField<Field, scalar>& interfaceBouCoeffs,
    const FieldField<Field, scalar>& interfaceIntCoeffs,
    const lduInterfaceFieldPtrsList& interfaces,
    const dictionary& solverControls
)
:
    lduMatrix::solver
    (
        fieldName,
        matrix,
        interfaceBouCoeffs,
        interfaceIntCoeffs,
        interfaces,
        solverControls
    ),
    maxBandwidth_(solverControls.lookupOrDefault<label>("maxBandwidth", 200))
{
    // Its own entries and those lduMatrix::solver and fvMatrix::solve read
    checkKnownEntries
    (
        solverControls,
        {
            "solver", "tolerance", "relTol", "maxBandwidth", "maxIter",
            "minIter", "type"
        },
        "system/fvSolution solvers/" + fieldName + " (solver bandedCholesky)"
    );

    if (maxBandwidth_ < 1)
    {
        FatalIOErrorInFunction(solverControls)
            << "maxBandwidth " << maxBandwidth_ << " for " << fieldName
            << " is outside the allowed range [1, inf)"
            << exit(FatalIOError);
    }

    forAll(interfaces, patchi)
    {
        if (interfaces.set(patchi))
        {
            FatalIOErrorInFunction(solverControls)
                << "solver bandedCholesky for " << fieldName
                << " cannot take coupled boundaries (processor, cyclic):"
                << " patch " << patchi << " is one. Run in serial on a mesh"
                << " without them, or use GAMG"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::label Foam::bandedCholesky::bandwidth() const
{
    const labelUList& l = matrix_.lduAddr().lowerAddr();
    const labelUList& u = matrix_.lduAddr().upperAddr();

    label b = 0;
    forAll(l, facei)
    {
        b = max(b, u[facei] - l[facei]);
    }
    return b;
}


Foam::scalar Foam::bandedCholesky::factorise
(
    const label b,
    scalarField& band
) const
{
    const label n = matrix_.diag().size();
    const scalarField& diag = matrix_.diag();
    const labelUList& lower = matrix_.lduAddr().lowerAddr();
    const labelUList& upper = matrix_.lduAddr().upperAddr();
    const scalarField& offDiag = matrix_.upper();   // symmetric: lower == upper

    // LAPACK factorises positive definite matrices: a negative definite one
    // (the finite-volume Laplacian) is negated
    const scalar sign = (n && diag[0] < 0) ? -1 : 1;

    // Lower band, column-major: A(i, j), j <= i <= j+b, at (i - j) + j (b+1)
    const label ldab = b + 1;
    band.setSize(n*ldab);
    band = 0;
    for (label j = 0; j < n; ++j)
    {
        band[j*ldab] = sign*diag[j];
    }
    forAll(lower, facei)
    {
        const label j = lower[facei];
        band[upper[facei] - j + j*ldab] = sign*offDiag[facei];
    }

    int info = 0;
    dpbtrf_("L", &n, &b, band.data(), &ldab, &info, 1);

    // A definite matrix has positive pivots: LAPACK stops at the first that
    // is not (info > 0); a singular one may instead end with a pivot at
    // round-off level (n eps of the diagonal; the smallest pivot of a sound
    // pressure matrix is ~ diag/rows)
    label bad = info > 0 ? info - 1 : -1;
    for (label i = 0; bad < 0 && i < n; ++i)
    {
        if (!(sqr(band[i*ldab]) > 10*n*std::numeric_limits<scalar>::epsilon()*mag(diag[i])))
        {
            bad = i;
        }
    }
    if (info < 0 || bad >= 0)
    {
        FatalErrorInFunction
            << "solver bandedCholesky for " << fieldName_
            << ": the matrix is singular or not definite (LAPACK dpbtrf"
            << " info " << info << ", cell " << bad << ", diagonal "
            << (bad >= 0 ? diag[bad] : 0) << "). A pressure equation needs"
            << " a fixed-value boundary or a reference level"
            << exit(FatalError);
    }

    return sign;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::solverPerformance Foam::bandedCholesky::solve
(
    scalarField& psi,
    const scalarField& source,
    const direction cmpt
) const
{
    solverPerformance solverPerf(typeName, fieldName_);

    const label n = psi.size();
    scalarField Apsi(n);
    scalarField work(n);

    matrix_.Amul(Apsi, psi, interfaceBouCoeffs_, interfaces_, cmpt);
    const scalar normFactor = this->normFactor(psi, source, Apsi, work);

    scalarField residual(source - Apsi);
    solverPerf.initialResidual() = gSumMag(residual)/normFactor;
    solverPerf.finalResidual() = solverPerf.initialResidual();

    if
    (
        minIter_ > 0
     || !solverPerf.checkConvergence(tolerance_, relTol_)
    )
    {
        const label b = bandwidth();
        if (b > maxBandwidth_)
        {
            FatalIOErrorInFunction(controlDict_)
                << "solver bandedCholesky for " << fieldName_
                << ": the matrix's half-bandwidth " << b
                << " is outside the allowed range [0, " << maxBandwidth_
                << "] (entry maxBandwidth). Renumber the mesh"
                << " (renumberMesh) or use GAMG"
                << exit(FatalIOError);
        }

        scalarField band;
        const scalar sign = factorise(b, band);

        // Solve for the correction of the current psi: the residual form
        // keeps the round-off relative to the correction
        residual *= sign;
        const label ldab = b + 1;
        const int nrhs = 1;
        int info = 0;
        dpbtrs_
        (
            "L", &n, &b, &nrhs, band.cdata(), &ldab, residual.data(), &n,
            &info, 1
        );
        psi += residual;

        matrix_.Amul(Apsi, psi, interfaceBouCoeffs_, interfaces_, cmpt);
        solverPerf.finalResidual() = gSumMag(source - Apsi)/normFactor;
        solverPerf.nIterations() = 1;
        solverPerf.checkConvergence(tolerance_, relTol_);
    }

    return solverPerf;
}


// ************************************************************************* //
