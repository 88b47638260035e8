// SPDX-License-Identifier: MIT
// Hypo-elastic material with the Jaumann objective rate (DESIGN §5, paper Eq. CauchyTensor):
//   σ̇ = C : D + W σ − σ W,   C : D = λ tr(D) I + 2G D,   D = sym L, W = skew L, L = Ḟ F^{-1}.
//
// The material interface every model follows (materials/plastic_solid.hpp too):
//   static constexpr std::array<HistoryVariable, N> kHistory; // what it carries between steps
//   void update(MaterialPoint&, const Mat3& D, const Mat3& W, double dt) const;
//   double waveSpeed(const MaterialPoint&) const;           // for the time step and viscosity
//   double storedEnergyDensity(const MaterialPoint&) const; // per current volume
//   const ElasticConstants& elastic() const;                // E also scales the hourglass penalty
// Models are plain values held in a std::variant (materials/material.hpp): no virtual call per
// particle (style habit 7).
#pragma once

#include <array>

#include "core/strip_mat3.hpp"
#include "core/types.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/material_point.hpp"

namespace gsph {

/// The rotation R = (I − ½ΔtW)^{-1}(I + ½ΔtW) of the incrementally objective Jaumann update
/// (Hughes & Winget 1980); exactly orthogonal for any Δt. T: double or a strip type
/// (core/strip_mat3.hpp), the same bits in every lane.
template <class T>
[[gnu::always_inline]] inline StripMat3<T> jaumannRotation(const StripMat3<T>& W, double dt) {
    const StripMat3<T> halfSpin = (0.5 * dt) * W;
    const StripMat3<T> identity = StripMat3<T>::identity();
    return inverse(identity - halfSpin) * (identity + halfSpin);
}
inline Mat3 jaumannRotation(const Mat3& W, double dt) {
    return eigenOf(jaumannRotation(stripOf(W), dt));
}

/// The elastic trial stress of every model, Jaumann rate integrated incrementally objectively
/// (Hughes & Winget 1980): σ_{n+1} = R σ_n R^T + Δt C : D, R = jaumannRotation(W, Δt).
/// R is exactly orthogonal, so a rigid spin leaves the invariants of σ unchanged to
/// round-off; to first order in Δt this is σ_n + Δt (C : D + W σ − σ W).
template <class T>
[[gnu::always_inline]] inline StripMat3<T> jaumannElasticUpdate(const ElasticConstants& e,
                                                                const StripMat3<T>& sigma,
                                                                const StripMat3<T>& D,
                                                                const StripMat3<T>& W, double dt) {
    const StripMat3<T> R = jaumannRotation(W, dt);
    const StripMat3<T> rotated = R * sigma * R.transpose();
    const T volumetric = e.lame() * D.trace();
    const double twiceShear = 2.0 * e.shearModulus();
    StripMat3<T> next;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const T rate = r == c ? volumetric + twiceShear * D(r, c) : twiceShear * D(r, c);
            next(r, c) = rotated(r, c) + dt * rate;
        }
    return next;
}
inline Mat3 jaumannElasticUpdate(const ElasticConstants& e, const Mat3& sigma, const Mat3& D,
                                 const Mat3& W, double dt) {
    return eigenOf(jaumannElasticUpdate(e, stripOf(sigma), stripOf(D), stripOf(W), dt));
}

class HypoElastic {
  public:
    static constexpr std::array<HistoryVariable, 0> kHistory{};  ///< none

    explicit HypoElastic(const ElasticConstants& e) : elastic_(e) {}

    const ElasticConstants& elastic() const { return elastic_; }

    void update(MaterialPoint& p, const Mat3& D, const Mat3& W, double dt) const {
        p.cauchy = jaumannElasticUpdate(elastic_, p.cauchy, D, W, dt);
    }

    double waveSpeed(const MaterialPoint&) const { return elastic_.pWaveSpeed(); }

    /// Complementary energy s:s/(4G) + p²/(2K) [J/m³]: the stored energy of linear elasticity
    /// written in the stress, exact for small strains.
    double storedEnergyDensity(const Mat3& sigma) const {
        const double p = sigma.trace() / 3.0;
        const Mat3 s = sigma - p * Mat3::Identity();
        return s.squaredNorm() / (4.0 * elastic_.shearModulus()) +
               p * p / (2.0 * elastic_.bulkModulus());
    }
    double storedEnergyDensity(const MaterialPoint& point) const {
        return storedEnergyDensity(point.cauchy);
    }

  private:
    ElasticConstants elastic_;
};

}  // namespace gsph
