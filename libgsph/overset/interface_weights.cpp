// SPDX-License-Identifier: MIT
#include "overset/interface_weights.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// Rows per constrained particle: (1) consistency 3×3 at [3i + j], (2) Piola 3 at [9 + j],
// (3) transposed moment 3×3 at [12 + 3i + j] (i: the X component, j: the weight component).
constexpr int kRows = 21;
constexpr int kPiola = 9, kMoment = 12;

struct CorrectedPair {
    Index a = 0, b = 0, k = 0;  // pair k = (a, b) of a's list, both in the band
};

// The coefficients of one pair's unknowns δγ_ab (3 components j) in the constraints' rows: the
// same for every j (the rows are offset by j), computed once. (1) at a: X_ab[i] / h_a in rows
// ra + 3i + j; (2) at a: 1 in ra + kPiola + j (a interior); (2) at b: −V_a / V_b in
// rb + kPiola + j and (3) at b: −V_a X_ab[i] / (V_b h_b) in rb + kMoment + 3i + j (b interior).
struct PairCoefficients {
    Index ra = 0, rb = 0;
    bool aInterior = false, bInterior = false;
    double consistency[3] = {}, piolaB = 0.0, moment[3] = {};
};

// The constraints of the band, scaled so that every row is O(|γ|): (1) by 1/h_a, (2) by
// 1/V_c, (3) by 1/(V_c h_c). A maps the corrections δγ (3 per pair) to the rows; the solve
// works on A Aᵀ, whose action is applyA(applyAt(λ)). Each sum adds its terms in the order
// (1) at a, (2) at a, (2) at b, (3) at b, as forEachCoefficient visits them.
class BandConstraints {
  public:
    BandConstraints(const Reference& ref, const std::vector<Index>& rowOf,
                    std::vector<CorrectedPair> pairs)
        : pairs_(std::move(pairs)), coefficients_(pairs_.size()), dim_(ref.dim.value) {
        // (2) and (3) hold only away from free faces (at a face the Piola sum is its traction).
        const auto interior = [&](std::size_t a) {
            return ref.oversetBand[a] == Reference::kBandInterior;
        };
        parallelFor(static_cast<Index>(pairs_.size()), [&](Index u) {
            const CorrectedPair& p = pairs_[static_cast<std::size_t>(u)];
            PairCoefficients& c = coefficients_[static_cast<std::size_t>(u)];
            const auto ia = static_cast<std::size_t>(p.a), ib = static_cast<std::size_t>(p.b);
            c.ra = kRows * rowOf[ia];
            c.rb = kRows * rowOf[ib];
            const Vec3 Xab = ref.X[ib] - ref.X[ia];
            const double ha = ref.smoothingLength[ia], hb = ref.smoothingLength[ib];
            const double Va = ref.quadVolume[ia], Vb = ref.quadVolume[ib];
            c.aInterior = interior(ia);
            c.bInterior = interior(ib);
            for (int i = 0; i < dim_; ++i) {
                c.consistency[i] = Xab[i] / ha;
                c.moment[i] = -Va * Xab[i] / (Vb * hb);
            }
            c.piolaB = -Va / Vb;
        });
    }

    std::size_t unknowns() const { return 3 * pairs_.size(); }
    const std::vector<CorrectedPair>& pairs() const { return pairs_; }

    // Coefficient of unknown (pair u, component j) in each of its rows, visited as
    // visit(row, coefficient). In 2-D the out-of-plane component is not an unknown.
    template <class Visit>
    void forEachCoefficient(std::size_t u, int j, Visit&& visit) const {
        const PairCoefficients& c = coefficients_[u];
        for (int i = 0; i < dim_; ++i) visit(c.ra + 3 * i + j, c.consistency[i]);
        if (c.aInterior) visit(c.ra + kPiola + j, 1.0);
        if (c.bInterior) {
            visit(c.rb + kPiola + j, c.piolaB);
            for (int i = 0; i < dim_; ++i) visit(c.rb + kMoment + 3 * i + j, c.moment[i]);
        }
    }

    // g = Aᵀ λ (per unknown: independent, so parallel and deterministic).
    void applyAt(const Eigen::VectorXd& lambda, Eigen::VectorXd& g) const {
        parallelFor(static_cast<Index>(pairs_.size()), [&](Index u) {
            for (int j = 0; j < 3; ++j) {
                double sum = 0.0;
                if (j < dim_)
                    forEachCoefficient(static_cast<std::size_t>(u), j,
                                       [&](Index row, double c) { sum += c * lambda[row]; });
                g[3 * u + j] = sum;
            }
        });
    }

    // r = A g (a scatter into the rows; serial, in pair order: the same bits on every run. A
    // gather per particle in parallel was slower: it reads g at random where this writes r).
    void applyA(const Eigen::VectorXd& g, Eigen::VectorXd& r) const {
        r.setZero();
        for (std::size_t u = 0; u < pairs_.size(); ++u)
            for (int j = 0; j < dim_; ++j)
                forEachCoefficient(u, j, [&](Index row, double c) {
                    r[row] += c * g[static_cast<Eigen::Index>(3 * u) + j];
                });
    }

    Eigen::VectorXd diagonalOfNormalMatrix(Index rows) const {
        Eigen::VectorXd diag = Eigen::VectorXd::Zero(rows);
        for (std::size_t u = 0; u < pairs_.size(); ++u)
            for (int j = 0; j < dim_; ++j)
                forEachCoefficient(u, j, [&](Index row, double c) { diag[row] += c * c; });
        return diag;
    }

  private:
    std::vector<CorrectedPair> pairs_;
    std::vector<PairCoefficients> coefficients_;
    int dim_;
};

}  // namespace

void correctInterfaceWeights(Reference& ref, const InterfaceSolveProgress& progress) {
    ref.correctionBegin.clear();
    ref.pairCorrection.clear();
    ref.mirrorCorrection.clear();
    ref.interfaceSolve = {};
    if (ref.oversetBand.empty()) return;
    const PairList& P = ref.pairs;
    const auto n = static_cast<std::size_t>(ref.size());
    std::vector<Index> rowOf(n, -1);
    Index constrained = 0;
    for (std::size_t a = 0; a < n; ++a)
        if (ref.oversetBand[a] != 0) rowOf[a] = constrained++;
    if (constrained == 0) return;
    std::vector<CorrectedPair> pairs;
    for (Index a = 0; a < ref.size(); ++a) {
        if (rowOf[static_cast<std::size_t>(a)] < 0) continue;
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const Index b = P.neighbor[static_cast<std::size_t>(k)];
            if (rowOf[static_cast<std::size_t>(b)] >= 0) pairs.push_back({a, b, k});
        }
    }
    const int d = ref.dim.value;
    const auto weight = [&](Index a, Index k) -> Vec3 {  // γ_ab = G(a) w_ab
        return ref.G[static_cast<std::size_t>(a)] *
               P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])].gradW;
    };
    // Right-hand side: minus the constraints' residuals with the uncorrected weights.
    const Index rows = kRows * constrained;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
    for (Index a = 0; a < ref.size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const double Va = ref.quadVolume[ia];
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            const Vec3 g = weight(a, k);
            if (rowOf[ia] >= 0) {  // own pair of a: (1) and (2)
                const Index r = kRows * rowOf[ia];
                const Vec3 Xab = ref.X[b] - ref.X[ia];
                for (int i = 0; i < d; ++i)
                    for (int j = 0; j < d; ++j) rhs[r + 3 * i + j] -= Xab[i] * g[j];
                for (int j = 0; j < d; ++j) rhs[r + kPiola + j] -= Va * g[j];
            }
            if (rowOf[b] >= 0) {  // incoming pair of b: (2) and (3)
                const Index r = kRows * rowOf[b];
                const Vec3 Xab = ref.X[ia] - ref.X[b];
                for (int j = 0; j < d; ++j) rhs[r + kPiola + j] += Va * g[j];
                for (int i = 0; i < d; ++i)
                    for (int j = 0; j < d; ++j) rhs[r + kMoment + 3 * i + j] -= Va * Xab[i] * g[j];
            }
        }
    }
    for (std::size_t a = 0; a < n; ++a) {
        if (rowOf[a] < 0) continue;
        const Index r = kRows * rowOf[a];
        const double h = ref.smoothingLength[a], V = ref.quadVolume[a];
        for (int i = 0; i < d; ++i) {
            rhs[r + 3 * i + i] += 1.0;
            rhs[r + kMoment + 3 * i + i] -= V;
        }
        for (int q = 0; q < 9; ++q) rhs[r + q] /= h;
        for (int q = 0; q < 3; ++q) rhs[r + kPiola + q] /= V;
        for (int q = 0; q < 9; ++q) rhs[r + kMoment + q] /= V * h;
    }
    const BandConstraints A(ref, rowOf, std::move(pairs));
    // Preconditioned conjugate gradients on A Aᵀ λ = rhs (Jacobi); rows without coefficients
    // (the out-of-plane ones in 2-D) stay at λ = 0.
    const Eigen::VectorXd diag = A.diagonalOfNormalMatrix(rows);
    Eigen::VectorXd inv(rows);
    for (Index r = 0; r < rows; ++r) {
        inv[r] = diag[r] > 0.0 ? 1.0 / diag[r] : 0.0;
        if (diag[r] == 0.0) rhs[r] = 0.0;
    }
    const double rhsNorm = rhs.norm();
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(rows), residual = rhs;
    Eigen::VectorXd z = inv.cwiseProduct(residual), direction = z, g(A.unknowns()), Ad(rows);
    double rz = residual.dot(z);
    const double tolerance = 1e-14 * rhsNorm;
    const int maxIterations = 20000;
    int it = 0;
    double residualNorm = rhsNorm;
    while (it < maxIterations && residualNorm > tolerance) {
        A.applyAt(direction, g);
        A.applyA(g, Ad);
        const double dAd = direction.dot(Ad);
        if (!(dAd > 0.0)) break;
        const double alpha = rz / dAd;
        lambda += alpha * direction;
        residual -= alpha * Ad;
        z = inv.cwiseProduct(residual);
        const double rzNext = residual.dot(z);
        direction = z + (rzNext / rz) * direction;
        rz = rzNext;
        ++it;
        residualNorm = residual.norm();
        if (progress) progress(it, residualNorm / rhsNorm);
    }
    // The achieved residual, recomputed from the corrections themselves.
    Eigen::VectorXd correction(A.unknowns()), achieved(rows);
    A.applyAt(lambda, correction);
    A.applyA(correction, achieved);
    const double achievedResidual = rhsNorm > 0.0 ? (achieved - rhs).norm() / rhsNorm : 0.0;
    if (!(achievedResidual < 1e-9))
        throw NumericalError(
            "overset interface weights: the band's consistency constraints "
            "cannot be met (relative residual " +
            std::to_string(achievedResidual) + " after " + std::to_string(it) + " iterations)");
    ref.interfaceSolve = {rows, it, achievedResidual};
    // Store in θ units along each list: δw_ab = G(a)^{-1} δγ_ab, and the mirrors.
    ref.correctionBegin.assign(n, -1);
    std::vector<std::uint8_t> touched(n, 0);
    for (const CorrectedPair& p : A.pairs())
        touched[static_cast<std::size_t>(p.a)] = touched[static_cast<std::size_t>(p.b)] = 1;
    Index slots = 0;
    for (Index a = 0; a < ref.size(); ++a)
        if (touched[static_cast<std::size_t>(a)] != 0) {
            ref.correctionBegin[static_cast<std::size_t>(a)] = slots;
            slots += P.end(a) - P.begin(a);
        }
    ref.pairCorrection.assign(static_cast<std::size_t>(slots), Vec3::Zero());
    ref.mirrorCorrection.assign(static_cast<std::size_t>(slots), Vec3::Zero());
    const auto slot = [&](Index a, Index k) {
        return static_cast<std::size_t>(ref.correctionBegin[static_cast<std::size_t>(a)] + k -
                                        P.begin(a));
    };
    for (std::size_t u = 0; u < A.pairs().size(); ++u) {
        const CorrectedPair& p = A.pairs()[u];
        const Vec3 dGamma = correction.segment<3>(static_cast<Eigen::Index>(3 * u));
        const Vec3 dw = ref.G[static_cast<std::size_t>(p.a)].inverse() * dGamma;
        ref.pairCorrection[slot(p.a, p.k)] = dw;
        if (ref.space[static_cast<std::size_t>(p.a)] != ref.space[static_cast<std::size_t>(p.b)])
            continue;
        // The mirror (b, a): same space, so it exists (pairs within a space are symmetric).
        const Index* first = P.neighbor.data() + P.begin(p.b);
        const Index* last = P.neighbor.data() + P.end(p.b);
        const Index* it2 = std::lower_bound(first, last, p.a);
        if (it2 == last || *it2 != p.a)
            throw Error("correctInterfaceWeights: a same-space pair without its mirror");
        ref.mirrorCorrection[slot(p.b, P.begin(p.b) + (it2 - first))] = dw;
    }
    for (std::size_t a = 0; a < n; ++a)
        if (touched[a] != 0) ref.oversetCoupled[a] = 1;
}

}  // namespace gsph
