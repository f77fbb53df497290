/*---------------------------------------------------------------------------*\
    bandedCholesky: direct L D L^T solver in band storage (see the header).
\*---------------------------------------------------------------------------*/

#include "bandedCholesky.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"

#include <limits>

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


void Foam::bandedCholesky::factorise
(
    const label b,
    scalarField& L,
    scalarField& D
) const
{
    const label n = matrix_.diag().size();
    const labelUList& lower = matrix_.lduAddr().lowerAddr();
    const labelUList& upper = matrix_.lduAddr().upperAddr();
    const scalarField& offDiag = matrix_.upper();   // symmetric: lower == upper

    // Row i holds columns i-b .. i-1 at L[i*b + (j - i + b)]
    L.setSize(n*b);
    L = 0;
    D = matrix_.diag();
    forAll(lower, facei)
    {
        const label i = upper[facei];
        const label j = lower[facei];
        L[i*b + j - i + b] = offDiag[facei];
    }

    // Row by row. While row i is worked on, its entries hold
    // w_k = L(i,k) D(k), the unscaled values; the dot products below run
    // over contiguous memory of rows i and j.
    const scalar sign = (D.size() && D[0] < 0) ? -1 : 1;
    scalar* __restrict__ Lp = L.begin();

    for (label i = 0; i < n; ++i)
    {
        scalar* __restrict__ rowI = Lp + i*b - (i - b);     // rowI[k], k >= i-b
        const label lo = max(label(0), i - b);

        for (label j = lo; j < i; ++j)
        {
            // The dot product in four independent sums: one chain of
            // dependent additions would leave the multipliers idle
            const scalar* __restrict__ rowJ = Lp + j*b - (j - b);
            scalar s0 = rowI[j], s1 = 0, s2 = 0, s3 = 0;
            label k = max(lo, j - b);
            for (; k + 3 < j; k += 4)
            {
                s0 -= rowI[k]*rowJ[k];
                s1 -= rowI[k + 1]*rowJ[k + 1];
                s2 -= rowI[k + 2]*rowJ[k + 2];
                s3 -= rowI[k + 3]*rowJ[k + 3];
            }
            for (; k < j; ++k)
            {
                s0 -= rowI[k]*rowJ[k];
            }
            rowI[j] = (s0 + s1) + (s2 + s3);
        }

        scalar d = D[i];
        for (label k = lo; k < i; ++k)
        {
            const scalar lik = rowI[k]/D[k];
            d -= lik*rowI[k];
            rowI[k] = lik;
        }

        // A definite matrix keeps the sign of its pivots; a singular one
        // ends with a pivot at round-off level (n eps of the diagonal; the
        // smallest pivot of a sound pressure matrix is ~ diag/rows)
        if (!(sign*d > 10*n*std::numeric_limits<scalar>::epsilon()*mag(matrix_.diag()[i])))
        {
            FatalErrorInFunction
                << "solver bandedCholesky for " << fieldName_
                << ": the matrix is singular or not definite (pivot " << d
                << " of cell " << i << ", diagonal " << matrix_.diag()[i]
                << "). A pressure equation needs a fixed-value boundary"
                << " or a reference level"
                << exit(FatalError);
        }
        D[i] = d;
    }
}


void Foam::bandedCholesky::substitute
(
    const label b,
    const scalarField& L,
    const scalarField& D,
    scalarField& x
)
{
    const label n = x.size();
    const scalar* __restrict__ Lp = L.cdata();

    // L y = r
    for (label i = 0; i < n; ++i)
    {
        const scalar* __restrict__ rowI = Lp + i*b - (i - b);
        scalar s = x[i];
        for (label k = max(label(0), i - b); k < i; ++k)
        {
            s -= rowI[k]*x[k];
        }
        x[i] = s;
    }

    // D z = y
    x /= D;

    // L^T x = z, by columns of L^T (rows of L, contiguous)
    for (label i = n - 1; i >= 0; --i)
    {
        const scalar* __restrict__ rowI = Lp + i*b - (i - b);
        const scalar xi = x[i];
        for (label k = max(label(0), i - b); k < i; ++k)
        {
            x[k] -= rowI[k]*xi;
        }
    }
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

        scalarField L;
        scalarField D;
        factorise(b, L, D);

        // Solve for the correction of the current psi: the residual form
        // keeps the round-off relative to the correction
        substitute(b, L, D, residual);
        psi += residual;

        matrix_.Amul(Apsi, psi, interfaceBouCoeffs_, interfaces_, cmpt);
        solverPerf.finalResidual() = gSumMag(source - Apsi)/normFactor;
        solverPerf.nIterations() = 1;
        solverPerf.checkConvergence(tolerance_, relTol_);
    }

    return solverPerf;
}


// ************************************************************************* //
