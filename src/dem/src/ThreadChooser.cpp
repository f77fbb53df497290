// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The team size chosen by timing (ThreadChooser.hpp).

#include "dem/ThreadChooser.hpp"

#include <algorithm>
#include <numeric>

namespace dem {

namespace {

/// The mean time of a call, the slowest left out: the time a team spends over many calls,
/// where some calls wait for a core (a median would not see them), without the one
/// neighbour-list build or hiccup that may fall into a short trial
double meanWithoutSlowest(std::array<double, ThreadChooser::trialCalls> t)
{
    std::sort(t.begin(), t.end());
    return std::accumulate(t.begin(), t.end() - 1, 0.0) / static_cast<double>(t.size() - 1);
}

} // namespace

ThreadChooser::ThreadChooser(int maxThreads)
    : maxThreads_(std::max(1, maxThreads)), chosen_(maxThreads_)
{
}

int ThreadChooser::next() const
{
    if (maxThreads_ == 1) return 1;
    if (trial_ < trialLength) return trial_ < blockCalls ? 1 : maxThreads_;
    return chosen_;
}

void ThreadChooser::record(double seconds)
{
    const int team = next();
    ++calls_[team == 1 ? 0 : 1];
    if (maxThreads_ == 1) return;
    if (trial_ >= trialLength) {
        if (--heldLeft_ <= 0) trial_ = 0;
        return;
    }
    const int inBlock = trial_ % blockCalls;
    const int timed = inBlock - settleCalls;   // the timed call's number in its block
    int decided = 0;
    if (timed >= 0) {
        times_[team == 1 ? 0 : 1][timed] = seconds;
        if (team != 1) {
            // The calls on all threads so far, their slowest left out, already took longer
            // than one thread's whole block: they cannot win; stop paying for them
            const auto first = times_[1].begin();
            const double sum = std::accumulate(first, first + timed + 1, 0.0)
                               - *std::max_element(first, first + timed + 1);
            const double oneSum = meanWithoutSlowest(times_[0]) * (trialCalls - 1);
            if (sum > oneSum) decided = 1;
        }
    }
    if (!decided && ++trial_ < trialLength) return;
    const int faster = decided ? decided
                       : meanWithoutSlowest(times_[0]) < meanWithoutSlowest(times_[1]) ? 1
                                                                                      : maxThreads_;
    hold_ = faster == chosen_ ? std::min(2 * hold_, maxHold) : minHold;
    chosen_ = faster;
    heldLeft_ = hold_;
    trial_ = trialLength;
}

} // namespace dem
