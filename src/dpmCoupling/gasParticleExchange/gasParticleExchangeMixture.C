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
    gasParticleExchange: the solids mixture, kept when the drag model needs it (Beetstra):
    the per-class volume fractions of the cells, mapped with the voidage
    model's shares, and the Sauter mean diameter at each particle.
\*---------------------------------------------------------------------------*/

#include "gasParticleExchange.H"
#include "solidsMixture.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasParticleExchange::updateMixture()
{
    const dem::Simulation& dem = engine_.dem();
    const label n = engine_.size();
    const label nCells = mesh_.nCells();
    const scalarField& Vc = grid_.cellVolumes();
    const double* d = dem.diameter();
    const int* cls = dem.classIndex();

    classFraction_.setSize(label(dem.settings().classes.size()));
    forAll(classFraction_, k)
    {
        classFraction_[k].setSize(nCells);
        classFraction_[k] = 0;
    }
    fractionByDiameter_.setSize(nCells);
    fractionByDiameter_ = 0;

    // The same shares as particleFraction_ in updateVoidage
    const labelList& counts = particleModel_.voidage().counts();
    const labelList& cells = particleModel_.voidage().cells();
    const scalarList& fractions = particleModel_.voidage().fractions();
    const label S = particleModel_.voidage().stride();
    for (label i = 0; i < n; ++i)
    {
        solidsMixture::addParticle
        (
            d[i], cls[i], counts[i], &cells[S*i], &fractions[S*i], Vc,
            classFraction_, fractionByDiameter_
        );
    }

    // Smoothed as phiP is, so that the classes still add up to it
    const coarseGraining& smoothing = particleModel_.smoothing();
    if (smoothing.active())
    {
        forAll(classFraction_, k)
        {
            smoothing.smooth(classFraction_[k]);
        }
        smoothing.smooth(fractionByDiameter_);
    }
}


void Foam::gasParticleExchange::interpolateMixture()
{
    // The stencils the gas was interpolated with (interpolateGas)
    const label n = engine_.size();
    const double* d = engine_.dem().diameter();
    const scalarField& phiP = particleFraction_.primitiveField();
    const label S = stencils_.stride;

    scalarField& dMean = mixtureP_.sauterDiameter;
    dMean.setSize(n);
    #pragma omp parallel for num_threads(nThreads_) schedule(static)
    for (label i = 0; i < n; ++i)
    {
        dMean[i] = solidsMixture::sauterDiameter
        (
            stencils_.counts[i], &stencils_.cells[S*i],
            &stencils_.weights[S*i], phiP, fractionByDiameter_, d[i]
        );
    }
}


// ************************************************************************* //
