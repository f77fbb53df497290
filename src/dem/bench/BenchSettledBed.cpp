// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the DEM on the paper's settled bed (6610 small + 1440 large, 0.15 m wide,
// dt = 1e-5 s): particle-steps per second on 1 and 2 threads, at rest and with a uniform
// drag that makes the bed roughly weightless. Figures go to docs/performance.md.
//
// The settled bed is made once (BenchBeds.hpp).

#include "BenchBeds.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>

namespace {

using demBench::settledBed;

/// Arguments: threads, drag (0: none, 1: uniform drag holding the bed's weight at zero slip,
/// u = 0.5 m/s, as in a bed at minimum fluidization; the bed then loosens and its contacts
/// open, so every run starts from the cached settled state and lasts 0.05 s).
void BM_SettledBed(benchmark::State& state)
{
    const int threads = static_cast<int>(state.range(0));
    const bool drag = state.range(1) != 0;
    auto sim = settledBed(threads);
    const std::size_t n = sim->size();
    if (drag) {
        const double u = 0.5;
        for (std::size_t i = 0; i < n; ++i) {
            sim->dragCoefficient()[i] = sim->mass()[i] * 9.81 / u;
            sim->gasVelocityY()[i] = u;
        }
    }
    const std::int64_t builds0 = sim->neighbourListBuilds();
    const std::int64_t steps0 = sim->stepCount();
    for (auto _ : state) {
        sim->advance(1e-4);   // one CFD step = 10 DEM steps
    }
    demBench::countStepsAndBuilds(state, *sim, steps0, builds0);
    state.counters["bytes_per_particle"] = static_cast<double>(sim->memoryBytes()) / static_cast<double>(n);
    state.counters["contacts_per_particle"] = static_cast<double>(sim->contactCount()) / static_cast<double>(n);
}

} // namespace

BENCHMARK(BM_SettledBed)
    ->ArgNames({"threads", "drag"})
    ->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(500)   // 500 CFD steps = 5000 DEM steps = 0.05 s from the settled state
    ->UseRealTime();

BENCHMARK_MAIN();
