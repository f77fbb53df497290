// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many of the cores this process may run on the rest of the machine left free, read
// from the kernel's accounting (Linux: /proc/stat's per-core times of the cores in the
// process's affinity mask, less the process's own CPU time). ThreadChooser asks it before a
// trial of all threads: beside a neighbour that keeps a core busy, a trial's calls on all
// threads cost about three times one thread's, and some catch a quiet moment and win, so
// trials alone keep two threads slower than one (by 10-20 % on the 2-core machine).

#include <cstdint>

namespace dem {

class CoreLoad {
public:
    /// A reading shorter than this is not made: /proc/stat counts in ticks of 10 ms, and a
    /// window of 0.25 s on each core is read to within about 4 % of a core.
    static constexpr double minWindow = 0.25;   // s

    /// Starts the first window now.
    CoreLoad();

    /// The cores of the affinity mask that others left free since the last reading, in
    /// cores (0 to cores()): the mask's cores less what other processes (and the hypervisor's
    /// steal) used of them, averaged over the window. NaN while the window is shorter than
    /// minWindow (the window then goes on), or where the kernel's accounting cannot be read.
    double freeCores();

    /// The cores in the affinity mask; 0 where it cannot be read.
    int cores() const { return cores_; }

    /// One reading of the counters: the busy time of the mask's cores, the process's own CPU
    /// time and the wall clock, s; false where they cannot be read.
    struct Counters {
        double busy = 0.0, own = 0.0, wall = 0.0;
    };
    bool read(Counters& c) const;
    /// The cores others left free between two readings, of `cores`: the busy time less the
    /// process's own, over the wall time between them, clamped to [0, cores].
    static double freeBetween(const Counters& from, const Counters& to, int cores);

private:
    int cores_ = 0;
    std::uint64_t mask_[16] = {};   // the affinity mask's first 1024 cores, a bit each
    bool valid_ = false;
    Counters start_;
};

} // namespace dem
