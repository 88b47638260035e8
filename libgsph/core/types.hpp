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

/// Spatial dimension of a run: 2 (plane strain in x-y, or axisymmetric) or 3.
struct Dimension {
    int value = 3;
    /// 2-D only: the x-y plane is the (r, z) half-plane of a body of revolution (x = r > 0 the
    /// radius, y along the axis) and the third direction is the hoop direction: volumes are
    /// rings (V = 2π r A), F_zz = r/R (forces/hoop_stress_stage.hpp; docs/theory.md
    /// "Axisymmetric runs").
    bool axisymmetric = false;

    /// Projector onto the directions the particle layout does not span: diag(0,0,1) in 2-D,
    /// zero in 3-D. Sums over neighbours have no z content in 2-D, so a tensor such as
    /// F = I + ... gets its zz entry from this projector (plane strain: F_zz = 1; in an
    /// axisymmetric run the reference's, the current F_zz being the hoop stretch r/R).
    Mat3 outOfPlane() const {
        Mat3 p = Mat3::Zero();
        if (value == 2) p(2, 2) = 1.0;
        return p;
    }
};

}  // namespace gsph
