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
Description
    Test-dpmCoupling: circle geometry, the grid's share of each disc, and
    Hoomans' map of close packings (GoogleTest suite DiscGeometry).

\*---------------------------------------------------------------------------*/

#include "couplingTest.H"
#include "cartesianGrid.H"
#include "fluidization.H"
#include "Random.H"
#include "mathematicalConstants.H"

using namespace Foam;

static const scalar pi = constant::mathematical::pi;


// Circle geometry (textbook): segment area r^2 acos(h/r) - h sqrt(r^2-h^2)
TEST(DiscGeometry, DiscRectangleAreasAreCircleSegments)
{
    const scalar r = 1.25e-3, h = 0.4e-3;
    const scalar segment = r*r*std::acos(h/r) - h*std::sqrt(r*r - h*h);
    check("disc beyond a line", discRectangleOverlap(0, 0, r, h, 1, -1, 1), segment, 1e-12);
    check("disc below a line", discRectangleOverlap(0, 0, r, -1, 1, -1, -h), segment, 1e-12);
    check("disc quarter", discRectangleOverlap(0, 0, r, 0, 1, 0, 1), 0.25*pi*r*r, 1e-12);
    check("disc whole", discRectangleOverlap(0, 0, r, -1, 1, -1, 1), pi*r*r, 1e-12);

    // The corner with its end at a made once (the grid's) gives the
    // general form's bits, on every branch (a, b across the disc)
    Random rnd(3);
    label differ = 0;
    for (label k = 0; k < 100000; ++k)
    {
        const scalar a = (2.4*rnd.sample01<scalar>() - 1.2)*r;
        const scalar b = (2.4*rnd.sample01<scalar>() - 1.2)*r;
        const discOverlapDetail::chordEnd A(a, r);
        differ += discQuadrantArea(A, b, r) != discQuadrantArea(a, b, r);
    }
    check("disc corner from a shared end, bit for bit", differ, 0, 0);
}


// The grid shares each disc out exactly: areas add up to pi r^2
TEST(DiscGeometry, GridSharesEachDiscExactly)
{
    const cartesianGrid grid(couplingTest::mesh());
    check("grid cells in x", grid.nx(), 20, 0);
    check("grid cells in y", grid.ny(), 120, 0);
    check("grid cell size", grid.dx(), 7.5e-3, 1e-9);

    Random rnd(7);
    scalar worst = 0;
    label shared = 0;
    for (label n = 0; n < 100000; ++n)
    {
        const scalar r = (n % 2 ? 0.75e-3 : 1.25e-3);
        const scalar x = grid.xMin() + r + rnd.sample01<scalar>()*(0.15 - 2*r);
        const scalar y = grid.yMin() + r + rnd.sample01<scalar>()*(0.9 - 2*r);
        scalar sum = 0;
        label nCells = 0;
        grid.forEachDiscOverlap
        (
            x, y, r, [&](label, scalar a) { sum += a; ++nCells; }
        );
        shared += (nCells > 1);
        worst = max(worst, mag(sum - pi*r*r)/(pi*r*r));
    }
    check("disc areas mapped to cells (worst of 1e5)", 1 + worst, 1, 1e-12);
    Info<< "    (" << shared << " of the 1e5 discs straddle cells)" << endl;
}


// Hoomans: 2D hexagonal packing -> 3D face-centred cubic (model.md)
TEST(DiscGeometry, HoomansMapsHexagonalToFaceCentredCubic)
{
    check
    (
        "Hoomans voidage of hexagonal packing",
        fluidization::voidage3D(1 - pi/(2*std::sqrt(3.0))),
        1 - pi/(3*std::sqrt(2.0)),
        1e-10
    );
    check("Hoomans voidage of empty cell", fluidization::voidage3D(1), 1, 1e-15);
}
