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
    Test-unstructuredGrid: the quadrature's shares of a sphere against the
    exact sphere-box volumes of cartesianGrid (forEachSphereBoxOverlap.H,
    checked against a quadrature by Test-sphereBoxOverlap) on the box, its
    error's convergence with the number of points, and on the cylinder the
    volume and the forces the shares hand over (suite UnstructuredShares).
\*---------------------------------------------------------------------------*/

#include "unstructuredGridTests.H"
#include "voidageModel.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{

//- The largest difference of a cell's share, as a fraction of the sphere
scalar worstShareError
(
    const gasGrid& grid,
    const cartesianGrid& exact,
    const point& c,
    const scalar d,
    const scalar spreadingDiameter = 0
)
{
    return max
    (
        mag
        (
            sharesOf(grid, c, d, spreadingDiameter)
          - sharesOf(exact, c, d, spreadingDiameter)
        )
    );
}

} // End anonymous namespace


// The cell (2, 2, 2): 20 to 30 mm each way. A particle a cell across
// at its centre, on its face, edge and corner; a sphere spread over
// two cells at the corner. The design's aim, 1 % of the sphere's volume in
// any cell, is the tolerance; at a face a plane through the centre halves
// the points exactly (1e-14)
TEST(UnstructuredShares, ExactAtACentreFaceEdgeAndCornerOfTheBox)
{
    const fvMesh& box = boxMesh();
    const cartesianGrid exact(box);
    const unstructuredGrid grid(box);
    const scalar h = exact.dx();
    const label N = grid.quadrature().size();
    const scalar tol = 0.01;
    const point centre(0.025, 0.025, 0.025);
    const vector offsets[] =
    {
        vector(0, 0, 0), vector(0.5, 0, 0), vector(0.5, 0.5, 0),
        vector(0.5, 0.5, 0.5)
    };
    const char* names[] = {"a cell centre", "a face", "an edge", "a corner"};
    for (label k = 0; k < 4; ++k)
    {
        const point c = centre + h*offsets[k];
        const scalar e = worstShareError(grid, exact, c, h);
        check
        (
            std::string("shares at ") + names[k] + " (d = h, N = "
          + std::to_string(N) + "): cartesianGrid's exact, worst cell",
            1 + e, 1, tol
        );
    }
    check
    (
        "a plane through the centre halves the points: at a face exactly",
        1 + worstShareError(grid, exact, centre + h*offsets[1], h), 1, 1e-14
    );
    check
    (
        "spread over 2h at a corner: the exact shares, worst cell",
        1 + worstShareError(grid, exact, centre + h*offsets[3], h, 2*h), 1, tol
    );
}


//- 4000 places at random in the box (seed 11)
static List<point> randomPlaces(const fvMesh& box)
{
    Random rnd(11);
    const label nSpheres = 4000;
    List<point> at(nSpheres);
    for (point& p : at)
    {
        p = box.bounds().min() + cmptMultiply(box.bounds().span(), rnd.sample01<vector>());
    }
    return at;
}


// Anywhere in the box, the walls included (a part beyond stays with
// the cell inside, as cartesianGrid's): the exact shares, 1 % of the
// sphere in the worst cell (the design's aim)
TEST(UnstructuredShares, ExactAtRandomPlacesInTheBox)
{
    const fvMesh& box = boxMesh();
    const cartesianGrid exact(box);
    const unstructuredGrid grid(box);
    const scalar h = exact.dx();
    const scalar tol = 0.01;
    const List<point> at(randomPlaces(box));
    const label nSpheres = at.size();
    scalar worst = 0, rms = 0;
    for (const point& p : at)
    {
        const scalar e = worstShareError(grid, exact, p, h);
        worst = max(worst, e);
        rms += sqr(e)/nSpheres;
    }
    Info<< "    random places: worst cell " << worst << ", rms " << std::sqrt(rms)
        << " of the sphere" << endl;
    check("shares at " + std::to_string(nSpheres) + " random places (d = h): exact, worst cell", 1 + worst, 1, tol);
}


// The error's convergence with N (shells x directions), over 400 of the
// random places: below 1/2 from 512 to 8192 points (a point set's error
// for a convex cut falls as N^(-1/2) to N^(-2/3))
TEST(UnstructuredShares, ErrorFallsWithTheQuadraturesPoints)
{
    const fvMesh& box = boxMesh();
    const cartesianGrid exact(box);
    const scalar h = exact.dx();
    const List<point> at(randomPlaces(box));
    const label sizes[][2] = {{4, 64}, {8, 64}, {8, 128}, {16, 128}, {24, 128}, {32, 256}};
    scalar at512 = 0, at8192 = 0;
    Info<< "    N      worst cell    rms   (d = h, 400 places)" << endl;
    for (const auto& s : sizes)
    {
        const unstructuredGrid g(box, s[0], s[1]);
        scalar w = 0, r = 0;
        for (label i = 0; i < 400; ++i)
        {
            const scalar e = worstShareError(g, exact, at[i], h);
            w = max(w, e);
            r += sqr(e)/400;
        }
        Info<< "    " << s[0]*s[1] << "  " << w << "  " << std::sqrt(r) << endl;
        if (s[0]*s[1] == 512) at512 = w;
        if (s[0]*s[1] == 8192) at8192 = w;
    }
    check("the error falls with N: 8192 points below half 512's", at8192 < 0.5*at512, 1, 0);
}


//- 3000 particles anywhere in the cylinder (beside the curved wall part of
//  a sphere lies beyond it), seed 19
static void cylinderParticles
(
    const fvMesh& cylinder,
    Random& rnd,
    List<double>& x,
    List<double>& y,
    List<double>& z
)
{
    const label n = 3000;
    x.setSize(n); y.setSize(n); z.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const point p = randomPointInside(cylinder, rnd);
        x[i] = p.x(); y[i] = p.y(); z[i] = p.z();
    }
}


// The shares of 3000 particles (d = 0.9 h) on the cylinder, and spread over
// 2 cells: they add up to 1 (1e-13, round-off) and are >= 0; the same bit
// for bit on 2 threads; a force handed to the cells by them keeps the
// particles' sum (1e-14, round-off)
TEST(UnstructuredShares, SumSignThreadsAndReactionOnTheCylinder)
{
    const fvMesh& cylinder = cylinderMesh();
    const unstructuredGrid grid(cylinder);
    const scalar d = 0.9*grid.minCellSize();
    Random rnd(19);
    List<double> x, y, z;
    cylinderParticles(cylinder, rnd, x, y, z);
    const label n = x.size();
    const List<double> dp(n, d);
    for (const scalar Ds : {scalar(0), 2*grid.minCellSize()})
    {
        const std::string m = Ds > 0 ? " (spread over 2 cells)" : " (d = 0.9 h)";
        cellWeights w1, w2;
        grid.sphereShares(n, x.cdata(), y.cdata(), z.cdata(), dp.cdata(), Ds, 1, w1);
        grid.sphereShares(n, x.cdata(), y.cdata(), z.cdata(), dp.cdata(), Ds, 2, w2);
        scalar worstSum = 0, lowest = GREAT;
        label well = 0;
        for (label i = 0; i < n; ++i)
        {
            scalar sum = 0;
            for (label k = w1.stride*i; k < w1.stride*i + w1.counts[i]; ++k)
            {
                sum += w1.weights[k];
                lowest = min(lowest, w1.weights[k]);
            }
            worstSum = max(worstSum, mag(sum - 1));
            const scalar r = std::sqrt(sqr(x[i]) + sqr(z[i]));
            well += r < 0.05 - max(d, Ds);
        }
        check("shares add up to 1" + m, 1 + worstSum, 1, 1e-13);
        check("shares >= 0" + m, lowest >= 0, 1, 0);
        check("spheres well inside among them" + m, well > 1000, 1, 0);
        check
        (
            "2 threads: the same shares bit for bit" + m,
            sameWeights(w1, w2),
            1, 0
        );

        // A force on each particle, handed to the cells by its shares:
        // the cells' sum is the particles'
        vectorField Fc(cylinder.nCells(), Zero);
        vector Fp(Zero);
        for (label i = 0; i < n; ++i)
        {
            const vector F = rnd.sample01<vector>() - vector::uniform(0.5);
            Fp += F;
            for (label k = w1.stride*i; k < w1.stride*i + w1.counts[i]; ++k)
            {
                Fc[w1.cells[k]] += w1.weights[k]*F;
            }
        }
        check("the reaction: the cells' force sum = the particles'" + m, 1 + mag(sum(Fc) - Fp)/(0.25*n), 1, 1e-14);
    }
}


// voidageModel spheres3D on the cylinder: the mapped volume is the 3000
// particles' (1e-12, round-off), also spread
TEST(UnstructuredShares, Spheres3DMapsTheParticlesVolumeOnTheCylinder)
{
    const scalar pi = constant::mathematical::pi;
    const fvMesh& cylinder = cylinderMesh();
    const unstructuredGrid grid(cylinder);
    const scalarField& Vc = grid.cellVolumes();
    const scalar d = 0.9*grid.minCellSize();
    Random rnd(19);
    List<double> x, y, z;
    cylinderParticles(cylinder, rnd, x, y, z);
    const label n = x.size();
    const List<double> dp(n, d);
    for (const char* entries :
    {
        "voidageModel spheres3D;",
        "voidageModel spheres3D; spheres3DCoeffs { spreadingDiameter 0.01; }"
    })
    {
        autoPtr<voidageModel> model
        (
            voidageModel::New(dictionary(IStringStream(entries)()), grid, 0.05)
        );
        scalarField eps(cylinder.nCells()), phiP(cylinder.nCells());
        model->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), dp.cdata(), 2);
        model->updateFields(n, dp.cdata(), eps, phiP);
        check
        (
            std::string("spheres3D: mapped volume = particles' (") + entries + ")",
            sum(phiP*Vc), n*pi*pow3(d)/6, 1e-12
        );
    }
}


// ************************************************************************* //
