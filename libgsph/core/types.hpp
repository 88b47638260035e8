// SPDX-License-Identifier: MIT
// Basic types of the library, in one place (style habit 10).
// Vectors and tensors are always 3-D; a 2-D (plane strain) run keeps every z offset zero and
// adds the out-of-plane identity where a tensor needs it (Dimension::outOfPlane()).
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace gsph {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Index = std::int32_t;

/// Spatial dimension of a run: 2 (plane strain in x-y) or 3.
struct Dimension {
    int value = 3;

    /// Projector onto the directions the particle layout does not span: diag(0,0,1) in 2-D,
    /// zero in 3-D. Sums over neighbours have no z content in 2-D, so a tensor such as
    /// F = I + ... gets its zz entry from this projector (plane strain: F_zz = 1).
    Mat3 outOfPlane() const {
        Mat3 p = Mat3::Zero();
        if (value == 2) p(2, 2) = 1.0;
        return p;
    }
};

}  // namespace gsph
