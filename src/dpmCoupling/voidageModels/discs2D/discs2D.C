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

#include "discs2D.H"
#include "fluidization.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidageModels
{
    defineTypeNameAndDebug(discs2D, 0);
    addToRunTimeSelectionTable(voidageModel, discs2D, grid);
}
}


Foam::voidageModels::discs2D::discs2D
(
    const dictionary& dict,
    const gasGrid& grid,
    const scalar voidageMin
)
:
    voidageModel(grid, voidageMin)
{
    requireOneCellThick(dict);
}


Foam::scalar Foam::voidageModels::discs2D::densestFraction
(
    const scalar d
) const
{
    // Hexagonal discs fill pi/(2 sqrt 3) of the plane, each the volume
    // (2/3) d of its area through the depth
    return constant::mathematical::pi/(3*sqrt(3.0))*d/grid_.depth();
}


Foam::string Foam::voidageModels::discs2D::description() const
{
    return
        "voidage model discs2D (the paper's): disc-area fraction of the"
        " cells, Hoomans' 2D-to-3D map, bounded by voidageMin";
}


void Foam::voidageModels::discs2D::updateOverlaps
(
    const label n,
    const double* x,
    const double* y,
    const double*,
    const double* d,
    const label nThreads
)
{
    // The costly part (segment areas): on the DEM's threads
    grid_.discShares(n, x, y, d, nThreads, shares_);
}


void Foam::voidageModels::discs2D::updateFields
(
    const label n,
    const double* d,
    scalarField& voidage,
    scalarField& phiP
)
{
    const scalarField& cellArea = grid_.cellAreas();
    const scalarField& Vc = grid_.cellVolumes();
    const label S = shares_.stride;
    const labelList& counts = shares_.counts;
    const labelList& cells = shares_.cells;
    const scalarList& fractions = shares_.weights;

    porosity2D_.setSize(voidage.size());
    porosity2D_ = 1;
    phiP = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar r = 0.5*d[i];
        const scalar discArea = constant::mathematical::pi*r*r;
        // 3 V_p, the sphere's volume of the disc's diameter
        const scalar threeVp = discArea*4*r;
        for (label k = S*i; k < S*i + counts[i]; ++k)
        {
            const label c = cells[k];
            porosity2D_[c] -= fractions[k]*discArea/cellArea[c];
            phiP[c] += threeVp/(3*Vc[c])*fractions[k];
        }
    }

    forAll(voidage, c)
    {
        voidage[c] =
            max(fluidization::voidage3D(porosity2D_[c]), voidageMin_);
    }
}


Foam::Pair<Foam::scalar> Foam::voidageModels::discs2D::amounts
(
    const label n,
    const double* d,
    const scalarField&
) const
{
    scalar particleArea = 0;
    for (label i = 0; i < n; ++i)
    {
        particleArea += constant::mathematical::pi*d[i]*d[i]/4;
    }
    return Pair<scalar>
    (
        particleArea, gSum((1 - porosity2D_)*grid_.cellAreas())
    );
}


// ************************************************************************* //
