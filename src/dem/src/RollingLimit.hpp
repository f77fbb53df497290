// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The limit on a particle's rolling torques, shared by the 2D and slab engines (internal).
//
// A contact's rolling torque M = c w_r (c = |M|/|w_r| <= I_eff/(n dt) by the clamp of
// rollingTorque) takes the fraction c dt/I_i of the relative rolling from particle i in a
// step. Over all of i's contacts these fractions sum to D_i; the step changes the
// particles' spins by w' = w - dt I^-1 L w, L the symmetric network of the c's, whose
// modes Gershgorin's theorem keeps within [0, 2 max D_i]. With D_i <= 1/2 for every
// particle no mode of the relative rolling reverses or grows in a step; a small particle
// among several large ones, or the mixed-phase modes of a dense packing of equal ones,
// exceed it. Each contact's torque is therefore scaled by min(s_i, s_j),
// s_i = min(1, 1/(2 D_i)); a pair alone (D = 1/(2n) for equal spheres) is untouched.

#include "dem/ContactLaw.hpp"

#include <cstddef>

namespace dem {

/// D_i -> s_i = min(1, 1/(2 D_i)) for particles [first, last) of share.
inline void rollingScales(double* share, std::size_t first, std::size_t last)
{
    for (std::size_t i = first; i < last; ++i) share[i] = share[i] > 0.5 ? 0.5 / share[i] : 1.0;
}

/// A contact's scale, min(s_i, s_j).
inline double rollingScale(const double* scale, std::size_t i, std::size_t j)
{
    return scale[i] < scale[j] ? scale[i] : scale[j];
}

} // namespace dem
