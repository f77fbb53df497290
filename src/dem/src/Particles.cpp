#include "dem/Particles.hpp"

namespace dem {

void Particles::append(int cls, double diam, double density, double px, double py,
                       double pvx, double pvy, double pomega)
{
    constexpr double pi = 3.14159265358979323846;
    const double m = density * pi * diam * diam * diam / 6.0;
    x.push_back(px);
    y.push_back(py);
    vx.push_back(pvx);
    vy.push_back(pvy);
    omega.push_back(pomega);
    radius.push_back(0.5 * diam);
    diameter.push_back(diam);
    mass.push_back(m);
    invMass.push_back(1.0 / m);
    invInertia.push_back(10.0 / (m * diam * diam));   // I = m d^2/10, a solid sphere
    classIndex.push_back(cls);
    id.push_back(static_cast<std::int64_t>(id.size()));
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
