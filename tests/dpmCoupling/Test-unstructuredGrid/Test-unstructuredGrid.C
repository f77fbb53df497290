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
    Test-unstructuredGrid

Description
    Checks of the gas grid of any 3D mesh (unstructuredGrid) on three
    meshes of blockMesh (the case's regions): box, a uniform 6 x 6 x 6
    grid of 10 mm cells, where cartesianGrid's exact answers are known;
    cylinder, an O-grid 100 mm across (1320 hexes, curved and skewed);
    thin, a bed one cell thick; warped, the box with its inner points
    moved at random by up to 2 mm each way (warped faces).
    - selection (gasGrid unstructured), sizes, the refusals: a mesh one
      cell thick, the disc and column shares, voidageModel discs2D;
    - findCell: polyMesh::findCell's cell at random points, also by the
      walk from a far cell, -1 outside (box, cylinder, warped);
    - interpolation: a linear field exactly (round-off) on those three;
      on the box trilinear's stencil at the centres and mesh points, and
      within 3h^2/2 of trilinear for |x|^2 (derived in its test);
    - the shares (Test-unstructuredGridShares.C).
    GoogleTest cases (suites UnstructuredGridSelection, UnstructuredFindCell,
    UnstructuredInterpolation and UnstructuredShares), run in the case
    tests/dpmCoupling/unstructuredGridCase with its four meshes made
    (blockMesh -region box, cylinder, thin, warped):

        Test-unstructuredGrid -case <dir> [--gtest_filter=Suite.Name]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "unstructuredGridTests.H"
#include "voidageModel.H"
#include "IStringStream.H"

using namespace Foam;

//- The message of the FatalError (or FatalIOError) f raises, "" for none
template<class F>
std::string errorOf(const F& f)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();
    try
    {
        f();
    }
    catch (const Foam::error& e)
    {
        FatalError.dontThrowExceptions();
        FatalIOError.dontThrowExceptions();
        return e.message();
    }
    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
    return "";
}

bool says(const std::string& message, const char* words)
{
    return message.find(words) != std::string::npos;
}


// Selected by gasGrid unstructured; depth, volumes and the smallest cell
// size of the 6 x 6 x 6 box of 10 mm cells (exact up to round-off); a
// wrong name lists unstructured
TEST(UnstructuredGridSelection, SelectedWithTheBoxsSizes)
{
    const fvMesh& box = boxMesh();
    autoPtr<gasGrid> grid
    (
        gasGrid::New(dictionary(IStringStream("gasGrid unstructured;")()), box)
    );
    check("gasGrid unstructured selected", grid->type() == "unstructured", 1, 0);
    check("resolved in depth", grid->resolvedInDepth(), 1, 0);
    check("depth: the mesh's z extent", grid->depth(), 0.06, 1e-12);
    check("cell volumes: the mesh's", grid->cellVolumes()[7], 1e-6, 1e-9);
    // For a box the width (volume / largest face) is the smallest edge, as
    // cartesianGrid's minCellSize
    const cartesianGrid cartesian(box);
    check("smallest cell size: cartesianGrid's", grid->minCellSize(), cartesian.minCellSize(), 1e-9);

    const std::string wrong = errorOf
    (
        [&]{ gasGrid::New(dictionary(IStringStream("gasGrid unstructed;")()), box); }
    );
    check("a wrong name lists unstructured", says(wrong, "unstructured"), 1, 0);
}


// A mesh one cell thick is refused, naming gasGrid cartesian
TEST(UnstructuredGridSelection, RefusesAMeshOneCellThick)
{
    const fvMesh& thin = thinMesh();
    const std::string thinMessage = errorOf([&]{ unstructuredGrid g(thin); });
    Info<< "    (" << thinMessage.c_str() << ")" << endl;
    check("a mesh one cell thick refused", says(thinMessage, "one cell thick"), 1, 0);
    check("... naming gasGrid cartesian", says(thinMessage, "gasGrid cartesian"), 1, 0);
}


// The disc and column shares, and voidageModel slab3D, are refused on it,
// naming the model
TEST(UnstructuredGridSelection, RefusesDiscAndColumnShares)
{
    autoPtr<gasGrid> grid
    (
        gasGrid::New(dictionary(IStringStream("gasGrid unstructured;")()), boxMesh())
    );
    const double x = 0.03, y = 0.03, d = 0.005;
    cellWeights w;
    const std::string discs = errorOf
    (
        [&]{ grid->discShares(1, &x, &y, &d, 1, w); }
    );
    Info<< "    (" << discs.c_str() << ")" << endl;
    check("disc shares refused, naming discs2D", says(discs, "discs2D") && says(discs, "unstructured"), 1, 0);
    const std::string columns = errorOf
    (
        [&]{ grid->sphereColumnShares(1, &x, &y, &d, 1, w); }
    );
    check("column shares refused, naming slab3D", says(columns, "slab3D") && says(columns, "unstructured"), 1, 0);
    const std::string model = errorOf
    (
        [&]
        {
            voidageModel::New
            (
                dictionary(IStringStream("voidageModel slab3D;")()), *grid, 0.05
            );
        }
    );
    check("voidageModel slab3D refused on it", says(model, "slab3D") && says(model, "one cell thick"), 1, 0);
}


void checkFindCell(const fvMesh& mesh)
{
    const unstructuredGrid grid(mesh);
    grid.report(Info);
    // Points in the bounding box grown by a tenth each way: the octree's
    // cell (-1 outside) from the search and from walks out of far cells
    Random rnd(31);
    const boundBox& bb = mesh.bounds();
    label disagree = 0, outside = 0, inside = 0;
    for (label n = 0; n < 5000; ++n)
    {
        const point p
        (
            bb.min() - 0.1*bb.span()
          + cmptMultiply(1.2*bb.span(), rnd.sample01<vector>())
        );
        const label expected = mesh.findCell(p);
        (expected < 0 ? outside : inside)++;
        const label seeds[] =
        {
            -1, 0, mesh.nCells() - 1, rnd.position<label>(0, mesh.nCells() - 1)
        };
        for (const label seed : seeds)
        {
            disagree += grid.findCell(p, seed) != expected;
        }
        disagree += grid.findCell(p) != expected;
    }
    const std::string m = " (" + mesh.name() + ", 5000 points x 5 searches)";
    check("findCell: polyMesh::findCell's cell" + m, disagree, 0, 0);
    check("points outside met" + m, outside > 100, 1, 0);
    check("points inside met" + m, inside > 1000, 1, 0);
    check("outside the box: -1", grid.findCell(bb.max() + bb.span(), 0), -1, 0);
}


void checkLinear(const fvMesh& mesh)
{
    const unstructuredGrid grid(mesh);
    // A linear field at the cell centres comes out exactly anywhere in the
    // mesh, the boundary cells too
    const vector slope(3, -2, 5);
    scalarField f(mesh.nCells());
    forAll(f, c) f[c] = 1 + (slope & mesh.C()[c]);

    Random rnd(7);
    const label n = 20000;
    List<double> x(n), y(n), z(n);
    for (label i = 0; i < n; ++i)
    {
        const point p = randomPointInside(mesh, rnd);
        x[i] = p.x(); y[i] = p.y(); z[i] = p.z();
    }
    cellWeights w;
    grid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, w);
    scalar worst = 0, worstSum = 0, most = 0, largest = 0;
    for (label i = 0; i < n; ++i)
    {
        const point p(x[i], y[i], z[i]);
        worst = max(worst, mag(w.interpolate(i, f) - (1 + (slope & p))));
        scalar sum = 0, sumMag = 0;
        for (label k = w.stride*i; k < w.stride*i + w.counts[i]; ++k)
        {
            sum += w.weights[k];
            sumMag += mag(w.weights[k]);
        }
        worstSum = max(worstSum, mag(sum - 1));
        largest = max(largest, sumMag);
        most = max(most, scalar(w.counts[i]));
    }
    const std::string m = " (" + mesh.name() + ", worst of 2e4)";
    Info<< "    stencils of up to " << most << " cells, sum |w| up to "
        << largest << m.c_str() << endl;
    check("a linear field exactly" + m, 1 + worst, 1, 1e-12);
    check("stencil weights add up to 1" + m, 1 + worstSum, 1, 1e-12);

    // Moved on and interpolated again: the walk from the last cells gives
    // the same stencils as a fresh grid's octree search
    for (label i = 0; i < n; ++i)
    {
        const point p = randomPointInside(mesh, rnd);
        x[i] = p.x(); y[i] = p.y(); z[i] = p.z();
    }
    cellWeights again, fresh;
    grid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 2, again);
    const unstructuredGrid freshGrid(mesh, 2, 2);
    freshGrid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, fresh);
    check("from the last cells, on 2 threads: the stencils of a fresh search" + m, sameWeights(again, fresh), 1, 0);
}


// At a cell centre the cell alone, at an inner mesh point the mean of its
// eight cells: trilinear's stencils there (1e-12, round-off)
TEST(UnstructuredInterpolation, TrilinearsStencilAtCentresAndInnerPointsOfTheBox)
{
    const fvMesh& box = boxMesh();
    const unstructuredGrid grid(box);
    const cartesianGrid cartesian(box);
    Random rnd(3);
    scalarField f(box.nCells());
    forAll(f, c) f[c] = rnd.sample01<scalar>();
    DynamicList<point> at;
    forAll(box.C(), c) at.append(box.C()[c]);
    forAll(box.points(), pointi)
    {
        const point& p = box.points()[pointi];
        if (box.bounds().contains(p) && min(cmptMin(p - box.bounds().min()), cmptMin(box.bounds().max() - p)) > 1e-9)
        {
            at.append(p);
        }
    }
    List<double> x(at.size()), y(at.size()), z(at.size());
    forAll(at, i) { x[i] = at[i].x(); y[i] = at[i].y(); z[i] = at[i].z(); }
    cellWeights u, t;
    grid.interpolationStencils(at.size(), x.cdata(), y.cdata(), z.cdata(), 1, u);
    cartesian.interpolationStencils(at.size(), x.cdata(), y.cdata(), z.cdata(), 1, t);
    scalar worst = 0;
    forAll(at, i) worst = max(worst, mag(u.interpolate(i, f) - t.interpolate(i, f)));
    check("box: trilinear's value at the centres and inner points, random field ("
        + std::to_string(at.size()) + " places)", 1 + worst, 1, 1e-12);
}


// f = |x - x0|^2 between the outer centres of the box: within 3h^2/2 of
// trilinear (derived below), and not below the convex field
TEST(UnstructuredInterpolation, SquareDistanceWithinThreeHalvesHSquaredOfTrilinearOnTheBox)
{
    const fvMesh& box = boxMesh();
    const unstructuredGrid grid(box);
    const cartesianGrid cartesian(box);
    // The random points of the trilinear stencils' test, drawn after its
    // random field
    Random rnd(3);
    scalarField f(box.nCells());
    forAll(f, c) f[c] = rnd.sample01<scalar>();
    List<double> x, y, z;
    cellWeights u, t;

    // f = |x - x0|^2 between the outer centres. Trilinear's error is
    // sum fx(1 - fx) h^2, in [0, 3h^2/4]; the cell-point one, a tet of the
    // cell centre (the exact value) and three corners (the mean of eight
    // centres, 3h^2/4 high), is sum l_i e_i + sum l_i |v_i - p|^2 in
    // [0, 3h^2/2] (the corners sqrt(3) h/2 from the centre): the two differ
    // by at most 3h^2/2
    const scalar h = cartesian.dx();
    const point x0(0.021, 0.033, 0.027);
    forAll(f, c) f[c] = magSqr(box.C()[c] - x0);
    const label n = 20000;
    x.setSize(n); y.setSize(n); z.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        const vector s = rnd.sample01<vector>();
        x[i] = 0.5*h + s.x()*5*h; y[i] = 0.5*h + s.y()*5*h; z[i] = 0.5*h + s.z()*5*h;
    }
    grid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, u);
    cartesian.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, t);
    scalar worstDiff = 0, meanDiff = 0, lowest = GREAT;
    for (label i = 0; i < n; ++i)
    {
        const scalar exact = magSqr(point(x[i], y[i], z[i]) - x0);
        const scalar d = mag(u.interpolate(i, f) - t.interpolate(i, f));
        worstDiff = max(worstDiff, d);
        meanDiff += d/n;
        lowest = min(lowest, u.interpolate(i, f) - exact);
    }
    Info<< "    |x - x0|^2: cell-point - trilinear up to " << worstDiff/sqr(h)
        << " h^2, mean " << meanDiff/sqr(h) << " h^2" << endl;
    check("|x - x0|^2: within 3h^2/2 of trilinear", worstDiff <= 1.5*sqr(h), 1, 0);
    check("|x - x0|^2: not below the convex field", lowest > -1e-15, 1, 0);
}


// polyMesh::findCell's cell (-1 outside) at 5000 points in and around
// each mesh, from the octree and from walks out of far cells: exact
TEST(UnstructuredFindCell, PolyMeshFindCellsCellOnTheBox)
{
    checkFindCell(boxMesh());
}

TEST(UnstructuredFindCell, PolyMeshFindCellsCellOnTheCylinder)
{
    checkFindCell(cylinderMesh());
}

TEST(UnstructuredFindCell, PolyMeshFindCellsCellOnTheWarpedBox)
{
    checkFindCell(warpedMesh());
}


// A linear field anywhere in each mesh, the boundary cells too, exactly
// (1e-12, round-off); weights adding up to 1; the walk's stencils those of
// a fresh search, on 2 threads
TEST(UnstructuredInterpolation, LinearFieldExactlyOnTheBox)
{
    checkLinear(boxMesh());
}

TEST(UnstructuredInterpolation, LinearFieldExactlyOnTheCylinder)
{
    checkLinear(cylinderMesh());
}

TEST(UnstructuredInterpolation, LinearFieldExactlyOnTheWarpedBox)
{
    checkLinear(warpedMesh());
}


int main(int argc, char *argv[])
{
    // GoogleTest's options first, then OpenFOAM's (-case <dir>); the
    // process ends with the tests' status (couplingTestMain.H)
    testing::InitGoogleTest(&argc, argv);
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"

    auto load = [&runTime](const word& region)
    {
        return new fvMesh
        (
            IOobject(region, runTime.timeName(), runTime, IOobject::MUST_READ)
        );
    };
    autoPtr<fvMesh> box(load("box"));
    autoPtr<fvMesh> cylinder(load("cylinder"));
    autoPtr<fvMesh> thin(load("thin"));
    autoPtr<fvMesh> warped(load("warped"));

    // The box's inner points moved at random by up to 0.2 h each way: its
    // faces are warped, so a cell's face planes and its tets differ
    {
        Random rnd(41);
        const boundBox bb = warped->bounds();
        pointField moved(warped->points());
        for (point& p : moved)
        {
            if (min(cmptMin(p - bb.min()), cmptMin(bb.max() - p)) > 1e-9)
            {
                p += 0.01*0.2*(2*rnd.sample01<vector>() - vector::one);
            }
        }
        warped->movePoints(moved);
    }

    meshes_ = {box.get(), cylinder.get(), thin.get(), warped.get()};
    const int status = RUN_ALL_TESTS();
    meshes_ = {};
    box.clear();
    cylinder.clear();
    thin.clear();
    warped.clear();

    // Not a return: args's destructor would end the process with status 0
    UPstream::exit(status);
    return status;
}


// ************************************************************************* //
