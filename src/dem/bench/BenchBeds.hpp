// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's bed for the benchmarks (6610 small + 1440 large, 0.15 m wide, dt = 1e-5 s),
// packed and settled once and cached in $DEM_BENCH_STATE (default
// /tmp/demBench-settledBed.state).

#include "dem/Facade.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <cstdlib>
#include <memory>
#include <string>

namespace demBench {

inline dem::Settings bedSettings(int threads)
{
    dem::Settings s;
    s.classes = {{"small", 1.5e-3, 2525.0}, {"large", 2.5e-3, 2525.0}};
    s.box = {0.0, 0.15, 0.0, 0.9};
    s.dt = 1e-5;
    s.nThreads = threads;
    return s;
}

/// The slab of BM_SlabBed and BM_FluidizedSlab: binary spheres in a slab 0.05 m wide and
/// 15 mm deep (Goldschmidt's depth, 6 large diameters), dt = 1e-5 s.
inline dem::Settings slabSettings(int threads)
{
    dem::Settings s;
    s.classes = {{"small", 1.5e-3, 2525.0}, {"large", 2.5e-3, 2525.0}};
    s.box = {0.0, 0.05, 0.0, 0.3};
    s.dimension = 3;
    s.slabDepth = 0.015;
    s.dt = 1e-5;
    s.nThreads = threads;
    return s;
}

/// The settled slab's cache, $DEM_BENCH_SLAB_STATE (default /tmp/demBench-slabBed.state).
inline std::string settledSlabPath()
{
    const char* env = std::getenv("DEM_BENCH_SLAB_STATE");
    return env ? env : "/tmp/demBench-slabBed.state";
}

inline std::string settledStatePath()
{
    const char* env = std::getenv("DEM_BENCH_STATE");
    return env ? env : "/tmp/demBench-settledBed.state";
}

/// The state cached at `path`, loaded with `settings`; without a usable cache, make()'s
/// simulation saved there first.
template <class Make>
std::unique_ptr<dem::Simulation> cached(const std::string& path, const dem::Settings& settings,
                                        Make&& make)
{
    auto sim = std::make_unique<dem::Simulation>(settings);
    try {
        sim->load(path);
        return sim;
    } catch (const dem::Error&) {
        // No usable cache: make it.
    }
    make()->save(path);
    sim->load(path);
    return sim;
}

/// The settled bed, from the cache or packed and settled anew (about 1 min).
inline std::unique_ptr<dem::Simulation> settledBed(int threads)
{
    return cached(settledStatePath(), bedSettings(threads), [] {
        auto fresh = std::make_unique<dem::Simulation>(bedSettings(2));
        fresh->packRandom({6610, 1440}, {0.0, 0.15, 0.0, 0.35}, 2012);
        fresh->settle(1.5, 1e-12);   // as the SettledBed test: at rest after ~0.9 s
        return fresh;
    });
}

/// The fluidized beds' drag inputs for the CFD step starting at sim.time(): K = m g/u
/// (u = 0.5 m/s) towards a gas velocity
///   u_y = lift u (1 + A (cos(2 pi x/W) cos(2 pi f t) + cos(4 pi x/W) sin(2 pi f t)))
/// below y = top, half of that above, A = 0.5, f = 2 Hz (lift = 1: the drag holds the
/// weight on average).
inline void setGas(dem::Simulation& sim, double top, double lift = 1.0)
{
    constexpr double pi = 3.14159265358979323846;
    const double u = 0.5, a = 0.5, f = 2.0;
    const double width = sim.settings().box.xMax - sim.settings().box.xMin;
    const double wt = 2.0 * pi * f * sim.time();
    const double c = std::cos(wt), s = std::sin(wt);
    const std::size_t n = sim.size();
    const double* x = sim.x();
    const double* y = sim.y();
    const double* m = sim.mass();
    double* K = sim.dragCoefficient();
    double* uy = sim.gasVelocityY();
    for (std::size_t i = 0; i < n; ++i) {
        const double k = 2.0 * pi * x[i] / width;
        K[i] = m[i] * 9.81 / u;
        uy[i] = (y[i] < top ? lift * u : 0.5 * lift * u) * (1.0 + a * (std::cos(k) * c + std::cos(2.0 * k) * s));
    }
}

/// The counters every bed reports: particle-steps per second and DEM steps per list build
/// since (steps0, builds0).
inline void countStepsAndBuilds(benchmark::State& state, const dem::Simulation& sim,
                                std::int64_t steps0, std::int64_t builds0)
{
    const double steps = static_cast<double>(sim.stepCount() - steps0);
    state.counters["particle_steps_per_s"] = benchmark::Counter(
        static_cast<double>(sim.size()) * steps, benchmark::Counter::kIsRate);
    state.counters["steps_per_list_build"] =
        steps / static_cast<double>(std::max<std::int64_t>(1, sim.neighbourListBuilds() - builds0));
    state.counters["skin_mm"] = 1e3 * sim.neighbourSkin();   // at the end (adaptive: varies)
}

} // namespace demBench
