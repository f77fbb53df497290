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
    exchangeBalance function object: see exchangeBalance.H
\*---------------------------------------------------------------------------*/

#include "exchangeBalance.H"
#include "cloudFunctionObject.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(exchangeBalance, 0);
    addToRunTimeSelectionTable(functionObject, exchangeBalance, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::exchangeBalance::exchangeBalance
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, true),
    dict_(dict),
    cloudName_("particles")
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::exchangeBalance::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    static const wordList known{"cloud"};
    static const wordHashSet common(cloudFunctionObject::commonEntries(true));
    checkKnownEntries
    (
        dict, known,
        "function object '" + name() + "' (type exchangeBalance)", common,
        "and those of every function object: type libs writeControl"
        " writeInterval timeStart timeEnd log writePrecision ..."
    );
    cloudName_ = dict.lookupOrDefault<word>("cloud", "particles");
    return true;
}


bool Foam::functionObjects::exchangeBalance::execute()
{
    return true;
}


bool Foam::functionObjects::exchangeBalance::write()
{
    if (functionObject::postProcess || !writeToFile())
    {
        return true;
    }
    const dpmCloud& particles =
        cloudFunctionObject::find(mesh_, cloudName_, dict_);
    const gasParticleExchange::balanceSums b = particles.balance();

    if (!file_.valid())
    {
        caseChecks::writesInsideCase
        (
            baseTimeDir(), time_.path(), "exchangeBalance", dict_
        );
        file_ = createFile("exchangeBalance");
        OFstream& os = file_();
        writeHeader
        (
            os,
            "The gas-particle exchange of the last step: the force on the"
            " particles against the reaction the gas cells carry, the"
            " particles' amount against the one mapped to the cells, and"
            " their drag coefficients (kg/s) against the gas's implicit share"
        );
        writeHeaderValue
        (
            os, "amount", word(b.amountName + " (" + b.unit() + ")")
        );
        writeCommented(os, "Time");
        for (const char* column :
        {
            "particleForce_x", "particleForce_y", "particleForce_z",
            "gasForce_x", "gasForce_y", "gasForce_z", "relativeExcess",
            "particleAmount", "mappedAmount", "particleDrag", "gasDrag"
        })
        {
            writeTabbed(os, column);
        }
        os  << endl;
    }

    const scalar excess =
        mag(b.gasForce - b.particleForce)/max(mag(b.particleForce), VSMALL);
    OFstream& os = file_();
    os  << setw(charWidth()) << time_.timeName();
    for (const scalar v :
    {
        b.particleForce.x(), b.particleForce.y(), b.particleForce.z(),
        b.gasForce.x(), b.gasForce.y(), b.gasForce.z(), excess,
        b.particleAmount, b.mappedAmount, b.particleDrag, b.gasDrag
    })
    {
        os  << tab << setw(charWidth()) << v;
    }
    os  << endl;
    return true;
}


// ************************************************************************* //
