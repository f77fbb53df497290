// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the slab mode's DEM as the solver sees it: BM_SlabBed's slab (1500
// small and 500 large spheres, 0.05 m x 15 mm) fluidized by BM_FluidizedBed's forcing
// (demBench::setGas, H = 0.06 m, four times the settled bed's height), so contacts open and
// close, the list is rebuilt every few steps and the particles are renumbered by cell every
// 20 CFD steps, as dpmCloud does. The fluidized state is made once from the settled slab
// (0.3 s of forcing) and cached next to it ($DEM_BENCH_SLAB_STATE + ".fluidized").
// The counters mean_ke_uJ and mean_y_mm (means over the CFD steps) compare runs whose
// trajectories differ at round-off.

#include "BenchBeds.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

namespace {

constexpr double dtCfd = 1e-4;        // the solver's CFD step: 10 DEM steps
constexpr long sortEvery = 20;        // CFD steps between sortByCell, as the solver
constexpr double warmUp = 0.3;        // s of forcing from the settled slab
constexpr double bedTop = 0.025;      // m, H of the forcing
constexpr double lift = 0.75;         // of the weight, held by the drag on average

std::unique_ptr<dem::Simulation> fluidizedSlab(int threads, bool measured)
{
    dem::Settings settings = demBench::slabSettings(threads);
    settings.measureThreads = measured;
    const std::string path = demBench::settledSlabPath() + ".fluidized";
    return demBench::cached(path, settings, [] {
        // From the settled slab, made as BM_SlabBed does.
        auto fresh = demBench::cached(demBench::settledSlabPath(), demBench::slabSettings(2), [] {
            auto slab = std::make_unique<dem::Simulation>(demBench::slabSettings(1));
            slab->packRandom({1500, 500}, {0.0, 0.05, 0.0, 0.06}, 2012);
            slab->settle(0.5, 1e-12);
            return slab;
        });
        const long steps = std::lround(warmUp / dtCfd);
        for (long k = 0; k < steps; ++k) {
            if (k % sortEvery == 0) fresh->sortByCell();
            demBench::setGas(*fresh, bedTop, lift);
            fresh->advance(dtCfd);
        }
        return fresh;
    });
}

/// Arguments: threads, and whether one thread or all is measured per CFD step
/// (Settings::measureThreads). 500 CFD steps (0.05 s) from the cached fluidized state; the
/// renumbering and the inputs (the solver's coupling) are not timed.
void BM_FluidizedSlab(benchmark::State& state)
{
    const int threads = static_cast<int>(state.range(0));
    auto sim = fluidizedSlab(threads, state.range(1) != 0);
    const std::size_t n = sim->size();
    const std::int64_t builds0 = sim->neighbourListBuilds();
    const std::int64_t steps0 = sim->stepCount();
    long k = 0;
    double contacts = 0.0, ke = 0.0, meanY = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        if (k % sortEvery == 0) sim->sortByCell();
        demBench::setGas(*sim, bedTop, lift);
        state.ResumeTiming();
        sim->advance(dtCfd);
        state.PauseTiming();
        contacts += static_cast<double>(sim->contactCount());
        ke += sim->kineticEnergy();
        const double* y = sim->y();
        double sumY = 0.0;
        for (std::size_t i = 0; i < n; ++i) sumY += y[i];
        meanY += sumY / static_cast<double>(n);
        state.ResumeTiming();
        ++k;
    }
    demBench::countStepsAndBuilds(state, *sim, steps0, builds0);
    const double steps = static_cast<double>(std::max(1L, k));
    state.counters["contacts_per_particle"] = contacts / steps / static_cast<double>(n);
    state.counters["mean_ke_uJ"] = 1e6 * ke / steps;
    state.counters["mean_y_mm"] = 1e3 * meanY / steps;
}

} // namespace

BENCHMARK(BM_FluidizedSlab)
    ->ArgNames({"threads", "measured"})
    ->Args({1, 0})->Args({2, 0})->Args({2, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(500)
    ->UseRealTime();
