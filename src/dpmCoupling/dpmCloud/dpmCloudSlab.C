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
    dpmCloud in the slab mode (voidageModel slab3D): 3D spheres
    between a front wall z = 0 and a back wall z = depth, the mesh's
    thickness, in a gas one cell thick. The gas has no z component: the
    spheres see u_z = 0 (the drag damps vz), their buoyancy and pressure-
    gradient forces have z = 0, and the gas gets the x-y forces back (the
    rest of dpmCloud reads x-y only). docs/model.md, "The slab mode: the
    cloud in 3D".
\*---------------------------------------------------------------------------*/

#include "dpmCloud.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::dpmCloud::slabGasInputs(scalarField& slip)
{
    const label n = size();
    const double* vx = dem_->vx();
    const double* vy = dem_->vy();
    const double* vz = dem_->vz();
    double* uZ = dem_->gasVelocityZ();
    double* fZ = dem_->extraForceZ();
    for (label i = 0; i < n; ++i)
    {
        uZ[i] = 0;
        fZ[i] = 0;
        if (frozen_) continue;      // slip of particles at rest, as set
        const vector& u = gasVelocityP_[i];
        const scalar sx = u.x() - vx[i];
        const scalar sy = u.y() - vy[i];
        slip[i] = std::sqrt(sx*sx + sy*sy + vz[i]*vz[i]);
    }
}


Foam::scalar Foam::dpmCloud::slabPackHeight
(
    const std::vector<int>& counts
) const
{
    // Random sequential addition jams near a solid fraction of 0.38 in 3D
    // (0.55 for discs, packed at 1/3): the spheres are packed at 1/5
    scalar V = 0;
    forAll(classNames_, k)
    {
        const scalar d = dem_->settings().classes[k].diameter;
        V += counts[k]*constant::mathematical::pi*pow3(d)/6;
    }
    const scalar width = grid_.xMax() - grid_.xMin();
    return 5*V/(width*grid_.depth());
}


void Foam::dpmCloud::addListedSphere
(
    const label classIndex,
    const scalar xyz[3],
    const bool hasZ
)
{
    const dem::Vector3 p{xyz[0], xyz[1], hasZ ? xyz[2] : 0.5*grid_.depth()};
    guarded
    (
        "Cannot place a particle of initialBed/positions (the slab's walls"
        " are z = 0 and z = the mesh's thickness)",
        [&]{ dem_->addParticle(classIndex, p); }
    );
}


void Foam::dpmCloud::reportSlab(Ostream& os) const
{
    os  << "    slab mode: 3D spheres between walls z = 0 and z = "
        << grid_.depth() << " m (the mesh's thickness); gas velocity z = 0"
        << endl;
}


// ************************************************************************* //
