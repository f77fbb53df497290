// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Particle state as a structure of arrays: the hot loops stream over each quantity.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dem {

/// Appends a sphere's constants of class cls to the arrays of `p` (Particles or
/// SlabParticles): radius, diameter, mass, inverse mass and inertia, class and id.
template <class P> void appendSphereConstants(P& p, int cls, double diam, double density)
{
    constexpr double pi = 3.14159265358979323846;
    const double m = density * pi * diam * diam * diam / 6.0;
    p.radius.push_back(0.5 * diam);
    p.diameter.push_back(diam);
    p.mass.push_back(m);
    p.invMass.push_back(1.0 / m);
    p.invInertia.push_back(10.0 / (m * diam * diam));   // I = m d^2/10, a solid sphere
    p.classIndex.push_back(cls);
    p.id.push_back(static_cast<std::int64_t>(p.id.size()));
}

/// Per-particle arrays, all of length size(), in one numbering (System::sortByCell changes
/// it; `id` stays with the particle).
struct Particles {
    // State
    std::vector<double> x, y;              ///< position, m
    std::vector<double> vx, vy;            ///< velocity, m/s
    std::vector<double> omega;             ///< spin about z, rad/s
    // Constants
    std::vector<double> radius, diameter;  ///< m
    std::vector<double> mass;              ///< kg
    std::vector<double> invMass;           ///< 1/kg
    std::vector<double> invInertia;        ///< 1/(kg m^2), I = m d^2/10
    std::vector<int> classIndex;
    std::vector<std::int64_t> id;
    // Forces of the last evaluation (contacts) and the fluid force of the current velocity
    std::vector<double> fx, fy;            ///< contact force, N
    std::vector<double> torque;            ///< contact torque about z, N m
    std::vector<double> fluidX, fluidY;    ///< fluid force at the current velocity, N
    // Position at the last neighbour-list build (Verlet skin criterion)
    std::vector<double> xRef, yRef;
    // Fluid coupling inputs
    std::vector<double> dragCoefficient;   ///< N s/m
    std::vector<double> gasVx, gasVy;      ///< m/s
    std::vector<double> extraFx, extraFy;  ///< N
    // Sub-step averages of the last CFD step
    std::vector<double> meanVx, meanVy;    ///< m/s
    std::vector<double> meanFluidX, meanFluidY;  ///< N

    std::size_t size() const { return x.size(); }

    /// Appends a particle at rest in all force arrays.
    void append(int cls, double diam, double density, double px, double py,
                double pvx, double pvy, double pomega);

    /// Heap memory, bytes.
    std::size_t memoryBytes() const;

    /// Applies f to every array (save/load), in a fixed order.
    template <class F> void forEachArray(F&& f)
    {
        f(x); f(y); f(vx); f(vy); f(omega);
        f(radius); f(diameter); f(mass); f(invMass); f(invInertia);
        f(classIndex); f(id);
        f(fx); f(fy); f(torque); f(fluidX); f(fluidY); f(xRef); f(yRef);
        f(dragCoefficient); f(gasVx); f(gasVy); f(extraFx); f(extraFy);
        f(meanVx); f(meanVy); f(meanFluidX); f(meanFluidY);
    }
    template <class F> void forEachArray(F&& f) const
    {
        const_cast<Particles*>(this)->forEachArray([&](const auto& a) { f(a); });
    }
};

} // namespace dem
