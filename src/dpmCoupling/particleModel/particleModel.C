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

#include "particleModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleModel::particleModel
(
    const dictionary& dict,
    const gasGrid& grid,
    const scalar voidageMin
)
:
    voidage_(voidageModel::New(dict, grid, voidageMin)),
    engine_(voidage_->engine()),
    smoothing_(coarseGraining::New(dict, grid))
{
    // The smoothed voidage is 1 - the smoothed volume fraction, which
    // Hoomans' 2D-3D map of discs2D is not
    if (smoothing_->active() && !voidage_->voidageOfFraction())
    {
        FatalIOErrorInFunction(dict)
            << "coarseGraining " << smoothing_->type() << " in "
            << dict.name() << " needs voidageModel slab3D or spheres3D (the"
            << " voidage 1 - the particles' volume fraction); the voidage"
            << " model is " << voidage_->type() << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleModel::selectEngine
(
    dem::Settings& s,
    const gasGrid& grid
) const
{
    if (slab())
    {
        // The spheres' slab runs from z = 0 to its depth
        if (mag(grid.zMin()) > 1e-9*grid.depth())
        {
            FatalErrorInFunction
                << "The gas's mesh spans z from " << grid.zMin() << " to "
                << grid.zMax() << " m; spheres need it from z = 0 (the"
                << " particles' front wall or slab): move the mesh, e.g."
                << " transformPoints -translate '(0 0 " << -grid.zMin()
                << ")'" << exit(FatalError);
        }
        s.dimension = 3;
        s.slabDepth = grid.depth();
    }
}


// ************************************************************************* //
