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
    Test-dpmCoupling

Description
    Checks of the coupling library against numbers from outside the code:
    circle geometry, the Hoomans voidage of close packings, Wen-Yu's Umf of
    the paper's Table 3, Stokes' law, the Ergun equation and the Dallavalle
    drag of a single sphere; the unknown-entry check (knownEntries.H); the
    closures for mixtures (GidaspowBlend, KochHill, Beetstra) against their
    limits and against values worked by hand from the published formulas;
    the Sauter mean diameter of mapped mixtures; the voidage models (their
    selection, the mapped volumes against the particles' volume, lattices
    of known solid fraction). Run in a case with the paper's 20 x 120 mesh
    (2.5 mm thick).
    Ends with the line "N passed, M failed".

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cartesianGrid2D.H"
#include "fluidization.H"
#include "dragModel.H"
#include "KochHill.H"
#include "Beetstra.H"
#include "solidsMixture.H"
#include "Random.H"
#include "knownEntries.H"
#include "voidageModel.H"
#include "IStringStream.H"

using namespace Foam;

static label nPassed = 0, nFailed = 0;

//- Compare with a relative tolerance and report
static void check
(
    const std::string& what, const scalar value, const scalar expected,
    const scalar relTol
)
{
    const scalar err = mag(value - expected)/max(mag(expected), VSMALL);
    const bool ok = err <= relTol;
    (ok ? nPassed : nFailed)++;
    Info<< (ok ? "PASS " : "FAIL ") << what.c_str() << ": " << value
        << " expected " << expected << " (relative error " << err
        << ", tolerance " << relTol << ")" << endl;
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar pi = constant::mathematical::pi;

    // Circle geometry (textbook): segment area r^2 acos(h/r) - h sqrt(r^2-h^2)
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
    {
        const cartesianGrid2D grid(mesh);
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
    check
    (
        "Hoomans voidage of hexagonal packing",
        fluidization::voidage3D(1 - pi/(2*std::sqrt(3.0))),
        1 - pi/(3*std::sqrt(2.0)),
        1e-10
    );
    check("Hoomans voidage of empty cell", fluidization::voidage3D(1), 1, 1e-15);

    // Wen-Yu Umf of the paper's Table 3 within 7 % (docs/theory/paper-model.md, "Minimum fluidization velocity")
    {
        const scalar wSmall[3] = {0.25, 0.5, 0.75};
        const scalar bar[4] = {1, 8, 32, 64};
        const scalar table3[3][4] =
        {
            {1.10, 0.45, 0.23, 0.17},
            {0.98, 0.41, 0.22, 0.15},
            {0.87, 0.38, 0.20, 0.14}
        };
        const scalarList d({1.5e-3, 2.5e-3});
        for (int i = 0; i < 3; ++i)
        {
            const scalarList w({wSmall[i], 1 - wSmall[i]});
            const scalar dMix = fluidization::harmonicMeanDiameter(w, d);
            for (int j = 0; j < 4; ++j)
            {
                const scalar Umf = fluidization::wenYuUmf
                (
                    dMix, 2525, 1.204*bar[j], 1.75e-5, 9.81
                );
                check
                (
                    "Umf w_small " + std::to_string(wSmall[i]).substr(0, 4)
                  + " at " + std::to_string(int(bar[j])) + " bar (Table 3)",
                    Umf, table3[i][j], 0.07
                );
            }
        }
        check
        (
            "harmonic mean diameter at w = 0.5",
            fluidization::harmonicMeanDiameter(scalarList({0.5, 0.5}), d),
            1.875e-3, 1e-12
        );
    }

    // Drag laws against textbook single-sphere and packed-bed results
    {
        const scalar rho = 1.204, mu = 1.75e-5, d = 1.5e-3;
        const scalar Vp = pi*d*d*d/6;
        dictionary dict;
        dict.add("dragModel", "ErgunWenYu");
        autoPtr<dragModel> ergunWenYu(dragModel::New(dict, rho, mu));
        dict.set("dragModel", "DiFelice");
        autoPtr<dragModel> diFelice(dragModel::New(dict, rho, mu));

        scalarField K(1);
        const scalarField dd(1, d);
        const particleMixture noMixture;

        // Stokes' law at eps = 1 and Re = 1e-6: K = 3 pi mu d
        const scalar creep = 1e-6*mu/(rho*d);
        ergunWenYu->dragCoefficient(scalarField(1, 1.0), dd, scalarField(1, creep), noMixture, K);
        check("Wen-Yu at eps = 1, Re -> 0: Stokes", K[0], 3*pi*mu*d, 1e-3);

        // Ergun: n K u = 150 (1-e)^2 mu Us/(e^3 d^2) + 1.75 (1-e) rho Us^2/(e^3 d)
        const scalar eps = 0.4, u = 1.0, Us = eps*u;
        ergunWenYu->dragCoefficient(scalarField(1, eps), dd, scalarField(1, u), noMixture, K);
        const scalar ergun =
            150*sqr(1 - eps)*mu*Us/(pow3(eps)*d*d)
          + 1.75*(1 - eps)*rho*Us*Us/(pow3(eps)*d);
        check("Ergun pressure gradient of a fixed bed", (1 - eps)/Vp*K[0]*u, ergun, 1e-12);

        // Di Felice at eps = 1: Dallavalle C_D = (0.63 + 4.8/sqrt(Re))^2
        const scalar slip = 0.5, Re = rho*d*slip/mu;
        diFelice->dragCoefficient(scalarField(1, 1.0), dd, scalarField(1, slip), noMixture, K);
        const scalar Cd = sqr(0.63 + 4.8/std::sqrt(Re));
        check("Di Felice at eps = 1: Dallavalle drag", K[0]*slip, 0.5*Cd*rho*0.25*pi*d*d*slip*slip, 1e-12);
    }

    // Unknown entries: the edit distance, and what passes and what does not
    {
        check("edit distance restitutoin/restitution", editDistance("restitutoin", "restitution"), 2, 0);
        check("edit distance nThread/nThreads", editDistance("nThread", "nThreads"), 1, 0);
        check("edit distance to an empty word", editDistance("", "kn"), 2, 0);

        const wordList known{"kn", "kt", "restitution"};
        auto message = [&](const string& text)
        {
            IStringStream is(text);
            const dictionary dict(is);
            FatalIOError.throwExceptions();
            try
            {
                checkKnownEntries(dict, known, "contact", wordHashSet{"wSmall"});
            }
            catch (const IOerror& err)
            {
                FatalIOError.dontThrowExceptions();
                return string(err.message());
            }
            FatalIOError.dontThrowExceptions();
            return string();
        };
        check("known entries, a pattern, a settings entry pass", message("kn 1; \"(kt|restitution)\" 0.5; wSmall 0.5;").empty(), 1, 0);
        const string m = message("kn 1; restitutoin 0.9;");
        Info<< "    message: " << m.c_str() << endl;
        check("a misspelling names the nearest entry", m.find("unknown entry 'restitutoin' in contact; did you mean 'restitution'?") != string::npos, 1, 0);
        check("a pattern matching no entry is unknown", message("\"kx.*\" 1;").empty(), 0, 0);
    }

    // The closures for mixtures. Hand values: the published formulas worked
    // with Python's math module (not this code) for rho = 1.204 kg/m3,
    // mu = 1.75e-5 Pa s, d = 1.5 mm; K = beta V_p/(1 - eps), beta the
    // two-fluid coefficient divided by eps (the gas sees the whole grad p)
    {
        const scalar rho = 1.204, mu = 1.75e-5, d = 1.5e-3;
        const scalar Vp = pi*d*d*d/6;
        const scalar stokes = 3*pi*mu*d;
        const scalar creep = 1e-6*mu/(rho*d);
        const scalarField dd(1, d);
        scalarField K(1);

        auto model = [&](const word& type)
        {
            dictionary dict;
            dict.add("dragModel", type);
            return dragModel::New(dict, rho, mu);
        };
        autoPtr<dragModel> blend(model("GidaspowBlend"));
        autoPtr<dragModel> kochHill(model("KochHill"));
        autoPtr<dragModel> beetstra(model("Beetstra"));
        check("only Beetstra needs the mixture", blend->needsMixture() + kochHill->needsMixture() + 10*beetstra->needsMixture(), 10, 0);

        const particleMixture noMixture;
        auto K1 = [&](const dragModel& m, const scalar eps, const scalar slip, const scalar dMean = 0)
        {
            particleMixture mix;
            if (dMean > 0) mix.sauterDiameter = scalarField(1, dMean);
            m.dragCoefficient(scalarField(1, eps), dd, scalarField(1, slip), dMean > 0 ? mix : noMixture, K);
            return K[0];
        };

        // Huilin and Gidaspow (2003): beta = (1 - phi) beta_WenYu + phi beta_Ergun,
        // phi = 1/2 + arctan(262.5 (alpha_s - 0.2))/pi
        // At eps = 1 the Ergun weight is 1/2 + arctan(-52.5)/pi = 0.0060623
        // (hand), and Ergun's drag vanishes there as Re -> 0: Stokes x 0.99394
        check("GidaspowBlend at eps = 1, Re -> 0: Stokes x (1 - 0.0060623)", K1(*blend, 1, creep), stokes*(1 - 0.006062312362569933), 1e-3);
        // eps = 1, slip 0.5 m/s (Re 51.6): Schiller-Naumann K = C_D rho pi d^2 |u-v|/8
        // = 8.0469e-7; the blend keeps an Ergun weight 0.0061 there: 8.07337e-7
        {
            const scalar Re = rho*d*0.5/mu;
            const scalar Cd = 24/Re*(1 + 0.15*std::pow(Re, 0.687));
            check("GidaspowBlend at eps = 1: Schiller-Naumann (Ergun weight 0.006)", K1(*blend, 1, 0.5), Cd*rho*pi*d*d*0.5/8, 0.005);
            check("GidaspowBlend at eps = 1, 0.5 m/s (hand)", K1(*blend, 1, 0.5), 8.073372333338735e-07, 1e-12);
        }
        check("GidaspowBlend eps 0.6, 1 m/s (hand)", K1(*blend, 0.6, 1), 6.423249587474494e-06, 1e-12);
        check("GidaspowBlend eps 0.8, 1 m/s: mean of Ergun and Wen-Yu (hand)", K1(*blend, 0.8, 1), 3.0218247847649264e-06, 1e-12);
        check("GidaspowBlend eps 0.95, 0.5 m/s (hand)", K1(*blend, 0.95, 0.5), 9.509303663485336e-07, 1e-12);
        // Continuous across alpha_s = 0.2, where ErgunWenYu jumps by 1.6 x
        for (const scalar slip : {0.2, 2.0})
        {
            const scalar below = K1(*blend, 0.8 - 1e-9, slip), above = K1(*blend, 0.8 + 1e-9, slip);
            check("GidaspowBlend continuous at eps = 0.8, " + std::to_string(slip).substr(0, 3) + " m/s", above, below, 1e-6);
        }

        // Hill, Koch and Ladd (2001) as Bokkers et al. (2004):
        // beta_A = 18 mu eps^2 alpha_s/d^2 (F0 + F3 Re/2), Re = rho d eps |u-v|/mu
        check("KochHill at eps = 1, Re -> 0: Stokes", K1(*kochHill, 1, creep), stokes, 1e-3);
        // Dense, Re -> 0: F0 = 10 alpha_s/eps^3 is Carman-Kozeny,
        // -dp/dx = 180 alpha_s^2 mu Us/(eps^3 d^2) at the superficial Us = eps u
        {
            const scalar eps = 0.4, Us = eps*creep;
            check("KochHill fixed bed at eps 0.4: Carman-Kozeny", (1 - eps)/Vp*K1(*kochHill, eps, creep)*creep, 180*sqr(1 - eps)*mu*Us/(pow3(eps)*d*d), 1e-5);
        }
        check("KochHill eps 0.7, 1 m/s (Re 72.2, hand)", K1(*kochHill, 0.7, 1), 3.3166296673548563e-06, 1e-12);
        check("KochHill eps 0.5, 0.3 m/s (Re 15.5, hand)", K1(*kochHill, 0.5, 0.3), 5.824735899592724e-06, 1e-12);
        check("KochHill F0 at alpha_s = 0.4: jump to Carman-Kozeny (hand 1.04 %)", dragModels::KochHill::F0(0.4)/dragModels::KochHill::F0(0.4 - 1e-12) - 1, 0.010421515760360656, 1e-8);

        // Beetstra, van der Hoef and Kuipers (2007): F(a, Re), Re on <d> and
        // the superficial slip; f_i = eps y + a y^2 + 0.064 eps y^3
        using dragModels::Beetstra;
        check("Beetstra F at a = 0, Re = 0: Stokes", Beetstra::F(0, 0), 1, 1e-15);
        check("Beetstra F(0.5, 0) = 10 a/eps^2 + eps^2 (1 + 1.5 sqrt a) (hand)", Beetstra::F(0.5, 0), 20.515165042944954, 1e-14);
        check("Beetstra F(0.4, 100) (hand)", Beetstra::F(0.4, 100), 30.741552554327278, 1e-12);
        check("Beetstra F(0.2, 10) (hand)", Beetstra::F(0.2, 10), 5.187160872063553, 1e-12);
        // Single sphere: a fit, within 6 % of Schiller-Naumann 1 + 0.15 Re^0.687 at Re 10
        check("Beetstra F(0, 10) near Schiller-Naumann", Beetstra::F(0, 10), 1 + 0.15*std::pow(10.0, 0.687), 0.06);
        check("Beetstra F(0, Re -> 0) continuous", Beetstra::F(0, 1e-12), 1, 1e-6);
        // Equal sizes: y = 1, f = 1 + 0.064 eps (the published f_i), so K is
        // the monodisperse 3 pi mu d F (1 + 0.064 eps)
        {
            const scalar eps = 0.6, slip = 0.5;
            const scalar Re = rho*eps*slip*d/mu;
            check("Beetstra equal sizes: monodisperse F times f(y = 1)", K1(*beetstra, eps, slip, d), stokes*Beetstra::F(1 - eps, Re)*(1 + 0.064*eps), 1e-14);
            check("Beetstra at eps = 1, Re -> 0: Stokes times f(y = 1) = 1.064", K1(*beetstra, 1, creep, d)/stokes, 1.064, 1e-3);
        }
        // Binary at equal volumes of 1.5 and 2.5 mm: <d> = 1.875 mm, y = 0.8
        // and 4/3, eps 0.6, slip 0.5 m/s (<Re> 38.7), hand: small 3.66377e-6,
        // large 1.29464e-5 N s/m
        {
            const scalar dMean = 1/(0.5/1.5e-3 + 0.5/2.5e-3);
            check("Beetstra small in a binary (hand)", K1(*beetstra, 0.6, 0.5, dMean), 3.663767146745189e-06, 1e-12);
            scalarField Kl(1);
            particleMixture mix;
            mix.sauterDiameter = scalarField(1, dMean);
            beetstra->dragCoefficient(scalarField(1, 0.6), scalarField(1, 2.5e-3), scalarField(1, 0.5), mix, Kl);
            check("Beetstra large in a binary (hand)", Kl[0], 1.294638077333998e-05, 1e-12);
        }
    }

    // The mixture of the cells (solidsMixture.H, as gasParticleExchange
    // maps it): the Sauter mean diameter of discs laid in the grid with
    // their overlaps
    {
        const cartesianGrid2D grid(mesh);
        const label nCells = grid.nx()*grid.ny();
        const scalar Vc = grid.cellVolume();
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
            label cells[4];
            scalar w[4];
            grid.interpolationStencil(grid.xMin() + grid.dx(), grid.yMin() + grid.dy(), cells, w);
            return solidsMixture::sauterDiameter(cells, w, phiP, byD, -1);
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
        // No solids near the point: the particle's own diameter stands
        {
            const scalarField zero(nCells, Zero);
            label cells[4];
            scalar w[4];
            grid.interpolationStencil(grid.xMin() + 0.05, grid.yMin() + 0.5, cells, w);
            check("Sauter mean without solids: fallback", solidsMixture::sauterDiameter(cells, w, zero, zero, 1.5e-3), 1.5e-3, 0);
        }
    }

    // The voidage models (voidageModels/): selection, and the mapped
    // volumes against the particles' own
    {
        const cartesianGrid2D grid(mesh);
        const label nCells = grid.nx()*grid.ny();
        const scalar Vc = grid.cellVolume();
        const scalar voidageMin = 0.1;
        auto select = [&](const char* entries)
        {
            return voidageModel::New(dictionary(IStringStream(entries)()), grid, voidageMin);
        };
        autoPtr<voidageModel> discs(select(""));
        autoPtr<voidageModel> slab(select("voidageModel slab3D;"));
        check("default voidage model is discs2D", discs->type() == "discs2D", 1, 0);
        check("voidageModel slab3D selects slab3D", slab->type() == "slab3D", 1, 0);

        // 1e4 random spheres of 1.5 and 2.5 mm anywhere in the bed: the
        // cells' volume fractions sum to the spheres' volume (round-off)
        {
            Random rnd(13);
            const label n = 10000;
            List<double> x(n), y(n), d(n);
            scalar Vp = 0;
            for (label i = 0; i < n; ++i)
            {
                d[i] = (i % 2 ? 1.5e-3 : 2.5e-3);
                const scalar r = 0.5*d[i];
                x[i] = grid.xMin() + r + rnd.sample01<scalar>()*(0.15 - 2*r);
                y[i] = grid.yMin() + r + rnd.sample01<scalar>()*(0.9 - 2*r);
                Vp += pi*pow3(d[i])/6;
            }
            for (const label nThreads : {1, 2})
            {
                scalarField eps(nCells), phiP(nCells);
                slab->updateOverlaps(n, x.cdata(), y.cdata(), d.cdata(), nThreads);
                slab->updateFields(n, d.cdata(), eps, phiP);
                const std::string t = " (" + std::to_string(nThreads) + " threads)";
                check("slab3D: mapped sphere volumes = particles' volume" + t, sum(phiP)*Vc, Vp, 1e-12);
                check("slab3D: voidage = 1 - phiP" + t, max(mag(eps - max(1 - phiP, voidageMin))), 0, 0);
                label shared = 0;
                forAll(slab->counts(), i) shared += slab->counts()[i] > 1;
                check("slab3D: some spheres straddle cells" + t, shared > 1000, 1, 0);

                discs->updateOverlaps(n, x.cdata(), y.cdata(), d.cdata(), nThreads);
                discs->updateFields(n, d.cdata(), eps, phiP);
                check("discs2D: mapped sphere volumes = particles' volume" + t, sum(phiP)*Vc, Vp, 1e-12);
            }
        }

        // Square lattice of 2.5 mm particles, 3 x 3 in every cell of the
        // lowest 4 rows: disc-area fraction pi/4; a sphere volume fraction
        // pi d/(6 depth) (9 spheres of pi d^3/6 in 3d x 3d x depth)
        {
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

            slab->updateOverlaps(n, x.cdata(), y.cdata(), d.cdata(), 1);
            slab->updateFields(n, d.cdata(), eps, phiP);
            const scalar phiSlab = pi*dp/(6*grid.depth());
            check("slab3D lattice: phiP = pi d/(6 depth)", phiP[c], phiSlab, 1e-12);
            check("slab3D lattice: voidage = 1 - pi d/(6 depth)", eps[c], 1 - phiSlab, 1e-12);
            check("slab3D lattice: empty cell above", eps[grid.cellIJ(5, 4)], 1, 0);

            discs->updateOverlaps(n, x.cdata(), y.cdata(), d.cdata(), 1);
            discs->updateFields(n, d.cdata(), eps, phiP);
            // Hoomans et al. (1996): 1 - 2/sqrt(pi sqrt 3) (1 - eps_2D)^1.5
            check("discs2D lattice: Hoomans of 1 - pi/4", eps[c], 1 - 2/std::sqrt(pi*std::sqrt(3.0))*std::pow(pi/4, 1.5), 1e-12);
            check("discs2D lattice: phiP = (2/3) d/depth pi/4", phiP[c], 2.0/3*dp/grid.depth()*pi/4, 1e-12);
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
