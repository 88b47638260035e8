// SPDX-License-Identifier: MIT
#include "spaces/metric.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// |det B| below this (relative to a full stencil's ≈ 1) means too few neighbours in some
// direction for a first-order correction: a particle with fewer than d independent neighbours.
constexpr double kSingularCorrection = 1e-8;

}  // namespace

void computeGeometry(Reference& ref) {
    const Index n = ref.size();
    if (ref.pairs.particles() != n)
        throw Error("computeGeometry: pairs not built for this reference");
    const auto N = static_cast<std::size_t>(n);
    ref.omega.resize(N);
    for (std::size_t a = 0; a < N; ++a)
        ref.omega[a] = thetaVolume(ref.dim, ref.spaces[static_cast<std::size_t>(ref.space[a])]);
    ref.G.resize(N);
    ref.quadVolume.resize(N);
    ref.mass.resize(N);
    if (ref.density.size() != N) throw InputError("reference has no density per particle");
    ref.spacing.resize(N);
    ref.smoothingLength.resize(N);
    ref.metricCondition.resize(N);
    const Mat3 outOfPlane = ref.dim.outOfPlane();
    const PairList& P = ref.pairs;

    // Failures are collected per particle and reported after the loop (no throw inside OpenMP).
    std::vector<std::uint8_t> failed(N, 0);
    parallelFor(n, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        Mat3 B = Mat3::Zero();
        Mat3 MX = Mat3::Zero();  // Σ ω (X_b − X_a) ⊗ ∇W, before the correction
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            // θ_b − θ_a = −r from the table: it carries the periodic minimum image.
            const KernelEntry& e =
                P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])];
            B.noalias() -= e.thetaOffset * e.gradW.transpose();
            MX.noalias() += (ref.X[b] - ref.X[ia]) * e.gradW.transpose();
        }
        B += outOfPlane;
        const double detB = B.determinant();
        if (!(std::abs(detB) > kSingularCorrection)) {
            failed[ia] = 1;
            return;
        }
        const Mat3 Binv = B.inverse();
        const Mat3 M = MX * Binv + outOfPlane;
        const double detM = M.determinant();
        if (!(detM > 0.0)) {
            failed[ia] = 2;
            return;
        }
        const Mat3 Q = M.inverse();
        ref.G[ia] = Q.transpose() * Binv.transpose();
        ref.quadVolume[ia] = ref.omega[ia] * detM;
        ref.mass[ia] = ref.density[ia] * ref.quadVolume[ia];
        const int d = ref.dim.value;
        const Vec3 s = d == 3 ? Vec3(Eigen::JacobiSVD<Mat3>(M).singularValues())
                              : Vec3(Eigen::JacobiSVD<Eigen::Matrix2d>(M.topLeftCorner<2, 2>())
                                         .singularValues()
                                         .homogeneous());
        const double dtheta = ref.spaces[static_cast<std::size_t>(ref.space[ia])].dtheta;
        ref.spacing[ia] = dtheta * s[d - 1];
        ref.smoothingLength[ia] = ref.kappa * dtheta * std::pow(detM, 1.0 / d);
        ref.metricCondition[ia] = s[0] / s[d - 1];
    });
    for (std::size_t a = 0; a < N; ++a) {
        if (failed[a] == 1)
            throw NumericalError("particle " + std::to_string(a) +
                                     ": singular kernel correction B (too few neighbours)",
                                 static_cast<long>(a));
        if (failed[a] == 2)
            throw NumericalError("particle " + std::to_string(a) +
                                     ": metric ∂X/∂θ is singular or inverted (det ≤ 0)",
                                 static_cast<long>(a));
    }
}

}  // namespace gsph
