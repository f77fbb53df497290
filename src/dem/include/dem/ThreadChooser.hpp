// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The team size of a repeated piece of work (a CFD step's DEM sub-steps), chosen by timing
// it: one thread or all of them, whichever ran faster. Threads that sleep at every barrier
// (OMP_WAIT_POLICY=passive), cores shared with other runs, or a step too short to share make
// more threads slower than one, and which holds changes with the host's load. The engines'
// results do not depend on the team size, so the choice changes only the speed.

#include <array>
#include <cstdint>
#include <functional>

namespace dem {

class ThreadChooser {
public:
    /// A trial runs a block of calls on one thread, then a block on all; in each block the
    /// first settleCalls are not timed (the other team's threads are still being put to
    /// sleep or woken) and the next trialCalls are. The team of the smaller mean time, the
    /// slowest call of each left out, runs for a hold of calls, then the next trial; the
    /// block on all threads stops as soon as its calls have taken longer than one thread's
    /// block. A hold on all threads is watched: once its last trialCalls calls, the slowest
    /// left out, have taken longer than as many of one thread's in the trial, the hold ends:
    /// within its first 2 trialCalls calls and at twice the trial's time on all threads, one
    /// thread holds (the trial caught a quiet moment beside a busy core, and a new one would
    /// catch another as often), else a new trial starts (a neighbour that started since, or a
    /// step whose cost changed, is timed again on both teams). Two threads slower than one
    /// are kept for about trialCalls calls, not a hold. Each team's hold starts at minHold
    /// and doubles up to maxHold each time the team wins a trial, so that a settled choice
    /// costs few trials and a change of the load is seen again; one thread's win, or a hold
    /// on all threads ended by its watch, starts all threads' hold over, and only a whole
    /// hold on all threads one thread's (a trial may catch a quiet moment).
    /// Why the mean: beside a busy core, most calls on two threads are faster than one
    /// thread's, but every few waits a scheduler's time slice for the core its partner
    /// shares (5-100 times as long): a median sees the fast calls and chose two threads at a
    /// third of one thread's speed; the time spent is the mean's.
    /// Before each trial the chooser asks how many cores the rest of the machine left free
    /// (CoreLoad); fewer than maxThreads - 1/2 and one thread holds without a trial: beside a
    /// busy core a trial's calls on all threads cost three times one thread's and some win
    /// by catching a quiet moment, which kept two threads 10-20 % slower than one.
    static constexpr int trialCalls = 21;
    static constexpr int settleCalls = 2;
    static constexpr int blockCalls = settleCalls + trialCalls;
    static constexpr int trialLength = 2 * blockCalls;
    static constexpr std::int64_t minHold = 50;
    static constexpr std::int64_t maxHold = 3200;

    /// The cores others left free since it was last asked; NaN: not known (a trial decides).
    using FreeCores = std::function<double()>;

    /// Without freeCores, trials alone decide.
    explicit ThreadChooser(int maxThreads, FreeCores freeCores = {});

    /// The team size for the next call.
    int next() const;
    /// The wall time of the call just made with next()'s team size, s.
    void record(double seconds);

    int maxThreads() const { return maxThreads_; }
    /// Calls made so far on one thread, and on maxThreads.
    std::int64_t callsOnOne() const { return calls_[0]; }
    std::int64_t callsOnAll() const { return calls_[1]; }
    /// Holds on all threads ended by their watch.
    std::int64_t holdsCutShort() const { return holdsCutShort_; }
    /// Trials not made because others kept fewer than maxThreads - 1/2 cores free.
    std::int64_t trialsSkipped() const { return trialsSkipped_; }

private:
    int maxThreads_;
    FreeCores freeCores_;
    int trial_ = 0;                       // calls made in the current trial; trialLength: none
    std::array<std::array<double, trialCalls>, 2> times_{};   // [one, all][call]
    int chosen_;                          // the team size held
    std::array<std::int64_t, 2> hold_{minHold, minHold};   // [one, all]: the next hold's calls
    std::int64_t heldLeft_ = 0;
    double oneMean_ = 0.0;                // one thread's mean call in the last trial, s
    // The current hold on all threads: its calls so far, the times of the last trialCalls, s
    std::int64_t watchedCalls_ = 0;
    std::array<double, trialCalls> watched_{};
    std::array<std::int64_t, 2> calls_{};
    std::int64_t holdsCutShort_ = 0;
    std::int64_t trialsSkipped_ = 0;

    void hold(int team);
    /// A trial, or one thread's hold where too few cores are free for all threads.
    void startTrial();
};

} // namespace dem
