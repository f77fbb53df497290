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

#include "dragModel.H"
#include "knownEntries.H"

Foam::autoPtr<Foam::dragModel> Foam::dragModel::New
(
    const dictionary& dict,
    const scalar rho,
    const scalar mu
)
{
    const word modelType(dict.lookupOrDefault<word>("dragModel", "ErgunWenYu"));

    Info<< "Selecting drag model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "dragModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    // Coefficients of another model are not used: said, not ignored silently
    for (const word& other : dictionaryConstructorTablePtr_->sortedToc())
    {
        if (other != modelType && dict.found(other + "Coeffs"))
        {
            WarningInFunction
                << dict.name() << ": " << other << "Coeffs is not used: the"
                << " dragModel is " << modelType << " (select dragModel "
                << other << " for it, or remove the entry)" << endl;
        }
    }

    const dictionary coeffs(dict.subOrEmptyDict(modelType + "Coeffs"));
    autoPtr<dragModel> model(cstrIter()(coeffs, rho, mu));
    checkKnownEntries
    (
        coeffs, model->coefficientNames(),
        "constant/particleProperties/" + modelType + "Coeffs"
    );
    return model;
}
