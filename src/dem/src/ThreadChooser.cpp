// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The team size chosen by timing (ThreadChooser.hpp).

#include "dem/ThreadChooser.hpp"

#include <algorithm>

namespace dem {

namespace {

constexpr int trialLength = 2 * ThreadChooser::trialCalls;

double median(std::array<double, ThreadChooser::trialCalls> t)
{
    std::nth_element(t.begin(), t.begin() + t.size() / 2, t.end());
    return t[t.size() / 2];
}

} // namespace

ThreadChooser::ThreadChooser(int maxThreads)
    : maxThreads_(std::max(1, maxThreads)), chosen_(maxThreads_)
{
}

int ThreadChooser::next() const
{
    if (maxThreads_ == 1) return 1;
    if (trial_ < trialLength) return trial_ % 2 == 0 ? maxThreads_ : 1;
    return chosen_;
}

void ThreadChooser::record(double seconds)
{
    const int team = next();
    ++calls_[team == 1 ? 0 : 1];
    if (maxThreads_ == 1) return;
    if (trial_ < trialLength) {
        times_[team == 1 ? 0 : 1][trial_ / 2] = seconds;
        if (++trial_ < trialLength) return;
        const int faster = median(times_[0]) < median(times_[1]) ? 1 : maxThreads_;
        hold_ = faster == chosen_ ? std::min(2 * hold_, maxHold) : minHold;
        chosen_ = faster;
        heldLeft_ = hold_;
        return;
    }
    if (--heldLeft_ <= 0) trial_ = 0;
}

} // namespace dem
