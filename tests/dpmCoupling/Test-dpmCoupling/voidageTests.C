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
    Test-dpmCoupling: the Sauter mean diameter of mapped mixtures, and the
    voidage models (selection, the mapped volumes against the particles'
    own, lattices of known solid fraction) (GoogleTest suites SauterMean
    and VoidageModels).

\*---------------------------------------------------------------------------*/

#include "couplingTest.H"
#include "cartesianGrid.H"
#include "solidsMixture.H"
#include "voidageModel.H"
#include "Random.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

using namespace Foam;

static const scalar pi = constant::mathematical::pi;


// The mixture of the cells (solidsMixture.H, as gasParticleExchange
// maps it): the Sauter mean diameter of discs laid in the grid with
// their overlaps
TEST(SauterMean, EqualSizesAndEqualVolumesOfMappedDiscs)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny();
    const scalarField& Vc = grid.cellVolumes();
    Random rnd(11);

    // Discs of the given diameters at random in the lowest 2 x 2 cells;
    // returns <d> at a point between them
    auto sauterOf = [&](const scalarList& diameters, const labelList& classes)
    {
        List<scalarField> phiK(2, scalarField(nCells, Zero));
        scalarField byD(nCells, Zero);
        forAll(diameters, i)
        {
            const scalar r = 0.5*diameters[i];
            const scalar x = grid.xMin() + r + rnd.sample01<scalar>()*(2*grid.dx() - 2*r);
            const scalar y = grid.yMin() + r + rnd.sample01<scalar>()*(2*grid.dy() - 2*r);
            label cells[4];
            scalar f[4];
            label count = 0;
            grid.forEachDiscOverlap
            (
                x, y, r,
                [&](label c, scalar a) { cells[count] = c; f[count++] = a/(pi*r*r); }
            );
            solidsMixture::addParticle(diameters[i], classes[i], count, cells, f, Vc, phiK, byD);
        }
        const scalarField phiP(phiK[0] + phiK[1]);
        label cells[8];
        scalar w[8];
        const label count = grid.interpolationStencil(grid.xMin() + grid.dx(), grid.yMin() + grid.dy(), 0, cells, w);
        return solidsMixture::sauterDiameter(count, cells, w, phiP, byD, -1);
    };

    // Equal sizes in two classes: <d> is the diameter itself, y = 1
    labelList alternate(40);
    forAll(alternate, i) alternate[i] = (i % 3 == 0);
    check("Sauter mean of equal sizes in two classes", sauterOf(scalarList(40, 2e-3), alternate), 2e-3, 1e-14);
    // Equal volumes of 1.5 and 2.5 mm (125 small and 27 large discs):
    // the mass-fraction harmonic mean 1.875 mm of the paper's Umf, where
    // the four cells' shares are interpolated with equal weights
    {
        scalarList ds(152);
        labelList cls(152);
        forAll(ds, i)
        {
            ds[i] = i < 125 ? 1.5e-3 : 2.5e-3;
            cls[i] = i < 125 ? 0 : 1;
        }
        check("Sauter mean of equal volumes of 1.5 and 2.5 mm", sauterOf(ds, cls), 1.875e-3, 1e-11);
    }
}


// No solids near the point: the particle's own diameter stands
TEST(SauterMean, FallbackWithoutSolids)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny();
    const scalarField zero(nCells, Zero);
    label cells[8];
    scalar w[8];
    const label count = grid.interpolationStencil(grid.xMin() + 0.05, grid.yMin() + 0.5, 0, cells, w);
    check("bilinear stencil on a grid one cell thick", count, 4, 0);
    check("Sauter mean without solids: fallback", solidsMixture::sauterDiameter(count, cells, w, zero, zero, 1.5e-3), 1.5e-3, 0);
}


// The voidage models (voidageModels/): selection, and the mapped
// volumes against the particles' own
namespace
{
    const scalar voidageMin = 0.1;

    //- A voidage model on the grid, selected by its entries
    autoPtr<voidageModel> select(const char* entries, const cartesianGrid& grid)
    {
        return voidageModel::New(dictionary(IStringStream(entries)()), grid, voidageMin);
    }
}


TEST(VoidageModels, SelectedByName)
{
    const cartesianGrid grid(couplingTest::mesh());
    autoPtr<voidageModel> discs(select("", grid));
    autoPtr<voidageModel> slab(select("voidageModel slab3D;", grid));
    autoPtr<voidageModel> spheres(select("voidageModel spheres3D;", grid));
    check("default voidage model is discs2D", discs->type() == "discs2D", 1, 0);
    check("voidageModel slab3D selects slab3D", slab->type() == "slab3D", 1, 0);
    check("voidageModel spheres3D selects spheres3D", spheres->type() == "spheres3D", 1, 0);
}


// 1e4 random spheres of 1.5 and 2.5 mm anywhere in the bed: the
// cells' volume fractions sum to the spheres' volume (round-off)
TEST(VoidageModels, MappedVolumesAreTheParticlesVolume)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny();
    const scalarField& Vc = grid.cellVolumes();
    autoPtr<voidageModel> discs(select("", grid));
    autoPtr<voidageModel> slab(select("voidageModel slab3D;", grid));
    autoPtr<voidageModel> spheres(select("voidageModel spheres3D;", grid));
    Random rnd(13);
    const label n = 10000;
    List<double> x(n), y(n), z(n), d(n);
    scalar Vp = 0;
    for (label i = 0; i < n; ++i)
    {
        d[i] = (i % 2 ? 1.5e-3 : 2.5e-3);
        const scalar r = 0.5*d[i];
        x[i] = grid.xMin() + r + rnd.sample01<scalar>()*(0.15 - 2*r);
        y[i] = grid.yMin() + r + rnd.sample01<scalar>()*(0.9 - 2*r);
        z[i] = 0.5*grid.depth();
        Vp += pi*pow3(d[i])/6;
    }
    for (const label nThreads : {1, 2})
    {
        scalarField eps(nCells), phiP(nCells);
        slab->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), d.cdata(), nThreads);
        slab->updateFields(n, d.cdata(), eps, phiP);
        const std::string t = " (" + std::to_string(nThreads) + " threads)";
        check("slab3D: mapped sphere volumes = particles' volume" + t, sum(phiP*Vc), Vp, 1e-12);
        check("slab3D: voidage = 1 - phiP" + t, max(mag(eps - max(1 - phiP, voidageMin))), 0, 0);
        label shared = 0;
        forAll(slab->counts(), i) shared += slab->counts()[i] > 1;
        check("slab3D: some spheres straddle cells" + t, shared > 1000, 1, 0);

        // On a mesh one cell thick, spheres3D's box volumes are the
        // column volumes: the same shares to round-off
        scalarField epsSpheres(nCells), phiPSpheres(nCells);
        spheres->updateOverlaps(n, x.cdata(), y.cdata(), z.cdata(), d.cdata(), nThreads);
        spheres->updateFields(n, d.cdata(), epsSpheres, phiPSpheres);
        check("spheres3D one cell thick: phiP of slab3D" + t, 1 + max(mag(phiPSpheres - phiP)), 1, 1e-12);

        discs->updateOverlaps(n, x.cdata(), y.cdata(), nullptr, d.cdata(), nThreads);
        discs->updateFields(n, d.cdata(), eps, phiP);
        check("discs2D: mapped sphere volumes = particles' volume" + t, sum(phiP*Vc), Vp, 1e-12);
    }
}


// Square lattice of 2.5 mm particles, 3 x 3 in every cell of the
// lowest 4 rows: disc-area fraction pi/4; a sphere volume fraction
// pi d/(6 depth) (9 spheres of pi d^3/6 in 3d x 3d x depth)
TEST(VoidageModels, SquareLatticeOfKnownSolidFraction)
{
    const cartesianGrid grid(couplingTest::mesh());
    const label nCells = grid.nx()*grid.ny();
    autoPtr<voidageModel> discs(select("", grid));
    autoPtr<voidageModel> slab(select("voidageModel slab3D;", grid));
    const scalar dp = 2.5e-3;
    const label n = 3*grid.nx()*3*4;
    List<double> x(n), y(n), d(n, dp);
    for (label i = 0; i < n; ++i)
    {
        x[i] = grid.xMin() + dp*(i % (3*grid.nx()) + 0.5);
        y[i] = grid.yMin() + dp*(i/(3*grid.nx()) + 0.5);
    }
    const label c = grid.cellIJ(5, 2);
    scalarField eps(nCells), phiP(nCells);

    slab->updateOverlaps(n, x.cdata(), y.cdata(), nullptr, d.cdata(), 1);
    slab->updateFields(n, d.cdata(), eps, phiP);
    const scalar phiSlab = pi*dp/(6*grid.depth());
    check("slab3D lattice: phiP = pi d/(6 depth)", phiP[c], phiSlab, 1e-12);
    check("slab3D lattice: voidage = 1 - pi d/(6 depth)", eps[c], 1 - phiSlab, 1e-12);
    check("slab3D lattice: empty cell above", eps[grid.cellIJ(5, 4)], 1, 0);

    discs->updateOverlaps(n, x.cdata(), y.cdata(), nullptr, d.cdata(), 1);
    discs->updateFields(n, d.cdata(), eps, phiP);
    // Hoomans et al. (1996): 1 - 2/sqrt(pi sqrt 3) (1 - eps_2D)^1.5
    check("discs2D lattice: Hoomans of 1 - pi/4", eps[c], 1 - 2/std::sqrt(pi*std::sqrt(3.0))*std::pow(pi/4, 1.5), 1e-12);
    check("discs2D lattice: phiP = (2/3) d/depth pi/4", phiP[c], 2.0/3*dp/grid.depth()*pi/4, 1e-12);
}
