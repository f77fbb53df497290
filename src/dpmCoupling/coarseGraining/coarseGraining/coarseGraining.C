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

#include "coarseGraining.H"

namespace Foam
{
    defineTypeNameAndDebug(coarseGraining, 0);
    defineRunTimeSelectionTable(coarseGraining, grid);
}


Foam::coarseGraining::coarseGraining(const gasGrid& grid)
:
    grid_(grid)
{}


void Foam::coarseGraining::smooth(vectorField& f) const
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        scalarField component(f.component(d));
        smooth(component);
        f.replace(d, component);
    }
}


// ************************************************************************* //
