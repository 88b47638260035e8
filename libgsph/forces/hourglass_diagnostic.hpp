// SPDX-License-Identifier: MIT
// Hourglass error diagnostic (DESIGN §4): how far the bonds are from the affine field F of
// their particles, as a kernel-weighted RMS of the relative bond error
//   η = √( Σ_a Σ_b ωW_ab |x_b − x_a − F_a (X_b − X_a)|² / |X_b − X_a|²  /  Σ_a Σ_b ωW_ab ).
// η = 0 for any affine motion; zero-energy (hourglass) modes show up as η > 0 while F, and so
// the stress, stays blind to them.
#pragma once

#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// η over all particles (thread-count independent).
double hourglassError(const Reference& ref, const State& state);

}  // namespace gsph
