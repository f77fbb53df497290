#include "gasProperties.H"
#include "positiveEntry.H"
#include "Time.H"

Foam::gasProperties::gasProperties(const objectRegistry& obr)
:
    IOdictionary
    (
        IOobject
        (
            "gasProperties",
            obr.time().constant(),
            obr,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    operatingPressure_(positiveEntry(*this, "operatingPressure")),
    densityAtOneBar_(positiveEntry(*this, "densityAtOneBar", 1.204)),
    mu_(positiveEntry(*this, "viscosity", 1.75e-5)),
    U0byUmf_(positiveEntry(*this, "U0byUmf")),
    inletPatch_(lookupOrDefault<word>("inletPatch", "inlet"))
{}
