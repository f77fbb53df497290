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

#include "slab3D.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace voidageModels
{
    defineTypeNameAndDebug(slab3D, 0);
    addToRunTimeSelectionTable(voidageModel, slab3D, grid);
}
}


Foam::voidageModels::slab3D::slab3D
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


Foam::voidageModels::slab3D::slab3D
(
    const gasGrid& grid,
    const scalar voidageMin
)
:
    voidageModel(grid, voidageMin)
{}


Foam::scalar Foam::voidageModels::slab3D::densestFraction
(
    const scalar
) const
{
    // Spheres in face-centred cubic packing
    return constant::mathematical::pi/(3*sqrt(2.0));
}


Foam::string Foam::voidageModels::slab3D::description() const
{
    OStringStream os;
    os  << "voidage model slab3D: spheres in a slab " << grid_.depth()
        << " m deep (the mesh's thickness), eps = 1 - (sphere volume in the"
        << " cell column)/(cell volume), used as it is";
    return os.str();
}


void Foam::voidageModels::slab3D::report(Ostream& os) const
{
    os  << "    slab mode: 3D spheres between walls z = 0 and z = "
        << grid_.depth() << " m (the mesh's thickness); gas velocity z = 0"
        << endl;
}


void Foam::voidageModels::slab3D::checkDiameters
(
    const dictionary& dict,
    const wordList& classNames,
    const scalarList& diameters
) const
{
    voidageModel::checkDiameters(dict, classNames, diameters);
    const scalar depth = grid_.depth();
    for (const scalar d : diameters)
    {
        if (!(d < depth))
        {
            FatalIOErrorInFunction(dict)
                << "voidageModel " << type() << " in " << dict.name()
                << ": particles of diameter " << d << " m do not fit in the"
                << " slab, whose depth is the mesh's thickness " << depth
                << " m (system/bedGeometry depth); each class's 'diameter'"
                << " must be less than the depth" << exit(FatalIOError);
        }
    }
}


void Foam::voidageModels::slab3D::updateOverlaps
(
    const label n,
    const double* x,
    const double* y,
    const double*,
    const double* d,
    const label nThreads
)
{
    grid_.sphereColumnShares(n, x, y, d, nThreads, shares_);
}


void Foam::voidageModels::slab3D::updateFields
(
    const label n,
    const double* d,
    scalarField& voidage,
    scalarField& phiP
)
{
    const scalarField& Vc = grid_.cellVolumes();
    const label S = shares_.stride;
    const labelList& counts = shares_.counts;
    const labelList& cells = shares_.cells;
    const scalarList& fractions = shares_.weights;

    phiP = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar r = 0.5*d[i];
        const scalar threeVp = 4*constant::mathematical::pi*r*r*r;
        for (label k = S*i; k < S*i + counts[i]; ++k)
        {
            const label c = cells[k];
            phiP[c] += threeVp/(3*Vc[c])*fractions[k];
        }
    }

    forAll(voidage, c)
    {
        voidage[c] = max(1 - phiP[c], voidageMin_);
    }
}


Foam::Pair<Foam::scalar> Foam::voidageModels::slab3D::amounts
(
    const label n,
    const double* d,
    const scalarField& phiP
) const
{
    scalar particleVolume = 0;
    for (label i = 0; i < n; ++i)
    {
        particleVolume += constant::mathematical::pi*d[i]*d[i]*d[i]/6;
    }
    return Pair<scalar>(particleVolume, gSum(phiP*grid_.cellVolumes()));
}


// ************************************************************************* //
