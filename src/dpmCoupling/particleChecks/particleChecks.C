/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
\*---------------------------------------------------------------------------*/

#include "particleChecks.H"
#include "gasProperties.H"
#include "dragModel.H"
#include "knownEntries.H"
#include "particlePropertiesEntries.H"
#include "Time.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::particleChecks::smallestClass(const dem::Settings& settings)
{
    int k = 0;
    dem::timeStepBound(settings, &k);
    return label(k);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleChecks::entries(const Time& time) const
{
    namespace names = particlePropertiesEntries;
    const string where("constant/particleProperties");
    const entryHome top{where + " (its top level)", names::top()};
    const entryHome sizeClass{where + "/classes/<class>", names::sizeClass()};
    const entryHome contact{where + "/contact", names::contact()};
    const entryHome initialBed{where + "/initialBed", names::initialBed()};
    const entryHome gas{"constant/gasProperties", gasProperties::entries()};

    // The coefficients of every drag model may stand at the top level
    wordHashSet alsoAllowed(settingsEntries(time));
    for (const word& model : dragModel::dictionaryConstructorTablePtr_->toc())
    {
        alsoAllowed.insert(model + "Coeffs");
    }
    checkKnownEntries
    (
        dict_, names::top(), where, alsoAllowed,
        "and <dragModel>Coeffs and the entries of the settings files"
        " that the case's dictionaries #include",
        {contact, initialBed, sizeClass, gas}
    );

    for (const entry& e : dict_.subDict("classes"))
    {
        if (e.isDict())
        {
            checkKnownEntries
            (
                e.dict(), names::sizeClass(), where + "/classes/" + e.keyword(),
                wordHashSet(), string(), {top, contact, initialBed}
            );
            // A distribution of diameters
            const dictionary* d = e.dict().findDict("diameter", keyType::LITERAL);
            if (d)
            {
                checkKnownEntries
                (
                    *d, names::diameterDistribution(),
                    where + "/classes/" + e.keyword() + "/diameter",
                    wordHashSet(), string(), {sizeClass}
                );
            }
        }
    }
    checkKnownEntries
    (
        dict_.subOrEmptyDict("contact"), names::contact(), where + "/contact",
        wordHashSet(), string(), {top, sizeClass, initialBed, gas}
    );
    // A pair's or a wall's own coefficients (their names: particleEngine)
    const dictionary contactDict(dict_.subOrEmptyDict("contact"));
    const entryHome pairs
    {
        where + "/contact/pairs/<classA>-<classB>", names::pairContact()
    };
    const entryHome walls{where + "/contact/walls/<class>", names::wallContact()};
    const auto checkOwn = [&]
    (
        const word& name,
        const entryHome& own,
        const entryHome& other
    )
    {
        const dictionary* d = contactDict.findDict(name, keyType::LITERAL);
        for (const entry& e : d ? *d : dictionary::null)
        {
            if (e.isDict())
            {
                checkKnownEntries
                (
                    e.dict(), own.entries,
                    where + "/contact/" + name + "/" + e.keyword(),
                    wordHashSet(), string(), {other}
                );
            }
        }
    };
    checkOwn("pairs", pairs, walls);
    checkOwn("walls", walls, pairs);
    checkKnownEntries
    (
        dict_.subOrEmptyDict("initialBed"), names::initialBed(),
        where + "/initialBed", wordHashSet(), string(), {top, contact, sizeClass}
    );
    // The placed particles of each class
    const entryHome placed
    {
        where + "/initialBed/place/<class>", names::placedClass()
    };
    const dictionary bed(dict_.subOrEmptyDict("initialBed"));
    for (const entry& e : bed.subOrEmptyDict("place"))
    {
        if (e.isDict())
        {
            checkKnownEntries
            (
                e.dict(), names::placedClass(),
                where + "/initialBed/place/" + e.keyword(),
                wordHashSet(), string(), {initialBed}
            );
        }
    }
}


void Foam::particleChecks::gasDensity
(
    const gasProperties& gas,
    const scalarList& rhoP
) const
{
    // The gas must be lighter than every class, or nothing can fluidize
    // (the Archimedes number of Umf turns negative)
    const label lightest = findMin(rhoP);
    if (!(gas.rho() < rhoP[lightest]))
    {
        FatalIOErrorInFunction(gas)
            << "operatingPressure " << gas.operatingPressure() << " bar in "
            << "constant/gasProperties gives a gas density " << gas.rho()
            << " kg/m3, not below the particles' " << rhoP[lightest]
            << " kg/m3 (class " << classNames_[lightest] << " of "
            << "constant/particleProperties): the particles must be denser"
            << " than the gas, or no bed can fluidize; allowed range (0, "
            << gas.operatingPressure()*rhoP[lightest]/gas.rho() << ") bar"
            << exit(FatalIOError);
    }
}


void Foam::particleChecks::writeInterval
(
    const scalar interval,
    const scalar dtGas
) const
{
    // Particle files on the requested times: the run writes one when a
    // step lands on a multiple of writeInterval, so the interval must be
    // a whole number of CFD steps (else the files come at uneven times, or
    // every step when the interval is below the step)
    const scalar steps = interval/dtGas;
    const label n = label(std::round(steps));
    if (n < 1 || mag(steps - n) > 1e-6*steps)
    {
        const label below = max(label(std::floor(steps)), 1);
        FatalIOErrorInFunction(dict_)
            << "Entry 'writeInterval' = " << interval << " in "
            << "constant/particleProperties is not a whole multiple of the CFD"
            << " step deltaT = " << dtGas << " of system/controlDict: the"
            << " particle files would "
            << (steps < 1 ? "come every CFD step" : "come at uneven times")
            << "; allowed: a multiple of the CFD step, e.g. " << below*dtGas
            << " or " << (below + 1)*dtGas << exit(FatalIOError);
    }
}


void Foam::particleChecks::demStep(const dem::Settings& settings) const
{
    // The bounds need valid particles and contact: an invalid one is the
    // DEM's to name (dem::Simulation, next)
    if (settings.classes.empty() || !(settings.contact.kn > 0))
    {
        return;
    }
    const scalar e = settings.contact.restitution;
    if (!(e > 0 && e <= 1))
    {
        return;
    }
    const bool hertz =
        settings.contact.law == dem::ContactLawType::hertzMindlin;
    const auto elastic = [](scalar E, scalar nu)
    {
        return E > 0 && nu > -1 && nu <= 0.5;
    };
    if
    (
        hertz
     && (
            !elastic
            (
                settings.contact.wallYoungsModulus,
                settings.contact.wallPoissonRatio
            )
         || !(settings.contact.impactSpeed > 0)
        )
    )
    {
        return;
    }
    for (const auto& c : settings.classes)
    {
        if
        (
            !(c.diameter > 0) || !(c.density > 0)
         || (hertz && !elastic(c.youngsModulus, c.poissonRatio))
        )
        {
            return;
        }
    }

    // Eq. 7's bound lets a dense bed blow up; the measured bounds are in
    // t_c, the contact duration of a pair of the lightest class
    const scalar dt = settings.dt;
    const scalar tc = dem::pairContactTime(settings);
    const scalar safe = dem::safeTimeStep(settings);
    const scalar stable = dem::stableTimeStep(settings);
    if (dt > stable)
    {
        FatalIOErrorInFunction(dict_)
            << "DEM step 'deltaT' = " << dt << " s in " << dict_.name()
            << " is above the stable bound " << stable << " s (" << stable/tc
            << " t_c, t_c = " << tc << " s the contact time of two "
            << settings.classes[smallestClass(settings)].name.c_str()
            << " particles): a"
            << " settling bed does not come to rest and overlaps grow"
            << " (docs/theory/numerics.md, \"The DEM step's bound\"; eq. 7's "
            << dem::timeStepBound(settings) << " s is not safe). Allowed"
            << " range (0, " << stable << "] s; accurate up to " << safe
            << " s" << exit(FatalIOError);
    }
    if (dt > safe)
    {
        WarningInFunction
            << "DEM step 'deltaT' = " << dt << " s in " << dict_.name()
            << " is above the safe bound " << safe << " s (t_c/10): stable,"
            << " but restitution and overlaps of head-on contacts are off by"
            << " more than 1 % (docs/theory/numerics.md, \"The DEM step's bound\");"
            << " a step of at most " << safe << " s is accurate" << endl;
    }
    // Near the dashpot's own bound, or a Hertz impactSpeed below the bed's
    // speed scale (the DEM refuses what is beyond)
    for (const std::string& warning : dem::settingsWarnings(settings))
    {
        WarningInFunction
            << warning.c_str() << " (" << dict_.name() << ")" << endl;
    }
}


// ************************************************************************* //
