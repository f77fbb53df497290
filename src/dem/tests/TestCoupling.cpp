// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The fluid-coupling contract of the facade: the mean fluid force of a CFD step is
// K (u - meanVelocity) + extra exactly, and it is the momentum the particle received.

#include "TestHelpers.hpp"

#include <gtest/gtest.h>

using namespace dem;
using namespace dem::test;

TEST(Coupling, MeanFluidForceIsTheImpulseDelivered)
{
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.1});
    s.gravity[1] = -9.81;
    Simulation sim(s);
    sim.addParticle(0, 0.05, 0.05, 0.01, -0.02);
    sim.addParticle(1, 0.02, 0.05, 0.0, 0.0, 3.0);
    for (std::size_t i = 0; i < 2; ++i) {
        sim.dragCoefficient()[i] = sim.mass()[i] / 0.01;
        sim.gasVelocityX()[i] = 0.2;
        sim.gasVelocityY()[i] = 1.0;
        sim.extraForceX()[i] = 1e-6;
        sim.extraForceY()[i] = -2e-6;
    }
    for (int step = 0; step < 5; ++step) {
        const double vx0[2] = {sim.vx()[0], sim.vx()[1]};
        const double vy0[2] = {sim.vy()[0], sim.vy()[1]};
        sim.advance(1e-4);
        for (std::size_t i = 0; i < 2; ++i) {
            const double K = sim.dragCoefficient()[i];
            // Exactly the stated formula.
            EXPECT_EQ(sim.meanFluidForceX()[i], K * (0.2 - sim.meanVelocityX()[i]) + 1e-6);
            EXPECT_EQ(sim.meanFluidForceY()[i], K * (1.0 - sim.meanVelocityY()[i]) - 2e-6);
            // Momentum balance over the CFD step (no contacts): m dv = (F_fluid + m g) dt.
            const double m = sim.mass()[i];
            EXPECT_NEAR(m * (sim.vx()[i] - vx0[i]), 1e-4 * sim.meanFluidForceX()[i], 1e-15);
            EXPECT_NEAR(m * (sim.vy()[i] - vy0[i]), 1e-4 * (sim.meanFluidForceY()[i] - m * 9.81), 1e-15);
        }
    }
}

TEST(Coupling, WeightlessParticleStaysPut)
{
    // Drag balancing gravity at zero slip: K u = m g, particle at rest, gas at u.
    Settings s = paperSettings({0.0, 0.1, 0.0, 0.1});
    s.gravity[1] = -9.81;
    Simulation sim(s);
    sim.addParticle(1, 0.05, 0.05);
    const double u = 0.5;
    sim.dragCoefficient()[0] = sim.mass()[0] * 9.81 / u;
    sim.gasVelocityY()[0] = u;
    for (int k = 0; k < 100; ++k) sim.advance(1e-4);
    EXPECT_NEAR(sim.vy()[0], 0.0, 1e-15);
    EXPECT_NEAR(sim.y()[0], 0.05, 1e-15);
}
