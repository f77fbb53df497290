// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The cores the rest of the machine leaves free (CoreLoad): a process spinning beside this
// one takes a core, this process's own threads do not, and the arithmetic of a window.

#include "dem/CoreLoad.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include <time.h>

#ifdef __linux__
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#endif

using namespace dem;

namespace {

void spinFor(double seconds)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    volatile double x = 1.0;
    while (std::chrono::steady_clock::now() < end) x = x * 1.0000001 + 1e-9;
}

} // namespace

TEST(CoreLoad, AWindowsArithmetic)
{
    // 2 cores for 1 s: 1.5 core-seconds busy, 1.0 of them this process's: others took half
    // a core, 1.5 were free. Others' share above the mask clamps to 0 free.
    const CoreLoad::Counters from{10.0, 3.0, 100.0}, to{11.5, 4.0, 101.0};
    EXPECT_DOUBLE_EQ(CoreLoad::freeBetween(from, to, 2), 1.5);
    const CoreLoad::Counters busier{13.0, 3.0, 101.0};
    EXPECT_DOUBLE_EQ(CoreLoad::freeBetween(from, busier, 2), 0.0);
}

#ifdef __linux__
TEST(CoreLoad, AProcessSpinningBesideTakesACore)
{
    CoreLoad load;
    if (load.cores() == 0) GTEST_SKIP() << "no affinity mask or /proc/stat to read";
    EXPECT_TRUE(std::isnan(load.freeCores())) << "a window shorter than minWindow is read";
    CoreLoad fresh;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        spinFor(0.6);
        _exit(0);
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(0.5));
    const double free = fresh.freeCores();
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    // The child's core at least (others may take more, never less)
    ASSERT_FALSE(std::isnan(free));
    EXPECT_LE(free, load.cores() - 0.8);
}

TEST(CoreLoad, ThisProcesssOwnThreadsAreNotOthers)
{
    CoreLoad load;
    if (load.cores() == 0) GTEST_SKIP() << "no affinity mask or /proc/stat to read";
    CoreLoad::Counters from, to;
    ASSERT_TRUE(load.read(from));
    // Another thread of this process spins for 0.3 s of its own CPU time (on a loaded
    // machine that takes longer on the wall)
    std::thread spinner([] {
        timespec t{};
        double spent = 0.0;
        volatile double x = 1.0;
        while (spent < 0.3) {
            for (int k = 0; k < 100000; ++k) x = x * 1.0000001 + 1e-9;
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
            spent = static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
        }
    });
    spinner.join();
    ASSERT_TRUE(load.read(to));
    // The process's own time holds every thread's, and the mask's busy time holds it (the
    // kernel's ticks of 10 ms: within a few); the others' share is what is left
    EXPECT_GE(to.own - from.own, 0.3);
    EXPECT_GE(to.busy - from.busy, 0.8 * (to.own - from.own));
}
#endif
