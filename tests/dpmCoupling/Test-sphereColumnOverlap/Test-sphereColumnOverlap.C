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
    Test-sphereColumnOverlap

Description
    Checks of the sphere-column volume of the slab mode
    (sphereColumnOverlap.H, forEachSphereOverlap.H) against numbers from
    outside the code: the sphere, half, quarter and the spherical cap
    pi H^2 (3R - H)/3 (textbook); an independent adaptive quadrature of the
    chord integral and Monte Carlo (columnQuadrature.H) at random cells cut
    by one to four planes; no NaN and no negative volume at tangency and
    with a corner on the sphere; the volumes of one sphere over a grid of
    cells add up to 4/3 pi R^3; the mapping to the paper's 20 x 120 mesh
    shares each sphere exactly. GoogleTest cases (suite
    SphereColumnOverlap), run in a case with that mesh:

        Test-sphereColumnOverlap -case <dir> [--gtest_filter=Suite.Name]

    With -benchmark, times the disc and the sphere mapping and the bare
    functions instead (benchmarks/sphereColumnOverlap).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cartesianGrid.H"
#include "forEachSphereOverlap.H"
#include "columnQuadrature.H"
#include "couplingTestMain.H"
#include "sphereColumnBenchmark.H"

#include <random>

using namespace Foam;

static const scalar pi = constant::mathematical::pi;
static const scalar R = 1.25e-3;
static const scalar Vs = 4*pi*R*R*R/3;
// Round-off of a handful of terms of size R^3
static const scalar roundOff = 1e-14*Vs;


// Limits (textbook): the sphere, half, a quarter; the cap of height H
// is pi H^2 (3R - H)/3; half a cap by symmetry
TEST(SphereColumnOverlap, TextbookLimits)
{
    const scalar xc = 0.3e-3, yc = -0.7e-3, big = 3*R;
    checkAbsolute("sphere in a wide column", sphereColumnOverlap(xc, yc, R, xc - big, xc + big, yc - big, yc + big), Vs, roundOff);
    checkAbsolute("half-space x > xc", sphereColumnOverlap(xc, yc, R, xc, xc + big, yc - big, yc + big), Vs/2, roundOff);
    checkAbsolute("half-space y < yc", sphereColumnOverlap(xc, yc, R, xc - big, xc + big, yc - big, yc), Vs/2, roundOff);
    checkAbsolute("quarter x > xc, y > yc", sphereColumnOverlap(xc, yc, R, xc, xc + big, yc, yc + big), Vs/4, roundOff);
    checkAbsolute("quarter x < xc, y < yc", sphereColumnOverlap(xc, yc, R, xc - big, xc, yc - big, yc), Vs/4, roundOff);
    for (const scalar h : {0.4*R, -0.3*R, 0.97*R})
    {
        const scalar H = R - h;
        const scalar cap = pi*H*H*(3*R - H)/3;
        const std::string at = " at " + std::to_string(h/R).substr(0, 5) + " R";
        checkAbsolute("cap x > xc + h" + at, sphereColumnOverlap(xc, yc, R, xc + h, xc + big, yc - big, yc + big), cap, roundOff);
        checkAbsolute("cap y < yc - h" + at, sphereColumnOverlap(xc, yc, R, xc - big, xc + big, yc - big, yc - h), cap, roundOff);
        // The same cap in two columns split by y = yc + 0.3 R: the
        // corner formula on either side
        const scalar split =
            sphereColumnOverlap(xc, yc, R, xc + h, xc + big, yc - big, yc + 0.3*R)
          + sphereColumnOverlap(xc, yc, R, xc + h, xc + big, yc + 0.3*R, yc + big);
        checkAbsolute("cap split in two columns" + at, split, cap, roundOff);
        checkAbsolute("half a cap x > xc + h, y > yc" + at, sphereColumnOverlap(xc, yc, R, xc + h, xc + big, yc, yc + big), cap/2, roundOff);
    }
    // A corner line on the sphere: nothing beyond it; symmetric in x, y
    const scalar p = 0.6*R, q = 0.8*R;
    checkAbsolute("corner on the sphere", sphereColumnOverlap(xc, yc, R, xc + p, xc + big, yc + q, yc + big), 0, roundOff);
    checkAbsolute
    (
        "symmetric in x and y",
        sphereColumnOverlap(xc, yc, R, xc + 0.2*R, xc + 0.7*R, yc - 0.5*R, yc + 0.1*R),
        sphereColumnOverlap(xc, yc, R, xc - 0.5*R, xc + 0.1*R, yc + 0.2*R, yc + 0.7*R),
        roundOff
    );
}


// Random cells against the quadrature, by the number of planes that cut
// the sphere (cells of 0.1 R to 3 R); quadrature to 1e-14 Vs
TEST(SphereColumnOverlap, RandomCellsAgainstQuadrature)
{
    std::mt19937_64 gen(17);
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst[5] = {0, 0, 0, 0, 0};
    label count[5] = {0, 0, 0, 0, 0};
    while (min(min(count[1], count[2]), min(count[3], count[4])) < 300)
    {
        const scalar r = (u(gen) < 0.5 ? 0.75e-3 : 1.25e-3);
        const scalar wx = (0.1 + 2.9*u(gen))*r, wy = (0.1 + 2.9*u(gen))*r;
        const scalar x0 = 0.01, y0 = 0.2;
        const scalar xc = x0 - r + u(gen)*(wx + 2*r);
        const scalar yc = y0 - r + u(gen)*(wy + 2*r);
        const scalar x1 = x0 + wx, y1 = y0 + wy;
        const label planes =
            (mag(x0 - xc) < r) + (mag(x1 - xc) < r)
          + (mag(y0 - yc) < r) + (mag(y1 - yc) < r);
        if (count[planes] >= 1000) continue;
        const scalar V = sphereColumnOverlap(xc, yc, r, x0, x1, y0, y1);
        const scalar V0 = 4*pi*r*r*r/3;
        const scalar Vq = columnQuadrature::quadratureColumnVolume
        (
            xc, yc, r, x0, x1, y0, y1, 1e-14*V0
        );
        ++count[planes];
        worst[planes] =
            max(worst[planes], std::isfinite(V) ? mag(V - Vq)/V0 : GREAT);
    }
    for (label k = 1; k <= 4; ++k)
    {
        checkAbsolute
        (
            "cells cut by " + std::to_string(k) + " of the 4 planes vs quadrature: 1 + worst error/(4/3 pi R^3) of "
          + std::to_string(count[k]),
            1 + worst[k], 1, 1e-12
        );
    }
    Info<< "    (" << count[0] << " uncut cells, worst " << worst[0] << ")" << endl;
}


// Monte Carlo (4e6 points, within 4 standard errors): the quadrature
// and the formula against the plainest reference
TEST(SphereColumnOverlap, MonteCarlo)
{
    const scalar xc = 0.0101, yc = 0.2003;
    const scalar cells[4][4] =
    {
        {0.0101 + 0.4*R, 0.02, 0.19, 0.21},                  // 1 plane
        {0.0101 - 0.3*R, 0.02, 0.2003 + 0.5*R, 0.21},        // 2 planes
        {0.0101 - 0.3*R, 0.0101 + 0.6*R, 0.2003 - 0.2*R, 0.21}, // 3 planes
        {0.0101 - 0.7*R, 0.0101 + 0.2*R, 0.2003 - 0.5*R, 0.2003 + 0.6*R}
    };
    for (label k = 0; k < 4; ++k)
    {
        const auto mc = columnQuadrature::monteCarloColumnVolume
        (
            xc, yc, R, cells[k][0], cells[k][1], cells[k][2], cells[k][3],
            4000000, 100 + k
        );
        const scalar V = sphereColumnOverlap(xc, yc, R, cells[k][0], cells[k][1], cells[k][2], cells[k][3]);
        Info<< "    Monte Carlo " << mc.first << " +- " << mc.second
            << " (" << mc.second/Vs << " Vs)" << endl;
        checkAbsolute("Monte Carlo, cut by " + std::to_string(k + 1) + " of the 4 planes (4 standard errors)", V, mc.first, 4*mc.second);
    }
}


// Tangency and corners on the sphere: finite, not negative, and as
// small as the true sliver (< 1e-14 Vs within a few epsilon of R)
TEST(SphereColumnOverlap, TangencyAndCornersOnTheSphere)
{
    const scalar eps = std::numeric_limits<scalar>::epsilon();
    scalar worstLow = 0, worstHigh = 0;
    label bad = 0, n = 0;
    auto probe = [&](const scalar V)
    {
        ++n;
        if (!std::isfinite(V)) ++bad;
        worstLow = min(worstLow, V);
        worstHigh = max(worstHigh, V);
    };
    const scalar big = 3*R;
    for (const scalar k : {-64.0, -4.0, -1.0, 0.0, 1.0, 4.0, 64.0})
    {
        const scalar d = R*(1 + k*eps);
        probe(sphereColumnOverlap(0, 0, R, d, big, -big, big));
        probe(sphereColumnOverlap(0, 0, R, -big, -d, -big, big));
        probe(sphereColumnOverlap(0, 0, R, -big, big, d, big));
        for (const scalar t : {0.0, 1e-9, 0.3, pi/4, 1.2, pi/2})
        {
            const scalar p = d*std::cos(t), q = d*std::sin(t);
            probe(sphereColumnOverlap(0, 0, R, p, big, q, big));
            probe(sphereColumnOverlap(0, 0, R, -big, -p, q, big));
            probe(sphereColumnOverlap(0, 0, R, -big, -p, -big, -q));
            probe(sphereQuadrantVolume(-p, -q, R));
        }
    }
    checkAbsolute("tangency: NaN or infinite volumes of " + std::to_string(n), bad, 0, 0);
    checkAbsolute("tangency: most negative volume / Vs", worstLow/Vs, 0, 1e-14);
    checkAbsolute("tangency: largest sliver / Vs", worstHigh/Vs, 0, 1e-14);
    // Exact zeros and the sphere's own boundary
    checkAbsolute("column x in [R, 2R]", sphereColumnOverlap(0, 0, R, R, 2*R, -R, R), 0, 0);
    checkAbsolute("corner line through the centre", sphereQuadrantVolume(0, 0, R), Vs/4, roundOff);
}


// Partition: one sphere over a grid of cells of 0.1 R to 3 R
TEST(SphereColumnOverlap, VolumesOverAGridOfCellsAddUpToTheSphere)
{
    std::mt19937_64 gen(23);
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst = 0;
    label maxCells = 0;
    for (label n = 0; n < 2000; ++n)
    {
        const scalar h = (0.1 + 2.9*u(gen))*R;
        const scalar xc = u(gen)*h, yc = u(gen)*h;
        const label lo = -label(R/h) - 1, hi = label(R/h) + 1;
        scalar sum = 0;
        for (label i = lo; i <= hi; ++i)
        {
            for (label j = lo; j <= hi; ++j)
            {
                sum += sphereColumnOverlap(xc, yc, R, i*h, (i + 1)*h, j*h, (j + 1)*h);
            }
        }
        maxCells = max(maxCells, (hi - lo + 1)*(hi - lo + 1));
        worst = max(worst, mag(sum - Vs)/Vs);
    }
    checkAbsolute("sum over a grid of cells of 0.1 R to 3 R (1 + worst relative error of 2000)", 1 + worst, 1, 1e-12);
    Info<< "    (worst relative error " << worst << ", up to " << maxCells << " cells)" << endl;
}


// The mapping to the paper's mesh: shares add up to the sphere and
// equal the column volume of their cell; a sphere pressing on the outer
// boundary keeps its part beyond it in its cell
TEST(SphereColumnOverlap, MappingToThePaperMeshSharesEachSphere)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    checkAbsolute("grid cells in x", grid.nx(), 20, 0);
    checkAbsolute("grid cells in y", grid.ny(), 120, 0);
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worstSum = 0, worstShare = 0;
    label byCount[5] = {0, 0, 0, 0, 0};
    for (label n = 0; n < 100000; ++n)
    {
        const scalar r = (n % 2 ? 0.75e-3 : 1.25e-3);
        const scalar V0 = 4*pi*r*r*r/3;
        const scalar x = grid.xMin() + r + u(gen)*(0.15 - 2*r);
        const scalar y = grid.yMin() + r + u(gen)*(0.9 - 2*r);
        scalar sum = 0;
        label nCells = 0;
        forEachSphereOverlap
        (
            grid, x, y, r,
            [&](const label celli, const scalar V)
            {
                sum += V;
                ++nCells;
                // The cell's bounds as xMin + i dx: the mapping puts
                // a neighbour's line at xLo + dx, an ulp of 0.9 m
                // (1e-16 m, 1e-13 R) away, which moves the shares by
                // about 1e-13 of the sphere
                const point& c = mesh.C()[celli];
                const label i = label((c.x() - grid.xMin())/grid.dx());
                const label j = label((c.y() - grid.yMin())/grid.dy());
                const scalar xLo = grid.xMin() + i*grid.dx();
                const scalar yLo = grid.yMin() + j*grid.dy();
                const scalar exact = sphereColumnOverlap
                (
                    x, y, r, xLo, xLo + grid.dx(), yLo, yLo + grid.dy()
                );
                worstShare = max(worstShare, mag(V - exact)/V0);
            }
        );
        ++byCount[min(nCells, label(4))];
        worstSum = max(worstSum, mag(sum - V0)/V0);
    }
    checkAbsolute("sphere volumes mapped to cells (1 + worst relative error of 1e5)", 1 + worstSum, 1, 1e-12);
    checkAbsolute("each share is its cell's column volume (1 + worst / sphere)", 1 + worstShare, 1, 1e-12);
    Info<< "    (worst sum error " << worstSum << ", share error "
        << worstShare << "; spheres in 1, 2, 4 cells: " << byCount[1]
        << " " << byCount[2] << " " << byCount[4] << ")" << endl;

    // On the left wall, 0.4 R beyond it, at a grid line in y
    scalar sum = 0;
    label nCells = 0;
    const scalar yLine = grid.yMin() + 10*grid.dy() + 0.3*R;
    forEachSphereOverlap
    (
        grid, grid.xMin() + 0.6*R, yLine, R,
        [&](label, const scalar V) { sum += V; ++nCells; }
    );
    checkAbsolute("sphere through the outer wall: whole volume kept", sum, Vs, roundOff);
    checkAbsolute("sphere through the outer wall: two cells", nCells, 2, 0);
}


// With -benchmark, the timings instead of the tests
int main(int argc, char *argv[])
{
    argList::addBoolOption("benchmark", "time the mappings instead of testing");
    return couplingTest::main
    (
        argc, argv, couplingTest::readCase,
        [](const argList& args, const fvMesh& mesh)
        {
            if (!args.found("benchmark")) return false;
            sphereColumnBenchmark(cartesianGrid(mesh));
            return true;
        }
    );
}
