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
Application
    Test-bandedCholesky

Description
    Checks of the bandedCholesky direct solver with manufactured solutions:
    on the case's mesh, the Laplacian of a chosen field phiExact with a
    coefficient that jumps over 5 decades from cell to cell (as the voidage
    times rAU of a bubbling bed) is the source; solving for phi must give
    phiExact back to round-off, for the negative definite Laplacian and for
    its positive definite negative, in one solve. The same problem solved by
    PCG to 1e-14 agrees. Ends with the line "N passed, M failed".

    Options:
      -fixedPatch <name>   the fixed-value patch (default outlet)
    and for the error checks of the calling script:
      -singular            no fixed-value boundary and no reference level
      -maxBandwidth <b>    a limit below the mesh's bandwidth

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "Random.H"

using namespace Foam;

static label nPassed = 0, nFailed = 0;

static void checkBelow
(
    const std::string& what, const scalar value, const scalar limit
)
{
    const bool ok = value <= limit;
    (ok ? nPassed : nFailed)++;
    Info<< (ok ? "PASS " : "FAIL ") << what.c_str() << ": " << value
        << " (limit " << limit << ")" << endl;
}


static dictionary solverControls(const word& solver, const label maxBandwidth)
{
    dictionary dict;
    dict.add("solver", solver);
    if (solver != "bandedCholesky")
    {
        dict.add("preconditioner", "DIC");  // bandedCholesky refuses it
    }
    dict.add("tolerance", 1e-14);
    dict.add("relTol", 0.0);
    dict.add("maxIter", 100000);
    if (maxBandwidth > 0)
    {
        dict.add("maxBandwidth", maxBandwidth);
    }
    return dict;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addBoolOption("singular", "all boundaries zero-gradient");
    argList::addOption("maxBandwidth", "b", "limit of the direct solver");
    argList::addOption("fixedPatch", "name", "the fixed-value patch (outlet)");
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const bool singular = args.found("singular");
    const label maxBandwidth = args.lookupOrDefault<label>("maxBandwidth", 0);
    const word fixedPatch = args.lookupOrDefault<word>("fixedPatch", "outlet");

    // Boundary conditions of the gas pressure: fixed at the outlet, zero
    // gradient elsewhere (all zero gradient for -singular). Fixed at the
    // inlet instead, the last rows factorised (the top) get the smallest
    // pivots: a sound matrix that the singularity check must not refuse.
    wordList patchTypes(mesh.boundary().size(), "zeroGradient");
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].type() == "empty")
        {
            patchTypes[patchi] = "empty";
        }
        else if (!singular && mesh.boundary()[patchi].name() == fixedPatch)
        {
            patchTypes[patchi] = "fixedValue";
        }
    }

    // Coefficient: log-uniform in [1e-5, 1] cell by cell
    Random rnd(2012);
    volScalarField gamma
    (
        IOobject("gamma", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1.0),
        "zeroGradient"
    );
    forAll(gamma, celli)
    {
        gamma[celli] = std::pow(10.0, -5*rnd.sample01<scalar>());
    }
    gamma.correctBoundaryConditions();
    const surfaceScalarField gammaf(fvc::interpolate(gamma));

    // Manufactured solution: smooth plus cell-to-cell noise, zero at the
    // outlet value
    volScalarField phiExact
    (
        IOobject("phiExact", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("zero", dimless, 0.0),
        patchTypes
    );
    const vectorField& C = mesh.C();
    forAll(phiExact, celli)
    {
        phiExact[celli] =
            1 + std::sin(7*C[celli].x())*std::cos(3*C[celli].y())
          + 0.1*rnd.sample01<scalar>();
    }
    phiExact.correctBoundaryConditions();

    const volScalarField source(fvc::laplacian(gammaf, phiExact));
    const scalar scale = gMax(mag(phiExact.primitiveField()));

    for (const scalar sign : {1.0, -1.0})
    {
        volScalarField phi
        (
            IOobject("phi", runTime.timeName(), mesh),
            mesh,
            dimensionedScalar("zero", dimless, 0.0),
            patchTypes
        );
        fvScalarMatrix eqn(sign*fvm::laplacian(gammaf, phi) == sign*source);

        const solverPerformance perf =
            eqn.solve(solverControls("bandedCholesky", maxBandwidth));

        const std::string which(sign > 0 ? "negative" : "positive");
        checkBelow
        (
            "bandedCholesky, " + which + " definite: max |phi - phiExact|"
            "/max |phiExact|",
            gMax(mag(phi.primitiveField() - phiExact.primitiveField()))/scale,
            1e-9
        );
        checkBelow
        (
            "bandedCholesky, " + which + " definite: final normalised"
            " residual",
            perf.finalResidual(), 1e-13
        );
        checkBelow
        (
            "bandedCholesky, " + which + " definite: solves",
            perf.nIterations(), 1
        );

        if (sign > 0)
        {
            volScalarField phiPCG
            (
                IOobject("phiPCG", runTime.timeName(), mesh),
                mesh,
                dimensionedScalar("zero", dimless, 0.0),
                patchTypes
            );
            fvScalarMatrix eqnPCG(fvm::laplacian(gammaf, phiPCG) == source);
            eqnPCG.solve(solverControls("PCG", 0));
            checkBelow
            (
                "bandedCholesky against PCG to 1e-14: max difference"
                "/max |phiExact|",
                gMax(mag(phi.primitiveField() - phiPCG.primitiveField()))
               /scale,
                1e-8
            );
        }
    }

    Info<< nl << nPassed << " passed, " << nFailed << " failed" << endl;
    if (nFailed)
    {
        // Not a return value: argList's destructor ends the run with 0
        FatalErrorInFunction
            << nFailed << " checks failed" << exit(FatalError);
    }
    return 0;
}


// ************************************************************************* //
