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
    const cartesianGrid& grid,
    const scalar voidageMin
)
:
    voidageModel(grid, voidageMin)
{
    requireOneCellThick(dict);
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
    storeOverlaps
    (
        n, d, nThreads,
        [this, x, y](const label i, const scalar r, const auto& op)
        {
            grid_.forEachDiscOverlap(x[i], y[i], r, op);
        },
        [](const scalar r) { return constant::mathematical::pi*r*r; }
    );
}


void Foam::voidageModels::discs2D::updateFields
(
    const label n,
    const double* d,
    scalarField& voidage,
    scalarField& phiP
)
{
    const scalar cellArea = grid_.dx()*grid_.dy();
    const scalar Vc = grid_.cellVolume();

    porosity2D_.setSize(voidage.size());
    porosity2D_ = 1;
    phiP = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar r = 0.5*d[i];
        const scalar discArea = constant::mathematical::pi*r*r;
        const scalar VpByVc = discArea*4*r/(3*Vc);
        for (label k = stride_*i; k < stride_*i + counts_[i]; ++k)
        {
            const label c = cells_[k];
            porosity2D_[c] -= fractions_[k]*discArea/cellArea;
            phiP[c] += VpByVc*fractions_[k];
        }
    }

    forAll(voidage, c)
    {
        voidage[c] =
            max(fluidization::voidage3D(porosity2D_[c]), voidageMin_);
    }
}


void Foam::voidageModels::discs2D::reportBalance
(
    Ostream& os,
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
    const scalar mappedArea = gSum(1 - porosity2D_)*grid_.dx()*grid_.dy();

    os  << "Exchange: particle area " << particleArea
        << " m2, mapped to cells " << mappedArea << " m2" << endl;
}


// ************************************************************************* //
