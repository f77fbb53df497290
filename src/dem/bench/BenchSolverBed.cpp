// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the DEM on a state saved by the solver (dpmFoam2D's <time>/uniform/dem.state of
// the paper's bubbling bed): its particles, contacts and coupling inputs (drag coefficient,
// gas velocity, extra force) as the solver left them. The inputs stay frozen, so this is
// the solver's DEM for the first few CFD steps and a bed near it after; 500 CFD steps of
// 10 DEM steps, renumbered by cell every 200 DEM steps as the solver does (not timed).
// Skipped unless $DEM_BENCH_SOLVER_STATE names such a state of the paper's particles.

#include "BenchBeds.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

constexpr double dtCfd = 1e-4;
constexpr long sortEvery = 20;   // CFD steps between sortByCell, as the solver

void BM_SolverBed(benchmark::State& state)
{
    const char* path = std::getenv("DEM_BENCH_SOLVER_STATE");
    if (!path) {
        state.SkipWithError("DEM_BENCH_SOLVER_STATE is not set");
        return;
    }
    dem::Settings settings = demBench::bedSettings(static_cast<int>(state.range(0)));
    // The solver's box comes from its mesh, one ulp off the round figures
    settings.box.xMax = std::nextafter(0.15, 1.0);
    settings.box.yMax = std::nextafter(0.9, 0.0);
    // $DEM_BENCH_SKIN (m): another neighbour skin than the default, to find the fastest
    if (const char* skin = std::getenv("DEM_BENCH_SKIN")) settings.neighbourSkin = std::atof(skin);
    auto sim = std::make_unique<dem::Simulation>(settings);
    sim->load(path);
    const std::int64_t builds0 = sim->neighbourListBuilds();
    const std::int64_t steps0 = sim->stepCount();
    long k = 0;
    for (auto _ : state) {
        if (k % sortEvery == 0) {
            state.PauseTiming();
            sim->sortByCell();
            state.ResumeTiming();
        }
        sim->advance(dtCfd);
        ++k;
    }
    demBench::countStepsAndBuilds(state, *sim, steps0, builds0);
}

} // namespace

BENCHMARK(BM_SolverBed)
    ->ArgNames({"threads"})
    ->Arg(1)->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(500)
    ->UseRealTime();
