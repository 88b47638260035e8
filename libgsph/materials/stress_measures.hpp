// SPDX-License-Identifier: MIT
// Scalar measures of a Cauchy stress σ that users plot and probe:
//   von Mises σ_vm = √(3/2 s:s), s = σ − (tr σ/3) I;   pressure p = −tr σ/3 (compression > 0).
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace gsph {

inline double vonMises(const Mat3& sigma) {
    const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    return std::sqrt(1.5 * s.squaredNorm());
}

inline double pressure(const Mat3& sigma) {
    return -sigma.trace() / 3.0;
}

}  // namespace gsph
