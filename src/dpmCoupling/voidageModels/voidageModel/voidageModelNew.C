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

#include "voidageModel.H"
#include "choiceEntry.H"

Foam::autoPtr<Foam::voidageModel> Foam::voidageModel::New
(
    const dictionary& dict,
    const gasGrid& grid,
    const scalar voidageMin
)
{
    const word choice = choiceEntry
    (
        dict, "voidageModel", gridConstructorTablePtr_->sortedToc(), "discs2D",
        "discs2D (disc-area fraction and Hoomans' 3D voidage, the paper's,"
        " default), slab3D (sphere volume in the cell column of a slab one"
        " cell thick) or spheres3D (sphere volume in the cells of a gas"
        " resolved in depth)"
    );
    // Another model's coefficients are not read: say so, since the user
    // wrote them for a reason (spheres3DCoeffs under discs2D: no spreading)
    for (const word& other : gridConstructorTablePtr_->sortedToc())
    {
        if (other != choice && dict.found(other + "Coeffs", keyType::LITERAL))
        {
            WarningInFunction
                << "Entry '" << other << "Coeffs' in " << dict.name()
                << " is ignored: voidageModel is " << choice << "; set"
                << " voidageModel " << other << " to use it, or remove it"
                << endl;
        }
    }
    return (*gridConstructorTablePtr_)[choice](dict, grid, voidageMin);
}


// ************************************************************************* //
