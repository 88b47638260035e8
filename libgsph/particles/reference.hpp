// SPDX-License-Identifier: MIT
// The reference configuration: everything the total Lagrangian form fixes at t = 0
// (style habit 2). Filled by a particle source (analytic map, particle file), completed once by
// buildPairs() and computeGeometry(), then read-only for the whole run.
//
// Invariants after computeGeometry():
//   * particles are sorted by body, so each body is one contiguous range;
//   * pairs never cross bodies; pairs within one space are symmetric (b in list of a ⇔ a in
//     list of b); a pair (a, b) across spaces (b transient in a's space, DESIGN §6) is taken in
//     a's space and need not have a mirror;
//   * F = [Σ_b ω_b (X_b − X_a) ⊗ ∇W_ab] G(a)^T + outOfPlane = I to round-off (DESIGN §3).
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "particles/axisymmetry.hpp"
#include "particles/pair_list.hpp"

namespace gsph {

/// One lattice space (DESIGN §2): θ = (i+½, j+½, k+½)·Δθ, h = κΔθ.
struct LatticeSpace {
    double dtheta = 1.0;                   ///< Δθ, uniform in every index direction
    std::array<int, 3> cells = {1, 1, 1};  ///< lattice extent per index (1 in z for 2-D)
    std::array<bool, 3> periodic = {false, false, false};  ///< index closes on itself
};

/// θ-volume of one lattice cell, the quadrature weight ω = Δθ^d of DESIGN §3.
inline double thetaVolume(const Dimension& dim, const LatticeSpace& s) {
    return dim.value == 2 ? s.dtheta * s.dtheta : s.dtheta * s.dtheta * s.dtheta;
}

/// A particle's coordinates in a space other than its home space (DESIGN §6): the particle is
/// *transient* there, and the home particles of that space within one kernel support take it
/// as a neighbour, in that space's θ, with that space's quadrature weight.
struct OversetEntry {
    Index particle = 0;         ///< the transient particle
    Index space = 0;            ///< the other space
    Vec3 theta = Vec3::Zero();  ///< its θ in that space
    double omega = 0.0;         ///< θ-volume in that space: V / det(∂X/∂θ_space) (DESIGN §3)
};

/// Transient particles (DESIGN §6), as gsph-preproc stores them (docs/formats.md, /overset):
/// entry e says that particle `particle[e]` also has coordinates `theta[e]` in space `space[e]`
/// (never its home space, always a space of its body) with θ-volume `omega[e]` = V / det(∂X/∂θ)
/// of that space at the particle. Entries are sorted by (space, particle), one per pair; they
/// hold every particle within 2·kappa·Δθ of a home particle of the other space, so a run with
/// κ ≤ kappa finds all it needs here (and must itself drop the entries beyond its own 2κΔθ).
struct OversetEntries {
    std::vector<Index> particle;  ///< particle index
    std::vector<Index> space;     ///< the other space s
    std::vector<Vec3> theta;      ///< θ in space s [θ units]
    std::vector<double> omega;    ///< θ-volume in space s [θ units³]
    double kappa = 0.0;           ///< the κ the entries were selected with (0: none stored)

    std::size_t size() const { return particle.size(); }
};

/// Which volume a particle's mass ρ0 V takes (docs/theory.md "Volumes and mass").
enum class MassBasis {
    /// ω det M, the volume of the energy: inertia and stiffness see one volume; the body's mass
    /// differs from ρ0 × its meshed volume where the metric sums are one-sided or the map is
    /// strongly curved (0.3–3 % on the samples).
    QuadratureVolume,
    /// The cell's meshed volume (Reference::volume): the body's mass and momentum are exact;
    /// where V ≠ ω det M inertia and stiffness see different volumes (a bar with a section
    /// graded 4:1 carries a pulse 4.5 % fast).
    MeshVolume,
    /// ω det M times one factor per body, its meshed volume over Σ ω det M, in the energy and
    /// the mass alike: the body's mass is exact and inertia and stiffness still see one volume.
    /// A uniform factor scales every force of a body as it scales its mass (the correction G
    /// and the interface weights do not depend on it), so a body on its own moves as with
    /// QuadratureVolume; what changes is its mass against other bodies and external loads.
    NormalizedQuadratureVolume,
};

struct Reference {
    Dimension dim;
    double kappa = 1.2;                                           ///< h = κΔθ (DESIGN §3)
    MassBasis massBasis = MassBasis::NormalizedQuadratureVolume;  ///< set before computeGeometry
    std::vector<LatticeSpace> spaces;

    // Per particle, from the particle source.
    std::vector<Vec3> X;          ///< reference position [m]
    std::vector<Vec3> theta;      ///< coordinates in the home space [θ units]
    std::vector<double> density;  ///< ρ0 [kg/m³]
    std::vector<double> volume;   ///< exact cell volume from the map or mesh [m³] (per m in 2-D)
    /// The cell's meshed volume as the run sees it: `volume`, or in an axisymmetric run its ring,
    /// 2πR × the cell's area [m³].
    double meshVolume(std::size_t a) const {
        return dim.axisymmetric ? ringFactor(X[a]) * volume[a] : volume[a];
    }
    std::vector<Index> body;            ///< body id; particles sorted by it
    std::vector<Index> space;           ///< home space id
    std::vector<OversetEntry> overset;  ///< transient coordinates (empty: one space per body)
    /// κ the overset entries were selected with (gsph-preproc --overset-kappa; 0: not stored).
    /// A run needs κ ≤ this, or pairs near an interface would be missing.
    double oversetKappa = 0.0;

    // Derived once (computeGeometry).
    std::vector<double> omega;  ///< θ-volume ω = Δθ^d (DESIGN §3; folded into pairs.table)
    std::vector<Mat3> G;        ///< Q^T B^{-T}: maps ∇_θ W_ab to the physical g_ab
    /// V = ω det M (times the body's factor with NormalizedQuadratureVolume): the volume in the
    /// energy Σ V Ψ(F) (DESIGN §4)
    std::vector<double> quadVolume;
    /// ρ0 V, V by massBasis [kg]
    std::vector<double> mass;
    std::vector<double> spacing;  ///< smallest physical particle spacing Δθ·σ_min(M) [m]
    std::vector<double> smoothingLength;  ///< physical h = κΔθ (det M)^{1/d} [m] (viscosity)
    std::vector<double> metricCondition;  ///< condition number of M = ∂X/∂θ
    PairList pairs;
    /// Per particle (computeGeometry, DESIGN §6): kBandInterior if it lies within two kernel
    /// supports of the coarser side of an overset interface (the *band*: its weights are
    /// corrected so that uniform and linear stress give the exact force there,
    /// overset/interface_weights.hpp), kBandNearFreeFace if it does but its support reaches a
    /// free face (its weights are corrected for consistency only: the surface takes up what
    /// the interface leaves), else 0. Empty without overset.
    static constexpr std::uint8_t kBandInterior = 1, kBandNearFreeFace = 2;
    std::vector<std::uint8_t> oversetBand;
    bool inOversetBand(Index a) const {
        return !oversetBand.empty() && oversetBand[static_cast<std::size_t>(a)] == kBandInterior;
    }
    /// Pairs across spaces need not have a mirror, so the pairwise form takes their transposed
    /// term from the other side's list: for each particle c, the pairs k = (b, c) of other
    /// spaces' lists that hold c (CSR crossOffset[c] … crossOffset[c+1] into crossPair, with
    /// crossOwner = b). Empty without overset.
    std::vector<Index> crossOffset, crossPair, crossOwner;
    /// Per particle: 1 if it has a pair across spaces, in its own list or another's, or lies in
    /// the band: it takes the CSR path. Empty without overset.
    std::vector<std::uint8_t> oversetCoupled;
    bool isOversetCoupled(Index a) const {
        return !oversetCoupled.empty() && oversetCoupled[static_cast<std::size_t>(a)] != 0;
    }

    /// Interface weights (overset/interface_weights.hpp): for a particle a with
    /// correctionBegin[a] ≥ 0, pair k of its list adds pairCorrection[correctionBegin[a] + k −
    /// pairs.begin(a)] to its table gradW (θ units), and mirrorCorrection at the same slot holds
    /// the correction of the mirror pair (b, a) of a same-space pair (zero across spaces). Empty
    /// without an overset band.
    std::vector<Index> correctionBegin;
    std::vector<Vec3> pairCorrection, mirrorCorrection;
    /// How the interface weights' solve went: the band's constraint rows, the conjugate-gradient
    /// iterations and the relative residual reached (all 0 without a band). Most of a large
    /// O-grid's set-up, so a run's log reports it.
    struct InterfaceSolve {
        Index rows = 0;
        int iterations = 0;
        double residual = 0.0;
    } interfaceSolve;
    /// Particle a's corrections along its list, or null when it has none.
    const Vec3* pairCorrections(Index a) const {
        if (correctionBegin.empty() || correctionBegin[static_cast<std::size_t>(a)] < 0)
            return nullptr;
        return pairCorrection.data() + correctionBegin[static_cast<std::size_t>(a)];
    }
    const Vec3* mirrorCorrections(Index a) const {
        if (correctionBegin.empty() || correctionBegin[static_cast<std::size_t>(a)] < 0)
            return nullptr;
        return mirrorCorrection.data() + correctionBegin[static_cast<std::size_t>(a)];
    }

    Index size() const { return static_cast<Index>(X.size()); }
};

/// "particle 12 at X = (…) m, t = … s": how a NumericalError names a particle.
inline std::string describeParticle(const Reference& ref, Index a, double time) {
    const Vec3& X = ref.X[static_cast<std::size_t>(a)];
    char text[160];
    std::snprintf(text, sizeof text, "particle %d at X = (%.6g, %.6g, %.6g) m, t = %.6e s", a, X[0],
                  X[1], X[2], time);
    return text;
}

}  // namespace gsph
