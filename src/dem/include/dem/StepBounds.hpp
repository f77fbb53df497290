// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The DEM step's bounds of a run's settings (StepBounds.cpp; docs/theory/numerics.md, "The
// DEM step's bound"), the warnings near them and the speeds they are taken at. Plain C++17
// (the facade includes it).

#include <string>
#include <vector>

namespace dem {

struct Settings;

/// The bed's own speed scale sqrt(|g| d_max), the speed of a fall through half the largest
/// diameter, m/s: a bed under gravity collides at least this fast.
double bedSpeedScale(const Settings& settings);

/// The impact speed the HertzMindlin step bounds are taken at: impactSpeed, or
/// bedSpeedScale where that is larger (settingsWarnings then says so), m/s.
double hertzSpeed(const Settings& settings);

/// Eq. 7 time-step bound (2 pi/5) sqrt(m_min/kn) over the classes, s; smallest class in `cls`.
/// HertzMindlin: the least (2 pi/5) sqrt(m/S) over the pairs of classes and the walls, m the
/// lighter particle's mass and S = 2 E* sqrt(R* delta_max) Hertz's stiffness at the peak
/// overlap of an impact at hertzSpeed; `cls` the lighter class of that contact.
double timeStepBound(const Settings& settings, int* smallestClass = nullptr);

/// Contact duration t_c for a pair of the lightest class, with that pair's restitution, s:
/// under the linear law the shortest contact (a wall's has twice the mass), until the
/// clamped force vanishes. HertzMindlin: the shortest of Hertz's elastic contact times at
/// hertzSpeed over the pairs of classes and the walls.
double pairContactTime(const Settings& settings);

/// The DEM step's measured bounds (docs/theory/numerics.md, "The DEM step's bound"), as fractions of
/// pairContactTime: below the safe one a head-on pair keeps its restitution within 1 % and
/// a settling bed comes to rest; above the stable one a settling bed does not.
double safeTimeStep(const Settings& settings);
double stableTimeStep(const Settings& settings);

/// The dashpot's own stability bound: the largest step at which no contact's normal damping
/// eta reverses the relative velocity within one step, min m_eff/eta over the pairs of
/// classes and the walls (HertzMindlin: eta at the peak overlap of an impact at hertzSpeed),
/// s. Settings with a larger dt are refused (validateSettings).
double dashpotTimeStep(const Settings& settings);

/// What is valid but near a bound, one sentence each, naming the entries (dt above half the
/// dashpot's bound; HertzMindlin's impactSpeed below the bed's speed scale); empty if none.
std::vector<std::string> settingsWarnings(const Settings& settings);

} // namespace dem
