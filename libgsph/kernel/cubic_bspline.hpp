// SPDX-License-Identifier: MIT
// Cubic B-spline kernel of q = |r|/h, support 2h (DESIGN §3; paper Eq. for W).
//   W(q) = σ_d · { 1 − 3/2 q² + 3/4 q³   (0 ≤ q < 1)
//                { 1/4 (2 − q)³          (1 ≤ q < 2)
//                { 0                     (q ≥ 2)
// with σ_3 = 1/(π h³) and σ_2 = 10/(7π h²). ∫W dV = 1 in d dimensions.
// gradient(r) is ∂W(r)/∂r = W'(q)/h · r/|r|; with r = θ_a − θ_b it is ∇_a W_ab.
#pragma once

#include <cmath>
#include <numbers>

#include "core/types.hpp"

namespace gsph {

class CubicBSpline {
  public:
    CubicBSpline(int dimension, double h)
        : h_(h),
          sigma_(dimension == 2 ? 10.0 / (7.0 * std::numbers::pi * h * h)
                                : 1.0 / (std::numbers::pi * h * h * h)) {}

    double smoothingLength() const { return h_; }
    double supportRadius() const { return 2.0 * h_; }

    double value(double r) const {
        const double q = r / h_;
        if (q < 1.0) return sigma_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
        if (q < 2.0) return sigma_ * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
        return 0.0;
    }

    /// dW/dr (≤ 0).
    double derivative(double r) const {
        const double q = r / h_;
        if (q < 1.0) return sigma_ / h_ * (-3.0 * q + 2.25 * q * q);
        if (q < 2.0) return -sigma_ / h_ * 0.75 * (2.0 - q) * (2.0 - q);
        return 0.0;
    }

    /// ∂W/∂r for the vector r; zero at r = 0.
    Vec3 gradient(const Vec3& r) const {
        const double d = r.norm();
        if (d <= 0.0) return Vec3::Zero();
        return (derivative(d) / d) * r;
    }

  private:
    double h_;
    double sigma_;
};

}  // namespace gsph
