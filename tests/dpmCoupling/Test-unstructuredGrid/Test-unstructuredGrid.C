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
    Checks of the gas grid of any 3D mesh (unstructuredGrid) on four
    meshes of blockMesh (the case's regions): box, a uniform 6 x 6 x 6
    grid of 10 mm cells, where cartesianGrid's exact answers are known;
    cylinder, an O-grid 100 mm across (1320 hexes, curved and skewed);
    thin, a bed one cell thick; warped, the box with its inner points
    moved at random by up to 2 mm each way (warped faces).
    - selection (gasGrid unstructured), sizes, the refusals: a mesh one
      cell thick, the disc and column shares, voidageModel discs2D;
    - findCell: polyMesh::findCell's cell at random points, also by the
      walk from a far cell, -1 outside (box, cylinder, warped);
    - interpolation, on those three, at random points and beside every
      boundary face: every weight >= 0, the weights adding up to 1, a
      constant voidage the constant, a voidage within its cells' values; a
      linear field exactly in the cells off the boundary, and within the
      bound |g| D anywhere (derived in checkLinear; on the box h/2 (|g_x| +
      |g_y| + |g_z|)); on the box trilinear's stencil at the centres and
      inner points, and within 3h^2/2 of trilinear for |x|^2 in the cells
      off the walls (derived in its test);
    - the shares (Test-unstructuredGridShares.C).
    GoogleTest cases (suites UnstructuredGridSelection, UnstructuredFindCell,
    UnstructuredInterpolation and UnstructuredShares), run in the case
    tests/dpmCoupling/unstructuredGridCase with its four meshes made
    (blockMesh -region box, cylinder, thin, warped):

        Test-unstructuredGrid -case <dir> [--gtest_filter=Suite.Name]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "couplingTestMain.H"
#include "unstructuredGridTests.H"
#include "voidageModel.H"
#include "IStringStream.H"
#include "bitSet.H"

using namespace Foam;

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


//- Points for the interpolation's checks on mesh: n at random inside, and
//  beside every boundary face, its centre and its points each moved a
//  millionth of the way to the owner's centre (walls, edges, corners);
//  with outside, each of those also moved a tenth of a cell beyond
//  the face (the nearest cell's value). The cell of each: the octree's,
//  the owner's beside a face
void checkPoints
(
    const fvMesh& mesh,
    Random& rnd,
    const label n,
    const bool outside,
    List<double>& x,
    List<double>& y,
    List<double>& z,
    labelList& cells
)
{
    DynamicList<point> at;
    DynamicList<label> in;
    for (label i = 0; i < n; ++i)
    {
        at.append(randomPointInside(mesh, rnd));
        in.append(mesh.findCell(at.last()));
    }
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        const point& C = mesh.C()[mesh.faceOwner()[facei]];
        const vector n = mesh.faceAreas()[facei]/mag(mesh.faceAreas()[facei]);
        const scalar h = mag(C - mesh.faceCentres()[facei]);
        DynamicList<point> on(1, mesh.faceCentres()[facei]);
        for (const label pointi : mesh.faces()[facei])
        {
            on.append(mesh.points()[pointi]);
        }
        for (const point& p : on)
        {
            at.append(p + 1e-6*(C - p));
            in.append(mesh.faceOwner()[facei]);
            if (outside)
            {
                at.append(p + 0.2*h*n);
                in.append(mesh.faceOwner()[facei]);
            }
        }
    }
    x.setSize(at.size()); y.setSize(at.size()); z.setSize(at.size());
    forAll(at, i) { x[i] = at[i].x(); y[i] = at[i].y(); z[i] = at[i].z(); }
    cells.transfer(in);
}


//- Every stencil's weights >= 0 (exactly) and adding up to 1 (1e-12);
//  a constant voidage interpolated is the constant and a voidage between
//  0.4 and 1 stays between its stencil's least and largest cell values,
//  up to the round-off of a sum of at most S terms (S 2^-53 relative, S
//  the most cells of a stencil)
void checkWeights(const fvMesh& mesh)
{
    const unstructuredGrid grid(mesh);
    Random rnd(23);
    List<double> x, y, z;
    labelList cells;
    checkPoints(mesh, rnd, 20000, true, x, y, z, cells);
    const label n = x.size();
    cellWeights w;
    grid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, w);

    scalarField eps(mesh.nCells());
    forAll(eps, c) eps[c] = 0.4 + 0.6*rnd.sample01<scalar>();
    const scalarField constant(mesh.nCells(), 0.37);
    const scalar roundOff = w.stride*std::pow(2.0, -53);
    scalar lowest = GREAT, worstSum = 0, worstConstant = 0, overshoot = 0;
    for (label i = 0; i < n; ++i)
    {
        scalar sum = 0, least = GREAT, largest = -GREAT;
        for (label k = w.stride*i; k < w.stride*i + w.counts[i]; ++k)
        {
            lowest = min(lowest, w.weights[k]);
            sum += w.weights[k];
            least = min(least, eps[w.cells[k]]);
            largest = max(largest, eps[w.cells[k]]);
        }
        worstSum = max(worstSum, mag(sum - 1));
        worstConstant = max(worstConstant, mag(w.interpolate(i, constant)/0.37 - 1));
        const scalar e = w.interpolate(i, eps);
        overshoot = max(overshoot, max(least - e, e - largest)/largest);
    }
    const std::string m =
        " (" + mesh.name() + ", " + std::to_string(n) + " points, walls too)";
    check("stencil weights >= 0" + m, lowest >= 0, 1, 0);
    check("stencil weights add up to 1" + m, 1 + worstSum, 1, 1e-12);
    check("a constant voidage: the constant" + m, 1 + worstConstant, 1, roundOff);
    check("a voidage within its stencil's cell values" + m, 1 + max(overshoot, scalar(0)), 1, roundOff);
}


//- A linear field (gradient g) on mesh: exactly (1e-12, the point weights'
//  tolerance 1e-13 of a cell, and round-off) in the cells none of whose
//  points is on the boundary; in any cell off by at most |g| D, D the
//  largest distance of a point of the cell from a cell centre around that
//  point (a convex combination of those centres is within D of the
//  point). Prints the largest error over |g| h, h the cell's width (its
//  volume over its largest face). The walk's stencils, on 2 threads, are
//  a fresh search's.
scalar checkLinear(const fvMesh& mesh)
{
    const unstructuredGrid grid(mesh);
    const vector slope(3, -2, 5);
    scalarField f(mesh.nCells());
    forAll(f, c) f[c] = 1 + (slope & mesh.C()[c]);

    // Each cell's D, width, and whether a point of it is on the boundary
    bitSet onBoundary(mesh.nPoints());
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        for (const label pointi : mesh.faces()[facei]) onBoundary.set(pointi);
    }
    scalarField D(mesh.nCells(), 0), width(mesh.nCells(), 0);
    bitSet inner(mesh.nCells(), true);
    forAll(D, c)
    {
        for (const label pointi : mesh.cellPoints()[c])
        {
            if (onBoundary.test(pointi)) inner.unset(c);
            for (const label celli : mesh.pointCells()[pointi])
            {
                D[c] = max(D[c], mag(mesh.C()[celli] - mesh.points()[pointi]));
            }
        }
        scalar largestFace = 0;
        for (const label facei : mesh.cells()[c])
        {
            largestFace = max(largestFace, mag(mesh.faceAreas()[facei]));
        }
        width[c] = mesh.V()[c]/largestFace;
    }

    Random rnd(7);
    List<double> x, y, z;
    labelList cells;
    checkPoints(mesh, rnd, 20000, false, x, y, z, cells);
    const label n = x.size();
    cellWeights w;
    grid.interpolationStencils(n, x.cdata(), y.cdata(), z.cdata(), 1, w);
    scalar worstInner = 0, worstInnerOfh = 0, worstOverBound = 0, worstOfh = 0;
    label nInner = 0;
    for (label i = 0; i < n; ++i)
    {
        const point p(x[i], y[i], z[i]);
        const label c = cells[i];
        const scalar e = mag(w.interpolate(i, f) - (1 + (slope & p)));
        if (inner.test(c))
        {
            worstInner = max(worstInner, e);
            worstInnerOfh = max(worstInnerOfh, e/(mag(slope)*width[c]));
            ++nInner;
        }
        worstOverBound = max(worstOverBound, e/(mag(slope)*D[c]));
        worstOfh = max(worstOfh, e/(mag(slope)*width[c]));
    }
    const std::string m = " (" + mesh.name() + ", " + std::to_string(n) + " points)";
    Info<< "    a linear field: error up to " << worstOfh << " |g| h, "
        << worstOverBound << " of the bound |g| D; off the boundary "
        << worstInnerOfh << " |g| h" << m.c_str() << endl;
    check("a linear field exactly in the cells off the boundary (" + std::to_string(nInner) + " of the points)" + m, 1 + worstInner, 1, 1e-12);
    check("a linear field within |g| D anywhere" + m, worstOverBound <= 1 + 1e-12, 1, 0);

    // At a point of one wall (its boundary faces' normals within 30
    // degrees of their mean n: not an edge or a corner) a field linear
    // along the wall comes out exactly: the point's cells' mean centre
    // (interpolated at the point, moved 1e-9 of the way to a cell's
    // centre: the other corners of its tet weigh about 1e-9, each shifted
    // by at most D) lies on the wall's normal through it, to 1e-6 D
    {
        DynamicList<point> at;
        DynamicList<vector> normal;
        DynamicList<scalar> within;
        for (const label pointi : onBoundary)
        {
            vector sum(Zero);
            for (const label facei : mesh.pointFaces()[pointi])
            {
                if (!mesh.isInternalFace(facei)) sum += mesh.faceAreas()[facei];
            }
            const vector nMean = sum/mag(sum);
            bool oneWall = true;
            for (const label facei : mesh.pointFaces()[pointi])
            {
                if (mesh.isInternalFace(facei)) continue;
                const vector& Sf = mesh.faceAreas()[facei];
                oneWall = oneWall && (Sf & nMean) > 0.866*mag(Sf);
            }
            if (!oneWall) continue;
            const point& v = mesh.points()[pointi];
            const label c = mesh.pointCells()[pointi][0];
            at.append(v + 1e-9*(mesh.C()[c] - v));
            normal.append(nMean);
            within.append(D[c]);
        }
        List<double> px(at.size()), py(at.size()), pz(at.size());
        forAll(at, i) { px[i] = at[i].x(); py[i] = at[i].y(); pz[i] = at[i].z(); }
        cellWeights pw;
        grid.interpolationStencils(at.size(), px.cdata(), py.cdata(), pz.cdata(), 1, pw);
        scalar worstAlong = 0;
        forAll(at, i)
        {
            const vector delta = pw.interpolate(i, mesh.C()) - at[i];
            const vector along = delta - (delta & normal[i])*normal[i];
            worstAlong = max(worstAlong, mag(along)/within[i]);
        }
        check("a field linear along the wall exactly at its points (" + std::to_string(at.size()) + " points of one wall; the mean centre's shift along the wall / D)" + m, 1 + worstAlong, 1, 1e-6);
    }

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
    return worstOfh;
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


// f = |x - x0|^2 in the box's cells off the walls: within 3h^2/2 of
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

    // f = |x - x0|^2 in the cells off the walls (h to 5h each way), whose
    // points are all inner points (a wall point's value, its cells' mean,
    // is off by a first-order term: checkLinear). Trilinear's error is
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
        x[i] = h + s.x()*4*h; y[i] = h + s.y()*4*h; z[i] = h + s.z()*4*h;
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


// Every stencil's weights >= 0 and adding up to 1, at random points and
// beside every boundary face (and beyond it): a constant voidage comes out
// as the constant, any voidage within its cells' values
TEST(UnstructuredInterpolation, WeightsNonNegativeAddingUpToOneOnTheBox)
{
    checkWeights(boxMesh());
}

TEST(UnstructuredInterpolation, WeightsNonNegativeAddingUpToOneOnTheCylinder)
{
    checkWeights(cylinderMesh());
}

TEST(UnstructuredInterpolation, WeightsNonNegativeAddingUpToOneOnTheWarpedBox)
{
    checkWeights(warpedMesh());
}


// A linear field: exactly off the boundary, within |g| D anywhere (in
// checkLinear). On the box, beside the walls, at most h/2 (|g_x| + |g_y|
// + |g_z|): a wall point's value is the mean of its cells (inverse
// distance's weights, equal by symmetry), whose centres lie h/2 inside
// each of its walls, and the tet's coordinates add up to 1
TEST(UnstructuredInterpolation, LinearFieldExactOffTheWallsOnTheBox)
{
    const scalar worst = checkLinear(boxMesh());
    const vector g(3, -2, 5);
    check("box: a linear field within h/2 (|g_x| + |g_y| + |g_z|)", worst <= (1 + 1e-12)*0.5*cmptSum(cmptMag(g))/mag(g), 1, 0);
}

TEST(UnstructuredInterpolation, LinearFieldExactOffTheWallsOnTheCylinder)
{
    checkLinear(cylinderMesh());
}

TEST(UnstructuredInterpolation, LinearFieldExactOffTheWallsOnTheWarpedBox)
{
    checkLinear(warpedMesh());
}


int main(int argc, char *argv[])
{
    // The four meshes are regions of the case (couplingTestMain.H)
    return couplingTest::mainWithTime
    (
        argc, argv,
        [](const argList&, Time& runTime)
        {
            auto load = [&runTime](const word& region)
            {
                return autoPtr<fvMesh>
                (
                    new fvMesh
                    (
                        IOobject
                        (
                            region, runTime.timeName(), runTime,
                            IOobject::MUST_READ
                        )
                    )
                );
            };
            autoPtr<fvMesh> box(load("box"));
            autoPtr<fvMesh> cylinder(load("cylinder"));
            autoPtr<fvMesh> thin(load("thin"));
            autoPtr<fvMesh> warped(load("warped"));

            // The box's inner points moved at random by up to 0.2 h each
            // way: its faces are warped, so a cell's face planes and its
            // tets differ
            {
                Random rnd(41);
                const boundBox bb = warped->bounds();
                pointField moved(warped->points());
                for (point& p : moved)
                {
                    if
                    (
                        min(cmptMin(p - bb.min()), cmptMin(bb.max() - p))
                      > 1e-9
                    )
                    {
                        p += 0.01*0.2*(2*rnd.sample01<vector>() - vector::one);
                    }
                }
                warped->movePoints(moved);
            }

            meshes_ = {box.get(), cylinder.get(), thin.get(), warped.get()};
            const int status = RUN_ALL_TESTS();
            meshes_ = {};
            return status;
        }
    );
}


// ************************************************************************* //
