// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The team size chosen by timing (ThreadChooser.hpp).

#include "dem/ThreadChooser.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

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

ThreadChooser::ThreadChooser(int maxThreads, FreeCores freeCores)
    : maxThreads_(std::max(1, maxThreads)), freeCores_(std::move(freeCores)), chosen_(maxThreads_)
{
    if (maxThreads_ > 1) startTrial();
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
        if (team != 1) {
            // The last trialCalls calls on all threads, their slowest left out, against as
            // many of one thread's
            watched_[watchedCalls_++ % trialCalls] = seconds;
            const double watchedMean =
                watchedCalls_ >= trialCalls ? meanWithoutSlowest(watched_) : 0.0;
            if (watchedMean > oneMean_) {
                // Slower than one thread was at the trial. At twice the trial's time on all
                // threads within two watches of the hold's start: the trial caught a quiet
                // moment beside a busy core (there a call waits a time slice every few), which
                // the next would catch as often; one thread holds. Else the load changed, or
                // the step's cost did (a bed that settles or lifts); a new trial decides
                ++holdsCutShort_;
                if (watchedCalls_ <= 2 * trialCalls
                    && watchedMean > 2.0 * meanWithoutSlowest(times_[1])) {
                    hold(1);
                    return;
                }
                hold_[1] = minHold;
                startTrial();
                return;
            }
        }
        if (--heldLeft_ <= 0) {
            // All threads kept up with one thread for a whole hold: one thread's next hold,
            // if a trial picks it, starts over
            if (team != 1) hold_[0] = minHold;
            startTrial();
        }
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
    oneMean_ = meanWithoutSlowest(times_[0]);
    hold(decided ? decided : oneMean_ < meanWithoutSlowest(times_[1]) ? 1 : maxThreads_);
}

void ThreadChooser::startTrial()
{
    // Not known (NaN): a trial. isless, as an ordered comparison with NaN raises the
    // invalid-operation exception that OpenFOAM's runs trap
    if (freeCores_ && std::isless(freeCores_(), maxThreads_ - 0.5)) {
        ++trialsSkipped_;
        hold(1);
        return;
    }
    trial_ = 0;
}

void ThreadChooser::hold(int team)
{
    // The winner holds for its hold, which doubles for its next win. One thread's win
    // starts all threads' hold over; all threads' win does not yet start one thread's
    // over, their hold has to keep up first
    const int k = team == 1 ? 0 : 1;
    heldLeft_ = hold_[k];
    hold_[k] = std::min(2 * hold_[k], maxHold);
    if (team == 1) hold_[1] = minHold;
    chosen_ = team;
    trial_ = trialLength;
    watchedCalls_ = 0;
}

} // namespace dem
