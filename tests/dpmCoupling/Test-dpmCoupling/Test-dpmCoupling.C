/*---------------------------------------------------------------------------*\
Application
    Test-dpmCoupling

Description
    Checks of the coupling library against numbers from outside the code:
    circle geometry, the Hoomans voidage of close packings, Wen-Yu's Umf of
    the paper's Table 3, Stokes' law, the Ergun equation and the Dallavalle
    drag of a single sphere; the unknown-entry check (knownEntries.H). Run
    in a case with the paper's 20 x 120 mesh.
    Ends with the line "N passed, M failed".

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cartesianGrid2D.H"
#include "fluidization.H"
#include "dragModel.H"
#include "Random.H"
#include "knownEntries.H"

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

    // Wen-Yu Umf of the paper's Table 3 within 7 % (model.md section 2)
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

        // Stokes' law at eps = 1 and Re = 1e-6: K = 3 pi mu d
        const scalar creep = 1e-6*mu/(rho*d);
        ergunWenYu->dragCoefficient(scalarField(1, 1.0), dd, scalarField(1, creep), K);
        check("Wen-Yu at eps = 1, Re -> 0: Stokes", K[0], 3*pi*mu*d, 1e-3);

        // Ergun: n K u = 150 (1-e)^2 mu Us/(e^3 d^2) + 1.75 (1-e) rho Us^2/(e^3 d)
        const scalar eps = 0.4, u = 1.0, Us = eps*u;
        ergunWenYu->dragCoefficient(scalarField(1, eps), dd, scalarField(1, u), K);
        const scalar ergun =
            150*sqr(1 - eps)*mu*Us/(pow3(eps)*d*d)
          + 1.75*(1 - eps)*rho*Us*Us/(pow3(eps)*d);
        check("Ergun pressure gradient of a fixed bed", (1 - eps)/Vp*K[0]*u, ergun, 1e-12);

        // Di Felice at eps = 1: Dallavalle C_D = (0.63 + 4.8/sqrt(Re))^2
        const scalar slip = 0.5, Re = rho*d*slip/mu;
        diFelice->dragCoefficient(scalarField(1, 1.0), dd, scalarField(1, slip), K);
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

    Info<< nl << nPassed << " passed, " << nFailed << " failed" << endl;
    return nFailed ? 1 : 0;
}
