// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the DEM on the paper's bed fluidized, as the solver sees it: contacts that open
// and close, the neighbour list rebuilt every few steps, particles renumbered by cell every
// 200 steps. Figures go to docs/performance.md.
//
// No gas is solved: a drag K = m g / u (u = 0.5 m/s) towards a gas velocity that varies
// across the bed and in time,
//   u_y = u (1 + A (cos(2 pi x/W) cos(2 pi f t) + cos(4 pi x/W) sin(2 pi f t))) below
//   y = H, half of that above,
// A = 0.5, f = 2 Hz, H = 0.2 m, holds the bed's weight on average and keeps it circulating
// (columns of particles rise and fall in turn); above H the particles fall back (the
// solver's bed stays dense because its drag falls as the bed expands). The fluidized state is made once from the settled
// bed (0.3 s of this forcing) and cached next to it ($DEM_BENCH_STATE + ".fluidized").

#include "BenchBeds.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>

namespace {

constexpr double dtCfd = 1e-4;        // the solver's CFD step: 10 DEM steps
constexpr long sortEvery = 20;        // CFD steps between sortByCell, as the solver
constexpr double warmUp = 0.3;        // s of forcing from the settled bed
constexpr double bedTop = 0.2;        // m, H above

/// One CFD step as the solver does it: renumber now and then, set the inputs, advance.
void cfdStep(dem::Simulation& sim, long cfdStepIndex)
{
    if (cfdStepIndex % sortEvery == 0) sim.sortByCell();
    demBench::setGas(sim, bedTop);
    sim.advance(dtCfd);
}

std::unique_ptr<dem::Simulation> fluidizedBed(int threads, bool measured)
{
    dem::Settings settings = demBench::bedSettings(threads);
    settings.measureThreads = measured;
    const std::string path = demBench::settledStatePath() + ".fluidized";
    return demBench::cached(path, settings, [] {
        auto fresh = demBench::settledBed(2);
        const long steps = std::lround(warmUp / dtCfd);
        for (long k = 0; k < steps; ++k) cfdStep(*fresh, k);
        return fresh;
    });
}

/// Arguments: threads, and whether one thread or all is measured per CFD step
/// (Settings::measureThreads). 500 CFD steps (0.05 s) from the cached fluidized state; the
/// renumbering and the inputs (the solver's coupling) are not timed.
void BM_FluidizedBed(benchmark::State& state)
{
    const int threads = static_cast<int>(state.range(0));
    auto sim = fluidizedBed(threads, state.range(1) != 0);
    const std::size_t n = sim->size();
    const std::int64_t builds0 = sim->neighbourListBuilds();
    const std::int64_t steps0 = sim->stepCount();
    long k = 0;
    std::size_t contacts = 0;
    for (auto _ : state) {
        state.PauseTiming();
        if (k % sortEvery == 0) sim->sortByCell();
        demBench::setGas(*sim, bedTop);
        state.ResumeTiming();
        sim->advance(dtCfd);
        contacts += sim->contactCount();
        ++k;
    }
    demBench::countStepsAndBuilds(state, *sim, steps0, builds0);
    state.counters["contacts_per_particle"] =
        static_cast<double>(contacts) / static_cast<double>(std::max(1L, k)) / static_cast<double>(n);
}

} // namespace

BENCHMARK(BM_FluidizedBed)
    ->ArgNames({"threads", "measured"})
    ->Args({1, 0})->Args({2, 0})->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(500)
    ->UseRealTime();
