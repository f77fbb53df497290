/*---------------------------------------------------------------------------*\
    dpmCloud: the checks of its settings that go beyond one entry's range
    (unknown entries, gravity, the gas against the particles, threads, the
    particle output interval), and the terminal velocity of a class.
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "gasProperties.H"
#include "caseChecks.H"
#include "knownEntries.H"
#include "particlePropertiesEntries.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpmCloud::checkEntries() const
{
    const string where("constant/particleProperties");

    // The coefficients of every drag model may stand at the top level
    wordHashSet alsoAllowed(settingsEntries(dict_.objectPath(), mesh_.time()));
    for (const word& model : dragModel::dictionaryConstructorTablePtr_->toc())
    {
        alsoAllowed.insert(model + "Coeffs");
    }
    checkKnownEntries
    (
        dict_, particlePropertiesEntries::top(), where, alsoAllowed,
        "and <dragModel>Coeffs, the entries of #included settings files"
        " and of constant/caseSettings"
    );

    for (const entry& e : dict_.subDict("classes"))
    {
        if (e.isDict())
        {
            checkKnownEntries
            (
                e.dict(), particlePropertiesEntries::sizeClass(),
                where + "/classes/" + e.keyword()
            );
        }
    }
    checkKnownEntries
    (
        dict_.subOrEmptyDict("contact"), particlePropertiesEntries::contact(),
        where + "/contact"
    );
    checkKnownEntries
    (
        dict_.subOrEmptyDict("initialBed"),
        particlePropertiesEntries::initialBed(), where + "/initialBed"
    );
}


void Foam::dpmCloud::checkSettings
(
    const gasProperties& gas,
    const startMode mode
) const
{
    // The gas must be lighter than every class, or nothing can fluidize
    // (the Archimedes number of Umf turns negative)
    const scalarList rhoP(classDensities());
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

    if (mode == startMode::postProcess) return;

    caseChecks::threadCount
    (
        dict_, "constant/particleProperties", dem_->settings().nThreads
    );

    if (mode != startMode::run) return;

    // Particle files on the requested times: the run writes one when a
    // step lands on a multiple of writeInterval, so the interval must be
    // a whole number of CFD steps (else the files come at uneven times, or
    // every step when the interval is below the step)
    const scalar dtGas = mesh_.time().deltaTValue();
    const scalar steps = writeInterval_/dtGas;
    const label n = label(std::round(steps));
    if (n < 1 || mag(steps - n) > 1e-6*steps)
    {
        const label below = max(label(std::floor(steps)), 1);
        FatalIOErrorInFunction(dict_)
            << "Entry 'writeInterval' = " << writeInterval_ << " in "
            << "constant/particleProperties is not a whole multiple of the CFD"
            << " step deltaT = " << dtGas << " of system/controlDict: the"
            << " particle files would "
            << (steps < 1 ? "come every CFD step" : "come at uneven times")
            << "; allowed: a multiple of the CFD step, e.g. " << below*dtGas
            << " or " << (below + 1)*dtGas << exit(FatalIOError);
    }
}


bool Foam::dpmCloud::hasParticleStates() const
{
    for (const instant& t : Time::findTimes(mesh_.time().path()))
    {
        if (isFile(stateFile(t.name())))
        {
            return true;
        }
    }
    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dpmCloud::terminalVelocity
(
    const label classi,
    const scalar g
) const
{
    // The slip at which the drag of the case's model on a lone particle
    // (voidage 1) carries its weight less the buoyancy; the drag K(s) s
    // grows with the slip s, so bisect
    const scalar d = dem_->settings().classes[classi].diameter;
    const scalar rhoP = dem_->settings().classes[classi].density;
    const scalar weight =
        (rhoP - rhoGas_)*constant::mathematical::pi*pow3(d)/6*g;
    if (!(weight > 0)) return 0;

    const scalarField voidage(1, 1.0), diameter(1, d);
    particleMixture alone;          // its own diameter is the mixture's
    alone.sauterDiameter = diameter;
    auto drag = [&](const scalar slip)
    {
        scalarField K(1);
        drag_->dragCoefficient(voidage, diameter, scalarField(1, slip), alone, K);
        return K[0]*slip;
    };
    scalar lower = 0, upper = 1;
    while (drag(upper) < weight && upper < 1e6) upper *= 2;
    for (int i = 0; i < 100 && upper - lower > 1e-10*upper; ++i)
    {
        const scalar mid = 0.5*(lower + upper);
        (drag(mid) < weight ? lower : upper) = mid;
    }
    return 0.5*(lower + upper);
}


// ************************************************************************* //
