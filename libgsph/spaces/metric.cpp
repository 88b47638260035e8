// SPDX-License-Identifier: MIT
#include "spaces/metric.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "overset/interface_weights.hpp"
#include "overset/overset_band.hpp"
#include "particles/axisymmetry.hpp"

namespace gsph {
namespace {

// |det B| below this (relative to a full stencil's ≈ 1) means too few neighbours in some
// direction for a first-order correction: a particle with fewer than d independent neighbours.
constexpr double kSingularCorrection = 1e-8;

// An axisymmetric layout lies in the half-plane x > 0 (x the radius) of a 2-D run. Overset
// layouts are refused: their interface weights are built for the plane-strain volume (and the
// (r, z) half-plane has no coordinate singularity for them to remove).
void checkAxisymmetric(const Reference& ref) {
    if (ref.dim.value != 2) throw InputError("an axisymmetric run needs a 2-D particle layout");
    if (!ref.overset.empty())
        throw InputError("an axisymmetric run needs a layout without overset spaces");
    for (std::size_t a = 0; a < ref.X.size(); ++a)
        if (!(ref.X[a][0] > 0.0))
            throw InputError("axisymmetric run: particle " + std::to_string(a) +
                             " lies at x = " + std::to_string(ref.X[a][0]) +
                             " (x is the radius: the layout must lie in x > 0)");
}

}  // namespace

ParticleMetric particleMetric(const Reference& ref, Index a, const std::uint8_t* intact) {
    const PairList& P = ref.pairs;
    const auto ia = static_cast<std::size_t>(a);
    const Mat3 outOfPlane = ref.dim.outOfPlane();
    ParticleMetric pm;
    Mat3 MX = Mat3::Zero();  // Σ ω (X_b − X_a) ⊗ ∇W, before the correction
    for (Index k = P.begin(a); k < P.end(a); ++k) {
        if (intact != nullptr && intact[k] == 0) continue;
        const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
        // θ_b − θ_a = −r from the table: it carries the periodic minimum image.
        const KernelEntry& e =
            P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])];
        pm.B.noalias() -= e.thetaOffset * e.gradW.transpose();
        MX.noalias() += (ref.X[b] - ref.X[ia]) * e.gradW.transpose();
    }
    pm.B += outOfPlane;
    if (!(std::abs(pm.B.determinant()) > kSingularCorrection)) {
        pm.status = ParticleMetric::Status::SingularCorrection;
        return pm;
    }
    const Mat3 Binv = pm.B.inverse();
    pm.M = MX * Binv + outOfPlane;
    if (!(pm.M.determinant() > 0.0)) {
        pm.status = ParticleMetric::Status::InvertedMetric;
        return pm;
    }
    pm.G = pm.M.inverse().transpose() * Binv.transpose();
    return pm;
}

namespace {

// MassBasis::NormalizedQuadratureVolume: each body's V = ω det M scaled by one factor, its meshed
// volume over Σ ω det M (summed in particle order: the same bits on any thread count), and the
// mass ρ0 V from it. Before the interface weights, which read V (they depend only on its ratios).
void normalizeBodyVolumes(Reference& ref) {
    const std::size_t n = ref.quadVolume.size();
    const auto bodyOf = [&](std::size_t a) {
        return ref.body.empty() ? std::size_t{0} : static_cast<std::size_t>(ref.body[a]);
    };
    std::size_t bodies = 0;
    for (std::size_t a = 0; a < n; ++a) bodies = std::max(bodies, bodyOf(a) + 1);
    std::vector<double> quadrature(bodies, 0.0), meshed(bodies, 0.0);
    for (std::size_t a = 0; a < n; ++a) {
        quadrature[bodyOf(a)] += ref.quadVolume[a];
        meshed[bodyOf(a)] += ref.meshVolume(a);
    }
    for (std::size_t a = 0; a < n; ++a) {
        ref.quadVolume[a] *= meshed[bodyOf(a)] / quadrature[bodyOf(a)];
        ref.mass[a] = ref.density[a] * ref.quadVolume[a];
    }
}

}  // namespace

void computeGeometry(Reference& ref, const InterfaceSolveProgress& progress) {
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
    const bool meshMass = ref.massBasis == MassBasis::MeshVolume;
    if (ref.massBasis != MassBasis::QuadratureVolume && ref.volume.size() != N)
        throw InputError("reference has no meshed volume per particle for its mass");
    if (ref.dim.axisymmetric) checkAxisymmetric(ref);
    ref.spacing.resize(N);
    ref.smoothingLength.resize(N);
    ref.metricCondition.resize(N);
    // Failures are collected per particle and reported after the loop (no throw inside OpenMP).
    std::vector<std::uint8_t> failed(N, 0);
    parallelFor(n, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const ParticleMetric pm = particleMetric(ref, a);
        if (pm.status != ParticleMetric::Status::Ok) {
            failed[ia] = pm.status == ParticleMetric::Status::SingularCorrection ? 1 : 2;
            return;
        }
        const Mat3& M = pm.M;
        const double detM = M.determinant();
        ref.G[ia] = pm.G;
        // An axisymmetric particle is a ring: its cross-section's area times 2πR.
        const double ring = ref.dim.axisymmetric ? ringFactor(ref.X[ia]) : 1.0;
        ref.quadVolume[ia] = ring * ref.omega[ia] * detM;
        ref.mass[ia] = ref.density[ia] * (meshMass ? ref.meshVolume(ia) : ref.quadVolume[ia]);
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
    if (ref.massBasis == MassBasis::NormalizedQuadratureVolume) normalizeBodyVolumes(ref);
    markOversetBand(ref);
    correctInterfaceWeights(ref, progress);
}

}  // namespace gsph
