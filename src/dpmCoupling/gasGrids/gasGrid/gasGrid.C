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

#include "gasGrid.H"

namespace Foam
{
    defineTypeNameAndDebug(gasGrid, 0);
    defineRunTimeSelectionTable(gasGrid, mesh);
}


Foam::gasGrid::gasGrid(const fvMesh& mesh)
:
    mesh_(mesh),
    bounds_(mesh.bounds())
{}


// ************************************************************************* //
