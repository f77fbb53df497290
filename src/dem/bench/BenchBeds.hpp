#pragma once
// The paper's bed for the benchmarks (6610 small + 1440 large, 0.15 m wide, dt = 1e-5 s),
// packed and settled once and cached in $DEM_BENCH_STATE (default
// /tmp/demBench-settledBed.state).

#include "dem/Facade.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
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

inline std::string settledStatePath()
{
    const char* env = std::getenv("DEM_BENCH_STATE");
    return env ? env : "/tmp/demBench-settledBed.state";
}

/// The settled bed, from the cache or packed and settled anew (about 1 min).
inline std::unique_ptr<dem::Simulation> settledBed(int threads)
{
    auto sim = std::make_unique<dem::Simulation>(bedSettings(threads));
    try {
        sim->load(settledStatePath());
        return sim;
    } catch (const dem::Error&) {
        // No usable cache: make the bed as the paper does.
    }
    auto fresh = std::make_unique<dem::Simulation>(bedSettings(2));
    fresh->packRandom({6610, 1440}, {0.0, 0.15, 0.0, 0.35}, 2012);
    fresh->settle(1.5, 1e-12);   // as the SettledBed test: at rest after ~0.9 s
    fresh->save(settledStatePath());
    sim->load(settledStatePath());
    return sim;
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
