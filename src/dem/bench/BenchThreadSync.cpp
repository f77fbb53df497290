// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// What one synchronisation of the DEM's threads costs on this host: an empty parallel
// region (a fork and a join, as each of a step's loops opens) and a barrier inside one (as
// between the pair groups' phases). A slab DEM step opens three regions with two barriers
// in one, so their cost against a step's work (BM_FluidizedSlab's time per DEM step on one
// thread) bounds what a second thread can gain. Run with and without
// OMP_WAIT_POLICY=passive: threads that sleep at a barrier wake later than threads that spin.

#include <benchmark/benchmark.h>

#include <omp.h>

namespace {

/// Argument: threads. Time per empty parallel region.
void BM_ParallelRegion(benchmark::State& state)
{
    const int threads = static_cast<int>(state.range(0));
    int sum = 0;
    for (auto _ : state) {
#pragma omp parallel num_threads(threads) reduction(+ : sum)
        sum += omp_get_thread_num();
    }
    benchmark::DoNotOptimize(sum);
    state.counters["time_per_sync"] = benchmark::Counter(
        static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ParallelRegion)->Arg(1)->Arg(2)->UseRealTime();

/// Argument: threads. Time per barrier, 1000 barriers in one region per iteration.
void BM_Barrier(benchmark::State& state)
{
    const int threads = static_cast<int>(state.range(0));
    constexpr int barriers = 1000;
    for (auto _ : state) {
#pragma omp parallel num_threads(threads)
        {
            for (int k = 0; k < barriers; ++k) {
#pragma omp barrier
            }
        }
    }
    state.counters["time_per_sync"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * barriers,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Barrier)->Arg(1)->Arg(2)->UseRealTime();

} // namespace
