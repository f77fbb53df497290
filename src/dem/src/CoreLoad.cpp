// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The cores others left free, from the kernel's accounting (CoreLoad.hpp).

#include "dem/CoreLoad.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <limits>

#ifdef __linux__
#include <sched.h>
#include <time.h>
#include <unistd.h>
#endif

namespace dem {

CoreLoad::CoreLoad()
{
#ifdef __linux__
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) != 0) return;
    for (int c = 0; c < 1024 && c < CPU_SETSIZE; ++c) {
        if (CPU_ISSET(c, &set)) {
            mask_[c / 64] |= std::uint64_t{1} << (c % 64);
            ++cores_;
        }
    }
    valid_ = cores_ > 0 && read(start_);
#endif
}

bool CoreLoad::read(Counters& c) const
{
#ifdef __linux__
    if (cores_ == 0) return false;
    std::FILE* f = std::fopen("/proc/stat", "r");
    if (!f) return false;
    const double tick = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
    char line[512];
    int seen = 0;
    double busy = 0.0;
    while (std::fgets(line, sizeof line, f)) {
        int cpu = -1;
        // user nice system idle iowait irq softirq steal (guest time is inside user's)
        unsigned long long t[8] = {};
        if (std::strncmp(line, "cpu", 3) != 0 || line[3] < '0' || line[3] > '9') continue;
        if (std::sscanf(line, "cpu%d %llu %llu %llu %llu %llu %llu %llu %llu", &cpu, &t[0],
                        &t[1], &t[2], &t[3], &t[4], &t[5], &t[6], &t[7]) < 8) {
            continue;
        }
        if (cpu < 0 || cpu >= 1024 || !(mask_[cpu / 64] >> (cpu % 64) & 1u)) continue;
        const double b = static_cast<double>(t[0] + t[1] + t[2] + t[5] + t[6] + t[7]);
        busy += b * tick;
        ++seen;
    }
    std::fclose(f);
    if (seen != cores_) return false;   // a core of the mask went offline: no reading
    timespec own{};
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &own) != 0) return false;
    c.busy = busy;
    c.own = static_cast<double>(own.tv_sec) + 1e-9 * static_cast<double>(own.tv_nsec);
    c.wall = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
                 .count();
    return true;
#else
    (void)c;
    return false;
#endif
}

double CoreLoad::freeCores()
{
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    if (!valid_) return unknown;
    Counters now;
    if (!read(now)) return unknown;
    if (now.wall - start_.wall < minWindow) return unknown;
    const double free = freeBetween(start_, now, cores_);
    start_ = now;
    return free;
}

double CoreLoad::freeBetween(const Counters& from, const Counters& to, int cores)
{
    // What the mask's cores did that was not this process's: the others' share
    const double others = (to.busy - from.busy) - (to.own - from.own);
    const double n = static_cast<double>(cores);
    return std::clamp(n - others / (to.wall - from.wall), 0.0, n);
}

} // namespace dem
