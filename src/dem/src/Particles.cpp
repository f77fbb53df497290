// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/Particles.hpp"

namespace dem {

void Particles::append(int cls, double diam, double density, double px, double py,
                       double pvx, double pvy, double pomega)
{
    x.push_back(px);
    y.push_back(py);
    vx.push_back(pvx);
    vy.push_back(pvy);
    omega.push_back(pomega);
    appendSphereConstants(*this, cls, diam, density);
    for (auto* a : {&fx, &fy, &torque, &fluidX, &fluidY, &dragCoefficient, &gasVx, &gasVy,
                    &extraFx, &extraFy, &meanVx, &meanVy, &meanFluidX, &meanFluidY}) {
        a->push_back(0.0);
    }
    xRef.push_back(px);
    yRef.push_back(py);
}

std::size_t Particles::memoryBytes() const
{
    std::size_t bytes = 0;
    forEachArray([&](const auto& a) { bytes += a.capacity() * sizeof(a[0]); });
    return bytes;
}

} // namespace dem
