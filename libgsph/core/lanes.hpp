// SPDX-License-Identifier: MIT
// A strip of consecutive particles evaluated together in SIMD lanes (issue #2).
//
// The stencil kernels (kinematics/deformation_gradient.cpp, forces/internal_force.cpp) run a
// strip of kLanes particles through a whole stencil with the per-particle sums held in
// registers; Lanes is an Eigen array, so the portable build gets SSE2 and a native build
// whatever Eigen picks. Pair formulas written as templates on the scalar type (double or
// Lanes) serve the strip kernels and the one-pair-at-a-time CSR path alike.
#pragma once

#include <Eigen/Core>

namespace gsph {

inline constexpr int kLanes = 2;
using Lanes = Eigen::Array<double, kLanes, 1>;

/// The kLanes values at p, p + 1, ... (unaligned).
inline Lanes loadLanes(const double* p) {
    return Eigen::Map<const Lanes>(p);
}
inline void storeLanes(double* p, const Lanes& v) {
    Eigen::Map<Lanes>{p} = v;
}

/// q where s < 0, else 0 (lane by lane): a select, not a branch, so that it vectorises.
[[gnu::always_inline]] inline double whereNegative(double s, double q) {
    return s < 0.0 ? q : 0.0;
}
[[gnu::always_inline]] inline Lanes whereNegative(const Lanes& s, const Lanes& q) {
    return (s < 0.0).select(q, 0.0);
}

}  // namespace gsph
