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
    Test-gasInDepth

Description
    Checks of the gas resolved in depth on a mesh of NETL's column (38.1 mm
    square, 228.6 mm tall, 4 x 24 x 4 cells):
    - the grid: sizes, and every cell found at its centre;
    - trilinear interpolation: exact for a linear field, the cell's value
      at its centre;
    - a sphere's volume shared out by forEachSphereBoxOverlap: each cell's
      share against the sphere-box volume of that cell alone
      (sphereBoxOverlap.H, checked against a quadrature by
      Test-sphereBoxOverlap), the shares against the whole;
    - voidageModel spheres3D: the mapped volume against the particles',
      a lattice of known solid fraction pi/6, the spreading sphere's
      shares, the same fields on 1 and 2 threads;
    - coarseGraining diffusion: a cell's unit amount diffused over the
      pseudo time T = b^2/4 keeps its sum and its sign, and spreads along
      the column with the variance 2T = b^2/2 of the finite-volume
      diffusion (exact on an unbounded grid: d<y^2>/dt = 2 for the
      three-point Laplacian; with b one cell the kernel's tail is below
      1e-15 at the column's ends); a uniform field stays uniform.
    GoogleTest cases (suites GasInDepthGrid, TrilinearInterpolation,
    SphereBoxShares, Spheres3D and DiffusionSmoothing), run in a case with
    that mesh:

        Test-gasInDepth -case <dir> [--gtest_filter=Suite.Name]

\*---------------------------------------------------------------------------*/

#include "couplingTestMain.H"
#include "cartesianGrid.H"
#include "forEachSphereBoxOverlap.H"
#include "voidageModel.H"
#include "coarseGraining.H"
#include "Random.H"
#include "IStringStream.H"

using namespace Foam;

static const scalar pi = constant::mathematical::pi;


// The grid: sizes, and every cell found at its centre
TEST(GasInDepthGrid, SizesAndEveryCellFoundAtItsCentre)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    check("cells in x", grid.nx(), 4, 0);
    check("cells in y", grid.ny(), 24, 0);
    check("cells in z", grid.nz(), 4, 0);
    check("cell size in z", grid.dz(), 0.0381/4, 1e-9);
    scalar worstVolume = 0;
    forAll(mesh.V(), celli)
    {
        worstVolume =
            max(worstVolume, mag(grid.cellVolumes()[celli]/mesh.V()[celli] - 1));
    }
    check("each cell's volume: the mesh's (worst relative)", 1 + worstVolume, 1, 1e-9);
    check("cell volume", grid.cellVolumes()[0], pow3(0.0381/4), 1e-9);
    label misplaced = 0;
    forAll(mesh.C(), celli)
    {
        const point& c = mesh.C()[celli];
        misplaced += grid.findCell(c.x(), c.y(), c.z()) != celli;
    }
    check("every cell found at its centre", misplaced, 0, 0);
    check("outside in z: no cell", grid.findCell(0.01, 0.01, 0.039), -1, 0);
}


// A linear field is interpolated exactly between the outer centres
TEST(TrilinearInterpolation, LinearFieldExactly)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    const vector slope(3, -2, 5);
    scalarField eps(mesh.nCells());
    forAll(eps, c)
    {
        eps[c] = (slope & mesh.C()[c]) + 1;
    }
    const vectorField U(mesh.nCells(), vector(1, 2, 3));
    Random rnd(5);
    scalar worst = 0;
    for (label n = 0; n < 10000; ++n)
    {
        const point p
        (
            grid.xMin() + grid.dx()*(0.5 + rnd.sample01<scalar>()*(grid.nx() - 1)),
            grid.yMin() + grid.dy()*(0.5 + rnd.sample01<scalar>()*(grid.ny() - 1)),
            grid.zMin() + grid.dz()*(0.5 + rnd.sample01<scalar>()*(grid.nz() - 1))
        );
        scalar e;
        vector u;
        grid.interpolate(p.x(), p.y(), p.z(), eps, U, e, u);
        worst = max(worst, mag(e - ((slope & p) + 1)));
        worst = max(worst, mag(u - vector(1, 2, 3)));
    }
    check("trilinear: a linear field exactly (worst of 1e4)", 1 + worst, 1, 1e-13);
}


// The stencil at a cell's centre: that cell alone
TEST(TrilinearInterpolation, StencilAtACentreIsThatCell)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    label cells[8];
    scalar w[8];
    const label c = grid.cellIJK(2, 7, 1);
    const point& C = mesh.C()[c];
    const label count = grid.interpolationStencil(C.x(), C.y(), C.z(), cells, w);
    scalar wc = 0, wSum = 0;
    for (label k = 0; k < count; ++k)
    {
        wSum += w[k];
        if (cells[k] == c) wc += w[k];
    }
    check("trilinear stencil: eight cells", count, 8, 0);
    check("trilinear at a centre: that cell alone", wc, 1, 1e-12);
    check("trilinear weights add up to 1", wSum, 1, 1e-14);
}


// A sphere's volume shared out by forEachSphereBoxOverlap: spheres of the
// glass (3.1 mm), the large intruder (9.43 mm) and spread spheres of two
// and three cells, anywhere inside the column
TEST(SphereBoxShares, EachCellsShareIsItsSphereBoxVolume)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    Random rnd(17);
    const scalar radii[] = {1.55e-3, 4.715e-3, grid.dx(), 1.5*grid.dx()};
    for (const scalar R : radii)
    {
        scalar worstCell = 0, worstSum = 0;
        label most = 0, shared = 0;
        const label span = sphereCellSpan(2*R, grid.dx());
        for (label n = 0; n < 20000; ++n)
        {
            const point c
            (
                grid.xMin() + R + rnd.sample01<scalar>()*(grid.xMax() - grid.xMin() - 2*R),
                grid.yMin() + R + rnd.sample01<scalar>()*(grid.yMax() - grid.yMin() - 2*R),
                grid.zMin() + R + rnd.sample01<scalar>()*(grid.zMax() - grid.zMin() - 2*R)
            );
            scalar sum = 0;
            label count = 0;
            forEachSphereBoxOverlap
            (
                grid, c.x(), c.y(), c.z(), R,
                [&](const label celli, const scalar V)
                {
                    const point& lo = mesh.C()[celli];
                    const scalar h = 0.5*grid.dx();
                    const scalar exact = sphereBoxOverlap
                    (
                        c.x(), c.y(), c.z(), R,
                        lo.x() - h, lo.x() + h, lo.y() - h, lo.y() + h,
                        lo.z() - h, lo.z() + h
                    );
                    worstCell = max(worstCell, mag(V - exact)/pow3(R));
                    sum += V;
                    ++count;
                }
            );
            most = max(most, count);
            shared += count > 1;
            worstSum = max(worstSum, mag(sum - 4*pi*pow3(R)/3)/pow3(R));
        }
        const std::string r = " (R = " + std::to_string(R*1e3) + " mm, worst of 2e4)";
        check("each cell's share = its sphere-box volume" + r, 1 + worstCell, 1, 1e-12);
        check("the shares add up to the sphere" + r, 1 + worstSum, 1, 1e-12);
        check("cells per sphere within the span" + r, most <= span*span*span, 1, 0);
        check("spheres straddle cells" + r, shared > 2000, 1, 0);
    }
}


// voidageModel spheres3D: an exact model and one spreading its particles
// over a sphere of diameter Ds = 2 cells (19.05 mm)
namespace
{
    const scalar voidageMin = 0.05;

    autoPtr<voidageModel> select(const char* entries, const cartesianGrid& grid)
    {
        return voidageModel::New(dictionary(IStringStream(entries)()), grid, voidageMin);
    }

    autoPtr<voidageModel> exactModel(const cartesianGrid& grid)
    {
        return select("voidageModel spheres3D;", grid);
    }

    autoPtr<voidageModel> spreadModel(const cartesianGrid& grid)
    {
        return select("voidageModel spheres3D; spheres3DCoeffs { spreadingDiameter 0.01905; }", grid);
    }
}


TEST(Spheres3D, Selected)
{
    const cartesianGrid grid(couplingTest::mesh());
    autoPtr<voidageModel> exact(exactModel(grid));
    check("spheres3D selected", exact->type() == "spheres3D", 1, 0);
}


// 4000 glass beads and 4 intruders at random (overlaps allowed): the
// volume mapped is the particles', on 1 and 2 threads alike
TEST(Spheres3D, MappedVolumeIsTheParticlesOnOneAndTwoThreads)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny()*grid.nz();
    const scalarField& Vc = grid.cellVolumes();
    autoPtr<voidageModel> exact(exactModel(grid));
    autoPtr<voidageModel> spread(spreadModel(grid));
    Random rnd(23);
    const label n = 4004;
    List<double> x(n), y(n), z(n), d(n);
    scalar Vp = 0;
    for (label i = 0; i < n; ++i)
    {
        d[i] = i < 4 ? 9.43e-3 : 3.101e-3;
        const scalar r = 0.5*d[i];
        x[i] = grid.xMin() + r + rnd.sample01<scalar>()*(grid.xMax() - grid.xMin() - 2*r);
        y[i] = grid.yMin() + r + rnd.sample01<scalar>()*(0.08 - 2*r);
        z[i] = grid.zMin() + r + rnd.sample01<scalar>()*(grid.zMax() - grid.zMin() - 2*r);
        Vp += pi*pow3(d[i])/6;
    }
    for (voidageModel* model : {exact.get(), spread.get()})
    {
        scalarField eps1(nCells), phiP1(nCells), eps2(nCells), phiP2(nCells);
        model->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), d.cdata(), 1);
        model->updateFields(n, d.cdata(), eps1, phiP1);
        model->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), d.cdata(), 2);
        model->updateFields(n, d.cdata(), eps2, phiP2);
        const std::string m = model == exact.get() ? " (exact)" : " (spread)";
        check("mapped volume = particles' volume" + m, sum(phiP1*Vc), Vp, 1e-12);
        check("voidage = max(1 - phiP, voidageMin)" + m, max(mag(eps1 - max(1 - phiP1, voidageMin))), 0, 0);
        check("2 threads: the same fields bit for bit" + m, max(mag(phiP1 - phiP2)), 0, 0);
        label most = 0;
        forAll(model->counts(), i) most = max(most, model->counts()[i]);
        check("cells per particle within the stride" + m, most <= model->stride(), 1, 0);
    }
    check("spheres3D: 8 cells at most for particles up to a cell", exact->stride(), 8, 0);
}


// Spheres larger than a cell (1.5 and 2.5 cells, 14.3 and 23.8 mm, as on
// a grid finer than NETL's intruder) among glass beads: each keeps its
// volume, spread over the cells it covers by their exact sphere-box
// volumes, and its cells stay within the stride; the voidage model takes
// them up to six cells, the depth permitting
TEST(Spheres3D, SpheresLargerThanACellKeepTheirVolume)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny()*grid.nz();
    const scalarField& Vc = grid.cellVolumes();
    autoPtr<voidageModel> exact(exactModel(grid));
    Random rnd(29);
    const label n = 1004;
    List<double> x(n), y(n), z(n), d(n);
    scalar Vp = 0;
    for (label i = 0; i < n; ++i)
    {
        d[i] = i < 2 ? 1.5*grid.dx() : i < 4 ? 2.5*grid.dx() : 3.101e-3;
        const scalar r = 0.5*d[i];
        x[i] = grid.xMin() + r + rnd.sample01<scalar>()*(grid.xMax() - grid.xMin() - 2*r);
        y[i] = grid.yMin() + r + rnd.sample01<scalar>()*(0.08 - 2*r);
        z[i] = grid.zMin() + r + rnd.sample01<scalar>()*(grid.zMax() - grid.zMin() - 2*r);
        Vp += pi*pow3(d[i])/6;
    }
    scalarField eps(nCells), phiP(nCells);
    exact->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), d.cdata(), 2);
    exact->updateFields(n, d.cdata(), eps, phiP);
    check("larger than a cell: mapped volume = particles' volume", sum(phiP*Vc), Vp, 1e-12);
    label most = 0;
    forAll(exact->counts(), i) most = max(most, exact->counts()[i]);
    check("larger than a cell: cells per particle within the stride", most <= exact->stride(), 1, 0);
    check("larger than a cell: a sphere of 2.5 cells spans 4 in each direction", exact->stride(), 64, 0);

    // The bound: the grid's largest spreading diameter (six cells), and
    // the column's depth (four cells here)
    const dictionary dict;
    const wordList names{"glass", "intruder"};
    const auto message = [&](const scalar dLarge)
    {
        FatalIOError.throwExceptions();
        string m;
        try
        {
            exact->checkDiameters(dict, names, scalarList{3.101e-3, dLarge});
        }
        catch (const IOerror& err)
        {
            m = err.message();
        }
        FatalIOError.dontThrowExceptions();
        return m;
    };
    check("spheres3D takes a sphere of three cells", message(3*grid.dx()).empty(), 1, 0);
    const string deep = message(grid.depth());
    Info<< "    message: " << deep.c_str() << endl;
    check("a sphere as deep as the column refused", deep.find("do not fit") != string::npos, 1, 0);
    const string large = message(7*grid.dx());
    Info<< "    message: " << large.c_str() << endl;
    check
    (
        "a sphere of seven cells refused, naming its class and the range",
        large.find("of class intruder") != string::npos
     && large.find("allowed range (0, 0.05715]") != string::npos,
        1, 0
    );
}


// A simple cubic lattice of touching spheres, spacing a third of a
// cell, its centres on the grid lines: every cell away from the walls
// holds a solid fraction pi/6
TEST(Spheres3D, CubicLatticeOfSolidFractionPiOverSix)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny()*grid.nz();
    autoPtr<voidageModel> exact(exactModel(grid));
    const scalar s = grid.dx()/3;
    DynamicList<double> x, y, z, d;
    for (label i = 1; i < 3*grid.nx(); ++i)
    for (label j = 1; j < 18; ++j)
    for (label k = 1; k < 3*grid.nz(); ++k)
    {
        x.append(grid.xMin() + i*s);
        y.append(grid.yMin() + j*s);
        z.append(grid.zMin() + k*s);
        d.append(s);
    }
    scalarField eps(nCells), phiP(nCells);
    exact->updateOverlaps(x.size(), x.cdata(), y.cdata(), z.cdata(), d.cdata(), 1);
    exact->updateFields(x.size(), d.cdata(), eps, phiP);
    scalar worst = 0;
    for (label i = 1; i < grid.nx() - 1; ++i)
    for (label j = 1; j < 5; ++j)
    for (label k = 1; k < grid.nz() - 1; ++k)
    {
        worst = max(worst, mag(eps[grid.cellIJK(i, j, k)] - (1 - pi/6)));
    }
    check("cubic lattice: eps = 1 - pi/6 in the inner cells", 1 + worst, 1, 1e-12);
    check("cubic lattice: empty cell above", eps[grid.cellIJK(1, 8, 1)], 1, 0);
}


// One intruder spread over a sphere of diameter Ds: each cell holds the
// share of the spreading sphere's volume inside it
TEST(Spheres3D, SpreadIntruderOwnCellShare)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    const label nCells = grid.nx()*grid.ny()*grid.nz();
    const scalarField& Vc = grid.cellVolumes();
    const scalar Ds = 2*grid.dx();
    autoPtr<voidageModel> spread(spreadModel(grid));
    const double x = grid.xMin() + 1.3*grid.dx();
    const double y = grid.yMin() + 5.6*grid.dy();
    const double z = grid.zMin() + 2.1*grid.dz();
    const double d = 9.43e-3;
    scalarField eps(nCells), phiP(nCells);
    spread->updateOverlaps(1, &x, &y, &z, &d, 1);
    spread->updateFields(1, &d, eps, phiP);
    const scalar Rs = 0.5*Ds;
    const label c = grid.cellIJK(1, 5, 2);
    const scalar h = 0.5*grid.dx();
    const point& C = mesh.C()[c];
    const scalar share = sphereBoxOverlap
    (
        x, y, z, Rs, C.x() - h, C.x() + h, C.y() - h, C.y() + h,
        C.z() - h, C.z() + h
    )/(4*pi*pow3(Rs)/3);
    check("spread: the own cell's share of the spreading sphere", phiP[c], pi*pow3(d)/6/Vc[c]*share, 1e-12);
    check("spread: the own cell holds less than the whole", share < 0.5, 1, 0);
    check("spread: the volume kept", sum(phiP*Vc), pi*pow3(d)/6, 1e-12);
}


// Beside a wall the spreading sphere's part beyond it stays with the
// cells at the wall: the volume is kept
TEST(Spheres3D, SpreadIntruderAtACornerKeepsItsVolume)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny()*grid.nz();
    const scalarField& Vc = grid.cellVolumes();
    autoPtr<voidageModel> spread(spreadModel(grid));
    const double x = grid.xMin() + 0.5*9.43e-3;
    const double y = grid.yMin() + 0.5*9.43e-3;
    const double z = grid.zMax() - 0.5*9.43e-3;
    const double d = 9.43e-3;
    scalarField eps(nCells), phiP(nCells);
    spread->updateOverlaps(1, &x, &y, &z, &d, 1);
    spread->updateFields(1, &d, eps, phiP);
    check("spread at a corner: the volume kept", sum(phiP*Vc), pi*pow3(d)/6, 1e-12);
}


// coarseGraining diffusion of bandwidth b = 0.009525 m (one cell)
namespace
{
    const scalar b = 0.009525;

    autoPtr<coarseGraining> diffusion(const cartesianGrid& grid)
    {
        return coarseGraining::New
        (
            dictionary
            (
                IStringStream
                (
                    "coarseGraining diffusion; diffusionCoeffs { bandwidth 0.009525; }"
                )()
            ),
            grid
        );
    }

    //- A unit amount in a cell of the column's middle, 12 cells from the
    //  ends, diffused
    scalarField diffusedUnit(const coarseGraining& smoothing, const cartesianGrid& grid, const label c)
    {
        scalarField f(couplingTest::mesh().nCells(), 0);
        f[c] = 1;
        smoothing.smooth(f);
        return f;
    }
}


// A unit amount in a cell of the column's middle, 12 cells from the
// ends: along y it spreads as on an unbounded grid
TEST(DiffusionSmoothing, UnitAmountKeepsSumSignAndVariance)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    autoPtr<coarseGraining> smoothing(diffusion(grid));
    check("diffusion selected", smoothing->type() == "diffusion", 1, 0);

    const label c = grid.cellIJK(1, 12, 2);
    const scalarField f(diffusedUnit(*smoothing, grid, c));
    scalar variance = 0;
    forAll(f, i)
    {
        variance += f[i]*sqr(mesh.C()[i].y() - mesh.C()[c].y());
    }
    check("diffusion: the sum kept", sum(f), 1, 1e-14);
    check("diffusion: no negative value", min(f) >= 0, 1, 0);
    check("diffusion: the variance along y = b^2/2", variance/(0.5*b*b), 1, 1e-12);
    check("diffusion: the cell keeps less than a third", f[c] < 1.0/3, 1, 0);
}


// A uniform field stays uniform
TEST(DiffusionSmoothing, UniformFieldStaysUniform)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    autoPtr<coarseGraining> smoothing(diffusion(grid));
    scalarField uniform(mesh.nCells(), 0.4);
    smoothing->smooth(uniform);
    check("diffusion: a uniform field stays", 1 + max(mag(uniform - 0.4)), 1, 1e-15);
}


// A vector field is diffused by components: its z component is 3 times
// the diffused unit amount
TEST(DiffusionSmoothing, VectorFieldByComponents)
{
    const fvMesh& mesh = couplingTest::mesh();
    const cartesianGrid grid(mesh);
    autoPtr<coarseGraining> smoothing(diffusion(grid));
    const label c = grid.cellIJK(1, 12, 2);
    const scalarField f(diffusedUnit(*smoothing, grid, c));
    vectorField v(mesh.nCells(), Zero);
    v[c] = vector(1, -2, 3);
    smoothing->smooth(v);
    check("diffusion: a vector field by components", 1 + max(mag(v.component(2) - 3*f)), 1, 1e-15);
}


int main(int argc, char *argv[])
{
    return couplingTest::main(argc, argv, couplingTest::readCase);
}
