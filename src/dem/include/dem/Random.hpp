// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reproducible random draws: built on the raw output of std::mt19937_64, whose sequence
// the standard fixes, because std:: distributions differ between library implementations.

#include <cstdint>
#include <random>

namespace dem {

/// Seeded generator with implementation-independent draws.
class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}

    /// Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

    /// Uniform in [a, b).
    double uniform(double a, double b) { return a + (b - a) * uniform(); }

    /// Uniform integer in [0, n), n > 0, without modulo bias (rejection).
    std::uint64_t below(std::uint64_t n)
    {
        const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
        std::uint64_t r;
        do {
            r = engine_();
        } while (r >= limit);
        return r % n;
    }

private:
    std::mt19937_64 engine_;
};

} // namespace dem
