// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the slab mode's DEM: a settled binary bed of 1500 small and 500 large
// spheres in a slab 0.05 m wide and 15 mm deep (Goldschmidt's depth, 6 large diameters),
// dt = 1e-5 s, at rest, 1 and 2 threads: particle-steps per second, to set beside
// BM_SettledBed's discs. The bed is packed and settled once and cached in
// $DEM_BENCH_SLAB_STATE (default /tmp/demBench-slabBed.state).

#include "BenchBeds.hpp"
#include "dem/SlabSystem.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <string>

namespace {

using demBench::slabSettings;

std::unique_ptr<dem::SlabSystem> settledSlab(int threads)
{
    const std::string path = demBench::settledSlabPath();
    auto sim = std::make_unique<dem::SlabSystem>(slabSettings(threads));
    try {
        sim->load(path);
        return sim;
    } catch (const dem::Error&) {
        // No usable cache: make the bed.
    }
    dem::SlabSystem fresh(slabSettings(1));   // the same bits as 2 threads
    fresh.packRandom({1500, 500}, {0.0, 0.05, 0.0, 0.06}, 2012);
    fresh.settle(0.5, 1e-12);
    fresh.save(path);
    sim->load(path);
    return sim;
}

void BM_SlabBed(benchmark::State& state)
{
    auto sim = settledSlab(static_cast<int>(state.range(0)));
    const std::size_t n = sim->particles().size();
    const std::int64_t builds0 = sim->neighbourListBuilds();
    const std::int64_t steps0 = sim->stepCount();
    for (auto _ : state) {
        sim->advance(1e-4);   // one CFD step = 10 DEM steps
    }
    const double steps = static_cast<double>(sim->stepCount() - steps0);
    state.counters["particle_steps_per_s"] =
        benchmark::Counter(static_cast<double>(n) * steps, benchmark::Counter::kIsRate);
    state.counters["steps_per_list_build"] =
        steps / static_cast<double>(std::max<std::int64_t>(1, sim->neighbourListBuilds() - builds0));
    state.counters["contacts_per_particle"] =
        static_cast<double>(sim->contactCount()) / static_cast<double>(n);
}

} // namespace

BENCHMARK(BM_SlabBed)
    ->ArgNames({"threads"})
    ->Args({1})->Args({2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(500)
    ->UseRealTime();
