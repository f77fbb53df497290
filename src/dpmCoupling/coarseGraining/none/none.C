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

#include "none.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coarseGrainings
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(coarseGraining, none, grid);
}
}


Foam::coarseGrainings::none::none
(
    const dictionary& dict,
    const gasGrid& grid
)
:
    coarseGraining(grid)
{
    // Coefficients of a model not selected: said, not ignored silently
    if (dict.found("diffusionCoeffs"))
    {
        WarningInFunction
            << dict.name() << ": diffusionCoeffs is not used: coarseGraining"
            << " is none (select coarseGraining diffusion for it, or remove"
            << " the entry)" << endl;
    }
}


Foam::string Foam::coarseGrainings::none::description() const
{
    return
        "coarse graining none: each particle's volume and reaction in the"
        " cells it overlaps";
}


// ************************************************************************* //
