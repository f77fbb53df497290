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

#include "gasProperties.H"
#include "positiveEntry.H"
#include "knownEntries.H"
#include "particlePropertiesEntries.H"
#include "Time.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

const Foam::wordList& Foam::gasProperties::entries()
{
    static const wordList names
    {
        "operatingPressure", "densityAtOneBar", "viscosity", "U0", "U0byUmf",
        "excessVelocity", "inletPatch"
    };
    return names;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

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
    U0_(-1),
    U0byUmf_(-1),
    excessVelocity_(-1),
    inletPatch_(lookupOrDefault<word>("inletPatch", "inlet"))
{
    checkKnownEntries
    (
        *this, entries(), "constant/gasProperties",
        settingsEntries(obr.time()),
        "and the entries of the settings files that the case's"
        " dictionaries #include",
        {
            {
                "constant/particleProperties (its top level)",
                particlePropertiesEntries::top()
            },
            {
                "constant/particleProperties/contact",
                particlePropertiesEntries::contact()
            }
        }
    );

    const bool byVelocity = found("U0");
    const bool byRatio = found("U0byUmf");
    const bool byExcess = found("excessVelocity");
    wordList given;
    if (byVelocity) given.append("U0");
    if (byRatio) given.append("U0byUmf");
    if (byExcess) given.append("excessVelocity");
    if (given.size() != 1)
    {
        string has("none");
        if (given.size() == 2)
        {
            has = given[0] + " and " + given[1];
        }
        else if (given.size() == 3)
        {
            has = given[0] + ", " + given[1] + " and " + given[2];
        }
        FatalIOErrorInFunction(*this)
            << name() << " needs exactly one of the entries 'U0' (the"
            << " superficial velocity in m/s, in (0, inf)), 'U0byUmf' (U0/Umf,"
            << " in (0, inf)) and 'excessVelocity' (U0 - Umf in m/s, in"
            << " (0, inf)); it has " << has.c_str() << exit(FatalIOError);
    }
    if (byVelocity)
    {
        U0_ = positiveEntry(*this, "U0");
    }
    else if (byRatio)
    {
        U0byUmf_ = positiveEntry(*this, "U0byUmf");
    }
    else
    {
        excessVelocity_ = positiveEntry(*this, "excessVelocity");
    }
}


Foam::string Foam::gasProperties::U0Setting() const
{
    OStringStream os;
    os.precision(Sout.precision());     // as the log prints the other numbers
    if (U0_ > 0)
    {
        os  << "U0 " << U0_ << " m/s";
    }
    else if (U0byUmf_ > 0)
    {
        os  << "U0/Umf " << U0byUmf_;
    }
    else
    {
        os  << "U0 - Umf " << excessVelocity_ << " m/s";
    }
    return os.str();
}
