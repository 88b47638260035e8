// SPDX-License-Identifier: MIT
#include "failure/brittle_bonds.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "spaces/metric.hpp"

namespace gsph {

bool segmentCrossesPatch(const CrackPatch& patch, const Vec3& from, const Vec3& to) {
    const Vec3 normal = patch.edge1.cross(patch.edge2);
    const bool fromAbove = normal.dot(from - patch.corner) >= 0.0;
    const bool toAbove = normal.dot(to - patch.corner) >= 0.0;
    if (fromAbove == toAbove) return false;
    // Evaluate from the end below the plane, so that (from, to) and (to, from) give the same bits.
    const Vec3& p = fromAbove ? to : from;
    const Vec3& q = fromAbove ? from : to;
    const Vec3 d = q - p;
    const double t = normal.dot(patch.corner - p) / normal.dot(d);
    const Vec3 r = p + t * d - patch.corner;
    // r = s edge1 + u edge2 in the patch's plane: the 2×2 Gram system.
    const double g11 = patch.edge1.squaredNorm(), g12 = patch.edge1.dot(patch.edge2),
                 g22 = patch.edge2.squaredNorm();
    const double det = g11 * g22 - g12 * g12;
    const double r1 = patch.edge1.dot(r), r2 = patch.edge2.dot(r);
    const double s = (g22 * r1 - g12 * r2) / det, u = (g11 * r2 - g12 * r1) / det;
    // Edges included to kPatchEdgeTolerance: a bond crossing exactly on an edge (a notch tip on
    // a cell face, where the bonds of mirror-image pairs meet) is cut whatever the round-off
    // of the positions, so that layouts with the same positions cut the same bonds.
    const double tol = kPatchEdgeTolerance;
    return s >= -tol && s <= 1.0 + tol && u >= -tol && u <= 1.0 + tol;
}

bool segmentPassesNear(const Vec3& p, const Vec3& q, const Vec3& f, double radius) {
    const Vec3 d = q - p;
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((f - p).dot(d) / dd, 0.0, 1.0) : 0.0;
    return (p + t * d - f).squaredNorm() < radius * radius;
}

Index breakBondsAcross(const Reference& ref, const std::vector<CrackPatch>& patches,
                       std::vector<std::uint8_t>& bondIntact) {
    const PairList& P = ref.pairs;
    if (bondIntact.size() != static_cast<std::size_t>(P.pairs()))
        throw InputError("initial cracks: " + std::to_string(bondIntact.size()) +
                         " bond flags for " + std::to_string(P.pairs()) + " pairs");
    for (const CrackPatch& patch : patches) {
        const Vec3 normal = patch.edge1.cross(patch.edge2);
        if (!(normal.squaredNorm() > 0.0) || !std::isfinite(normal.squaredNorm()))
            throw InputError("initial crack: its edges must span a plane (edge1 × edge2 ≠ 0)");
    }
    // Per CSR entry, from the reference positions alone: a and b decide alike. Each particle
    // writes only its own entries; fresh pairs are counted as entries (a, b) with a < b, as
    // BrittleBonds::brokenPairs counts them.
    std::vector<Index> fresh(static_cast<std::size_t>(ref.size()), 0);
    parallelFor(ref.size(), [&](Index a) {
        const Vec3& Xa = ref.X[static_cast<std::size_t>(a)];
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const auto ik = static_cast<std::size_t>(k);
            if (bondIntact[ik] == 0) continue;
            const Index b = P.neighbor[ik];
            const Vec3& Xb = ref.X[static_cast<std::size_t>(b)];
            for (const CrackPatch& patch : patches)
                if (segmentCrossesPatch(patch, Xa, Xb)) {
                    bondIntact[ik] = 0;
                    if (b > a) ++fresh[static_cast<std::size_t>(a)];
                    break;
                }
        }
    });
    Index broken = 0;
    for (Index f : fresh) broken += f;
    return broken;
}

BrittleBonds::BrittleBonds(const Reference& ref, std::vector<double> stretchByParticle,
                           std::vector<FailedBondRule> failedRuleByParticle, bool precracked,
                           std::vector<std::uint8_t> cohesiveByParticle)
    : ref_(ref),
      stretch_(std::move(stretchByParticle)),
      failedRule_(std::move(failedRuleByParticle)),
      cohesive_(std::move(cohesiveByParticle)),
      enabled_(precracked) {
    if (stretch_.size() != static_cast<std::size_t>(ref.size()))
        throw InputError("bond stretch limits: " + std::to_string(stretch_.size()) +
                         " values for " + std::to_string(ref.size()) + " particles");
    if (failedRule_.empty()) failedRule_.assign(stretch_.size(), FailedBondRule::Keep);
    if (failedRule_.size() != stretch_.size())
        throw InputError("failed-bond rules: " + std::to_string(failedRule_.size()) +
                         " values for " + std::to_string(ref.size()) + " particles");
    if (!cohesive_.empty() && cohesive_.size() != stretch_.size())
        throw InputError("cohesive flags: " + std::to_string(cohesive_.size()) + " values for " +
                         std::to_string(ref.size()) + " particles");
    for (FailedBondRule rule : failedRule_) {
        if (rule != FailedBondRule::Keep) enabled_ = breaksByDamage_ = true;
        if (rule == FailedBondRule::Cut) anyCut_ = true;
    }
    for (double e : stretch_) {
        if (!(e >= 0.0) || !std::isfinite(e))
            throw InputError("bond stretch limit εmax must be finite and ≥ 0, got " +
                             std::to_string(e));
        if (e > 0.0) enabled_ = true;
    }
    if (!enabled_) return;
    const auto n = static_cast<std::size_t>(ref.size());
    G_ = ref.G;
    damaged_.assign(n, 0);
    detached_.assign(n, 0);
    changed_.assign(n, 0);
    released_.assign(n, 0.0);
    intactDetB_.resize(n);
    stepFactor_.assign(n, 1.0);
    if (anyCut_) {
        failedSeen_.assign(n, 0);
        newlyFailed_.assign(n, 0);
        nearNewlyFailed_.assign(n, 0);
        neighbourFailed_.assign(static_cast<std::size_t>(ref.pairs.pairs()), 0);
    }
    if (anyCut_) cellFrame_.resize(n);
    parallelFor(ref.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const ParticleMetric pm = particleMetric(ref_, a);
        intactDetB_[ia] = std::abs(pm.B.determinant());
        // Cut: offsets in cell units of the particle's own lattice, (Δθ M)^{-1} (X − X_f), so
        // that "within kCutRadius of the cell" follows a stretched cell in every direction.
        if (anyCut_) {
            const double dtheta = ref_.spaces[static_cast<std::size_t>(ref_.space[ia])].dtheta;
            cellFrame_[ia] = (dtheta * pm.M).inverse();
        }
    });
}

void BrittleBonds::refreshParticle(const State& state, Index a) {
    const auto ia = static_cast<std::size_t>(a);
    const std::uint8_t* intact = state.bondIntact.data();
    std::uint8_t damaged = 0;
    for (Index k = ref_.pairs.begin(a); k < ref_.pairs.end(a); ++k)
        if (intact[k] == 0) damaged = 1;
    damaged_[ia] = damaged;
    if (damaged == 0) {
        G_[ia] = ref_.G[ia];
        detached_[ia] = 0;
        stepFactor_[ia] = 1.0;
        return;
    }
    const ParticleMetric pm = particleMetric(ref_, a, intact);
    bool spans = pm.status == ParticleMetric::Status::Ok &&
                 std::abs(pm.B.determinant()) >= kDetachedCorrection * intactDetB_[ia];
    // With Cut, also detached when G has grown beyond 1/kDetachedStepFactor of its intact size
    // (the other rules keep the |det B| criterion alone).
    const double factor = spans ? std::min(1.0, ref_.G[ia].norm() / pm.G.norm()) : 1.0;
    const bool byDamage = failedRule_[ia] != FailedBondRule::Keep;
    if (failedRule_[ia] == FailedBondRule::Cut && factor < kDetachedStepFactor) spans = false;
    detached_[ia] = spans ? 0 : 1;
    G_[ia] = spans ? pm.G : Mat3::Zero();
    stepFactor_[ia] = spans && byDamage ? factor : 1.0;
}

void BrittleBonds::markStale(ParticleRange particles) {
    stale_.resize(damaged_.size());
    parallelFor(particles, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        std::uint8_t stale = damaged_[ia];
        for (Index k = ref_.pairs.begin(a); k < ref_.pairs.end(a) && stale == 0; ++k)
            stale = damaged_[static_cast<std::size_t>(
                ref_.pairs.neighbor[static_cast<std::size_t>(k)])];
        // The pairs of other spaces' lists that hold a (their transposed terms are a's too).
        if (!ref_.crossOffset.empty())
            for (Index k = ref_.crossOffset[ia]; k < ref_.crossOffset[ia + 1] && stale == 0; ++k)
                stale = damaged_[static_cast<std::size_t>(
                    ref_.crossOwner[static_cast<std::size_t>(k)])];
        stale_[ia] = stale;
    });
}

void BrittleBonds::attach(const State& state) {
    if (!enabled_) return;
    if (state.bondIntact.size() != static_cast<std::size_t>(ref_.pairs.pairs()))
        throw InputError("state has " + std::to_string(state.bondIntact.size()) +
                         " bond flags for " + std::to_string(ref_.pairs.pairs()) + " pairs");
    parallelFor(ref_.size(), [&](Index a) { refreshParticle(state, a); });
    markStale({0, ref_.size()});
    // Cut: the next call tries every failed particle again (the bonds it cut are broken
    // already, the others stay), so a resumed run cuts exactly what the uninterrupted one does.
    std::fill(failedSeen_.begin(), failedSeen_.end(), std::uint8_t{0});
    brokenPairs_ = 0;
    for (Index a = 0; a < ref_.size(); ++a)
        for (Index k = ref_.pairs.begin(a); k < ref_.pairs.end(a); ++k)
            if (state.bondIntact[static_cast<std::size_t>(k)] == 0 &&
                ref_.pairs.neighbor[static_cast<std::size_t>(k)] > a)
                ++brokenPairs_;
}

double BrittleBonds::internalPower(const State& state, Index a) const {
    const auto ia = static_cast<std::size_t>(a);
    if (detached_[ia] != 0) return 0.0;
    const Mat3& F = state.F[ia];
    const double J = F.determinant();
    const Mat3 K = ref_.quadVolume[ia] * state.cauchy[ia] * (J * F.inverse().transpose()) * G_[ia];
    Mat3 gradX, gradV;
    thetaGradients(ref_, a, state.x.data(), state.v.data(), gradX, gradV, state.bondIntact.data());
    return (K.array() * gradV.array()).sum();
}

BondBreak BrittleBonds::breakStretchedBonds(State& state) {
    Domain serial;
    return breakStretchedBonds(state, {0, ref_.size()}, serial);
}

BondBreak BrittleBonds::breakStretchedBonds(State& state, ParticleRange owned, Domain& domain) {
    if (!enabled_) return {};
    const bool split = domain.processes() > 1;
    const PairList& P = ref_.pairs;
    std::uint8_t* intact = state.bondIntact.data();
    const auto stretched = [&](std::size_t ia, Index k, double factor) {
        const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
        const double current = (state.x[b] - state.x[ia]).squaredNorm();
        const double initial = (ref_.X[b] - ref_.X[ia]).squaredNorm();
        return current >= factor * initial;
    };
    // Johnson–Cook failure (D ≥ 1); the rule is the body's (pairs never join two bodies).
    const bool damageKnown = state.damage.size() == stretch_.size();
    const auto failed = [&](std::size_t i) { return damageKnown && state.damage[i] >= 1.0; };
    // Cut: the particles failed since the last call, and the particles next to one of them
    // (a bond (b, c) is tried when b or c is).
    const bool cutting = anyCut_ && damageKnown;
    if (cutting) {
        parallelFor(ref_.size(), [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            newlyFailed_[ia] = failed(ia) && failedSeen_[ia] == 0 ? 1 : 0;
        });
        // Split: a bond to a ghost c is cut by c's neighbours too, which may be no neighbour
        // of this process's particles; c's owner sends, per entry of c's row, whether that
        // neighbour failed since the last call.
        if (split) {
            std::uint8_t mine = 0;
            for (Index a = owned.begin; a < owned.end && mine == 0; ++a)
                mine = newlyFailed_[static_cast<std::size_t>(a)];
            if (domain.any(mine != 0)) {
                parallelFor(owned, [&](Index a) {
                    for (Index k = P.begin(a); k < P.end(a); ++k)
                        neighbourFailed_[static_cast<std::size_t>(k)] =
                            newlyFailed_[static_cast<std::size_t>(
                                P.neighbor[static_cast<std::size_t>(k)])];
                });
                domain.shareGhostRows(neighbourFailed_);
                for (Index c : domain.ghosts())
                    for (Index k = P.begin(c); k < P.end(c); ++k)
                        if (neighbourFailed_[static_cast<std::size_t>(k)] != 0)
                            newlyFailed_[static_cast<std::size_t>(
                                P.neighbor[static_cast<std::size_t>(k)])] = 1;
            }
        }
        parallelFor(ref_.size(), [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            std::uint8_t near = 0;
            if (failedRule_[ia] == FailedBondRule::Cut)
                for (Index k = P.begin(a); k < P.end(a) && near == 0; ++k)
                    near = newlyFailed_[static_cast<std::size_t>(
                        P.neighbor[static_cast<std::size_t>(k)])];
            nearNewlyFailed_[ia] = near;
        });
    }
    // Cut: does a particle failed since the last call, a neighbour of b or of c, lie in the
    // cell the segment X_b → X_c passes through? From the lower index, for the same bits.
    const auto cutByFailed = [&](std::size_t ib, std::size_t ic) {
        if (nearNewlyFailed_[ib] == 0 && nearNewlyFailed_[ic] == 0) return false;
        const std::size_t lo = std::min(ib, ic), hi = std::max(ib, ic);
        const Vec3 &p = ref_.X[lo], &q = ref_.X[hi];
        for (const std::size_t end : {lo, hi}) {
            const auto e = static_cast<Index>(end);
            for (Index k = P.begin(e); k < P.end(e); ++k) {
                const auto f = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
                if (newlyFailed_[f] == 0 || f == ib || f == ic) continue;
                const Mat3& toCells = cellFrame_[f];
                if (segmentPassesNear(toCells * (p - ref_.X[f]), toCells * (q - ref_.X[f]),
                                      Vec3::Zero(), kCutRadius))
                    return true;
            }
        }
        return false;
    };
    // Each particle reads and writes only its own CSR entries (its old K:∇v before writing
    // them); (a, b) and (b, a) compare the same squared lengths and the same two damages, so
    // both sides decide alike.
    parallelFor(owned, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const double limit = stretch_[ia];
        changed_[ia] = 0;
        released_[ia] = 0.0;
        const FailedBondRule rule = failedRule_[ia];
        if (limit == 0.0 && rule == FailedBondRule::Keep) return;
        const bool selfFailed = failed(ia);
        const double factor = (1.0 + limit) * (1.0 + limit);
        enum Cause : std::uint8_t { Holds, ByRule, ByStretch };
        const auto cause = [&](Index k) {
            if (intact[k] == 0) return Holds;
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            if ((rule == FailedBondRule::Either || rule == FailedBondRule::Cut) &&
                (selfFailed || failed(b)))
                return ByRule;
            if (rule == FailedBondRule::Cut && cutting && cutByFailed(ia, b)) return ByRule;
            if (rule == FailedBondRule::Both && selfFailed && failed(b)) return ByRule;
            return limit > 0.0 && stretched(ia, k, factor) ? ByStretch : Holds;
        };
        bool any = false;
        for (Index k = P.begin(a); k < P.end(a) && !any; ++k) any = cause(k) != Holds;
        if (!any) return;
        released_[ia] = internalPower(state, a);  // over the old bonds, with the old G
        const bool softens = !cohesive_.empty() && cohesive_[ia] != 0;
        for (Index k = P.begin(a); k < P.end(a); ++k) {
            const Cause c = cause(k);
            if (c == Holds) continue;
            if (c == ByStretch && softens) startSoftening(state, ia, k);
            intact[k] = 0;
            ++changed_[ia];
        }
    });
    if (cutting)
        parallelFor(ref_.size(), [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            if (newlyFailed_[ia] != 0) failedSeen_[ia] = 1;
        });
    // Both sides of a pair break in the same call: each fresh pair is counted twice.
    const double freshEntries = domain.total(exactSum(owned, [&](Index a) {
        return static_cast<double>(changed_[static_cast<std::size_t>(a)]);
    }));
    if (freshEntries == 0.0) return {};
    BondBreak result;
    result.pairs = static_cast<Index>(freshEntries) / 2;
    brokenPairs_ += result.pairs;
    // Split: the ghosts' rows from their owners, and what derives from them here.
    if (split) {
        domain.shareGhostRows(state.bondIntact);
        const std::span<const Index> ghosts = domain.ghosts();
        parallelFor(static_cast<Index>(ghosts.size()),
                    [&](Index g) { refreshParticle(state, ghosts[static_cast<std::size_t>(g)]); });
    }
    parallelFor(owned, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        if (changed_[ia] == 0) return;
        refreshParticle(state, a);
        released_[ia] = 0.5 * state.dt * (released_[ia] - internalPower(state, a));
    });
    markStale(owned);
    const ExactSum released =
        exactSum(owned, [&](Index a) { return released_[static_cast<std::size_t>(a)]; });
    result.releasedEnergy = split ? domain.total(released) : released.value();
    return result;
}

// The normal stress across the bond and its stretch, from the end of the lower index (both
// directions of the pair write the same bits); a bond not in tension breaks without cohesion.
void BrittleBonds::startSoftening(State& state, std::size_t ia, Index k) const {
    const auto ik = static_cast<std::size_t>(k);
    const auto ib = static_cast<std::size_t>(ref_.pairs.neighbor[ik]);
    const std::size_t lo = std::min(ia, ib), hi = std::max(ia, ib);
    const Vec3 d = state.x[hi] - state.x[lo];
    const double dd = d.squaredNorm();
    const double traction = d.dot(0.5 * (state.cauchy[lo] + state.cauchy[hi]) * d) / dd;
    if (!(traction > 0.0)) return;
    state.cohesiveTraction[ik] = traction;
    state.cohesiveStretch[ik] = std::sqrt(dd / (ref_.X[hi] - ref_.X[lo]).squaredNorm()) - 1.0;
}

BondView BrittleBonds::view(const State& state) const {
    if (!enabled_) return {};
    return {state.bondIntact.data(), damaged_.data(), stale_.data()};
}

}  // namespace gsph
