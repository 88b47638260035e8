// SPDX-License-Identifier: MIT
// Brittle bond failure (DESIGN §5, the paper's Rankine criterion): the bond of a pair (a, b)
// breaks for good when its stretch (|x_b − x_a| − |X_b − X_a|) / |X_b − X_a| ≥ εmax, εmax an
// input per body (0: the body's bonds never break). A broken bond leaves every pair sum of
// the step (F, Ḟ, the force, viscosity, hourglass control), and the particle's metric
// (B, M, G of spaces/metric.hpp) is recomputed over the surviving bonds, so F = I stays
// exact at rest and an affine motion still gives its F (DESIGN §3).
//
// The integrity lives in State::bondIntact (per CSR pair, checkpointed); this class keeps
// what derives from it: G per particle, which particles lost a bond (they leave the stencil
// fast path for the masked CSR path), and which are detached (their surviving bonds no
// longer span the space: |det B| fell below kDetachedCorrection of its intact value, or M
// inverts; with FailedBondRule::Cut, also once G has grown fourfold, kDetachedStepFactor). A
// detached particle carries no stress and keeps its last F; its surviving bonds still move it with
// its neighbours.
//
// Both directions of a pair evaluate the same stretch from the same positions, so a and b
// always agree without writing each other's entries: the check runs in parallel and gives the
// same result for any thread count.
//
// Failed particles (ductile fracture): a body may also break bonds by Johnson–Cook
// damage (State::damage, FailedBondRule per particle): with Either, the bond of a pair (a, b)
// breaks for good once a or b has failed (D ≥ 1); with Both, once a and b have. Both sides
// evaluate the same rule from the same damages, so they agree as for the stretch. A failed
// particle carries no deviatoric stress and no tension (materials/plastic_solid.hpp), but its
// bonds still tie the two sides of a shear band together. With Either it loses every bond and
// is detached: it keeps its mass and momentum, meets other bodies through contact, and no longer
// ties the pieces together. With Both, a band of failed particles at least two wide cuts the
// bonds across it, and a single failed particle inside sound material keeps its bonds. With Cut,
// as with Either, and the bond of any pair (b, c) also breaks once its reference segment passes
// through the cell of a failed particle f (within kCutRadius, measured in f's cells: the offset
// from X_f mapped by (Δθ M_f)^{-1}, so a cell stretched by the layout is cut along its own
// sizes, not within a sphere of its smallest spacing): a band of failed
// particles one wide, narrower than the kernel support, then cuts the load path across it (with
// Either the sound particles on both sides of such a band keep the bonds that span it, and the
// sliding of the two sides shears their F without bound). The candidates f are the failed
// neighbours of b and of c (a failed particle that close to the segment is a neighbour of one
// end); only particles that failed since the last call are tried, since a bond that an earlier
// failure did not cut stays uncut by it. No particle is removed. The damage of t_n decides at
// the drift of step n+1.
//
// Energy released (docs/theory.md "Fracture energy"): the step that breaks bonds kicks with
// the old bonds' force f_n in its first half and the new bonds' in its second, while the
// stress advances with the new bonds' Ḟ. Against a step whose bonds had broken at t_n, its
// kinetic energy changes by ½Δt (f_n^old − f_n^new)·v_{n+½} = ½Δt Σ_a (K_a^new : ∇v_a^new −
// K_a^old : ∇v_a^old), using Σ_a f_a·v_a = −Σ_a K_a : ∇v_a (exact for the pair force of
// forces/internal_force.hpp over any symmetric bond set), K = V J σ F^{-T} G and ∇v the
// θ-gradient of v_{n+½} over the bonds. Only particles that lost a bond contribute; the
// negative of that change is the energy the broken pairs take out of the motion, booked as
// fracture energy. (The overset band's difference form is outside this identity.)
//
// Softening bonds (forces/cohesive_bonds.hpp): in a body with a fracture energy, a bond broken
// by its stretch leaves the pair sums as any other, and its pair starts to carry a cohesive
// force: the call records in State::cohesiveTraction the normal stress n·σ̄·n across it (σ̄ the
// mean of the two particles' σ_n, n along x_b − x_a; > 0 only, a bond not in tension breaks
// without cohesion) and in State::cohesiveStretch its stretch. Bonds broken by failed particles
// or initial cracks carry none.
//
// Initial cracks (a sharp notch, docs/theory.md "Initial cracks"): the bonds of every pair whose
// reference segment X_a → X_b crosses a planar patch start broken (breakBondsAcross); attach()
// then derives G, damaged and detached exactly as after a break. A reference position on the
// patch's plane counts on the side its normal edge1 × edge2 points to, so a row of particles
// lying on the notch line belongs to one face, and the decision depends on the pair, not on
// which side evaluates it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "distributed/domain.hpp"
#include "particles/bond_view.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// When Johnson–Cook damage breaks the bond of a pair (a, b) (see above).
enum class FailedBondRule : std::uint8_t {
    Keep = 0,    ///< never: failed particles keep their bonds
    Either = 1,  ///< once a or b has failed (D ≥ 1)
    Both = 2,    ///< once a and b have failed
    /// As Either, and also once the reference segment X_a → X_b passes within kCutRadius cells
    /// of a failed third particle f (in f's lattice, (Δθ M_f)^{-1}(X − X_f)): a band of
    /// failed particles one wide cuts every bond across it (see above).
    Cut = 3,
};

/// Cut: a failed particle f cuts the bonds whose reference segment passes closer to X_f than
/// this many of f's cells (offsets mapped to f's lattice by (Δθ M_f)^{-1}). 0.6 cuts every bond of
/// the kernel support (2.4 cells) across a plane of failed particles of a cubic lattice (the worst
/// crossing passes 0.577 Δx from the nearest lattice point of the plane) and no bond between two
/// particles on one side.
inline constexpr double kCutRadius = 0.6;

/// True when the segment p → q passes within `radius` of f. Evaluate it with p the end of the
/// lower index, so that both sides of a pair compute the same bits.
bool segmentPassesNear(const Vec3& p, const Vec3& q, const Vec3& f, double radius);

/// What one call of breakStretchedBonds did.
struct BondBreak {
    Index pairs = 0;              ///< pairs (a < b) broken by the call
    double releasedEnergy = 0.0;  ///< ½Δt Σ_a (K^old:∇v^old − K^new:∇v^new) [J] (see above)
};

/// A planar crack present at t = 0: the parallelogram corner + s·edge1 + t·edge2, s, t ∈ [0, 1]
/// (reference configuration; edge1 × edge2 ≠ 0 is its normal).
struct CrackPatch {
    Vec3 corner = Vec3::Zero();
    Vec3 edge1 = Vec3::UnitX();
    Vec3 edge2 = Vec3::UnitZ();
};

/// Patch coordinates s, t within this of [0, 1] count as on the patch (edges included robustly).
inline constexpr double kPatchEdgeTolerance = 1e-9;

/// True when the reference segment from `from` to `to` crosses the patch: the ends lie on
/// opposite sides of its plane (a point on the plane is on the side of the normal) and the
/// segment meets the plane inside the parallelogram, edges included to kPatchEdgeTolerance (in
/// the patch coordinates s, t). Symmetric in its ends.
bool segmentCrossesPatch(const CrackPatch& patch, const Vec3& from, const Vec3& to);

/// Clears bondIntact of every CSR pair (a, b) whose reference segment crosses one of the
/// patches (both directions of a pair alike); returns the pairs newly broken, counted as
/// entries (a, b) with a < b like BrittleBonds::brokenPairs. Throws InputError on a degenerate
/// patch (edge1 × edge2 = 0) or a flag array that does not match the pairs.
Index breakBondsAcross(const Reference& ref, const std::vector<CrackPatch>& patches,
                       std::vector<std::uint8_t>& bondIntact);

class BrittleBonds {
  public:
    /// |det B| of a particle's surviving bonds below this fraction of its intact value: detached.
    static constexpr double kDetachedCorrection = 1e-3;
    /// In a body with FailedBondRule::Cut, a particle is also detached once ‖G_ref‖_F / ‖G‖_F
    /// falls below this: its surviving bonds leave F ill-conditioned (a particle next to a plane
    /// cut keeps 0.63–0.66, measured), and its stiffness, growing as ‖G‖², sets the time step of
    /// the whole run (plate perforation without it: G 5–12× its intact size, Δt 40× below Δt0).
    static constexpr double kDetachedStepFactor = 0.25;

    /// `stretchByParticle`: εmax of each particle's body (0 = unbreakable), from the body ranges;
    /// `failedRuleByParticle` (empty: Keep everywhere): the particle's body's FailedBondRule.
    /// `precracked`: the state may start with broken bonds (initial cracks), so the bonds are
    /// tracked even when no body can break. `cohesiveByParticle` (empty: none): 1 where the
    /// particle's body has a fracture energy, so that its bonds broken by stretch soften (the
    /// state then holds cohesiveTraction and cohesiveStretch, one per pair). Throws InputError on
    /// a negative or non-finite εmax or a size mismatch.
    BrittleBonds(const Reference& ref, std::vector<double> stretchByParticle,
                 std::vector<FailedBondRule> failedRuleByParticle = {}, bool precracked = false,
                 std::vector<std::uint8_t> cohesiveByParticle = {});

    bool enabled() const { return enabled_; }

    /// Derives G, damaged and detached from state.bondIntact (at the start and after a restart).
    void attach(const State& state);

    /// Breaks every bond stretched to εmax at the current positions state.x (x_{n+1}), and every
    /// bond its body's FailedBondRule breaks (state.damage ≥ 1), updates what
    /// derives from it; returns the pairs broken and the energy they release, from state.v
    /// (v_{n+½}), state.F and state.cauchy (F_n, σ_n) and the step state.dt.
    BondBreak breakStretchedBonds(State& state);
    /// The same for a run split over processes (distributed/domain.hpp): breaks the bonds of the
    /// `owned` particles, whose neighbours' x, v, damage (and σ, with softening bonds) the
    /// ghost exchanges have brought; then takes the ghosts' bond rows from their owners. The
    /// pairs and the released energy returned are every process's (the energy summed in
    /// process order). Collective: every process calls it at the same step.
    BondBreak breakStretchedBonds(State& state, ParticleRange owned, Domain& domain);
    /// True when some body's bonds break by Johnson–Cook damage (FailedBondRule other than Keep).
    bool breaksByDamage() const { return breaksByDamage_; }

    /// G per particle: the reference's until a bond of the particle breaks.
    const std::vector<Mat3>& G() const { return enabled_ ? G_ : ref_.G; }
    bool detached(Index a) const { return enabled_ && detached_[static_cast<std::size_t>(a)] != 0; }
    /// True for a particle of a body with a FailedBondRule other than Keep that has lost a bond:
    /// its F is advanced by F_{n+1} = F_n + Δt Ḟ instead of being taken from x_{n+1} over its
    /// surviving bonds. Over a different set of bonds a non-affine motion gives another F, and
    /// a pressure that is a function of J (the equations of state of Johnson–Cook bodies) would
    /// jump with it, creating energy (docs/theory.md "Ductile fracture").
    /// Stable-step length factor of particle a, min(1, ‖G_ref‖_F / ‖G‖_F): a particle whose
    /// surviving bonds leave its correction ill-conditioned has a larger G, and its pair forces
    /// a stiffness that grows as ‖G‖² (the time step scales its length by this). 1 outside the
    /// bodies with a FailedBondRule other than Keep.
    double stepFactor(Index a) const {
        return enabled_ ? stepFactor_[static_cast<std::size_t>(a)] : 1.0;
    }
    bool integratesF(Index a) const {
        const auto ia = static_cast<std::size_t>(a);
        return enabled_ && damaged_[ia] != 0 && failedRule_[ia] != FailedBondRule::Keep;
    }
    BondView view(const State& state) const;
    /// Pairs (a < b) broken so far.
    Index brokenPairs() const { return brokenPairs_; }

  private:
    void refreshParticle(const State& state, Index a);
    /// Derives stale_ of `particles` from damaged_ (BondView::stale).
    void markStale(ParticleRange particles);
    /// Records the softening of the pair at CSR entry k of particle ia (see above).
    void startSoftening(State& state, std::size_t ia, Index k) const;
    /// K : ∇v of particle a over its surviving bonds with its current G (0 when detached).
    double internalPower(const State& state, Index a) const;

    const Reference& ref_;
    std::vector<double> stretch_;             ///< εmax per particle
    std::vector<FailedBondRule> failedRule_;  ///< per particle
    std::vector<std::uint8_t> cohesive_;      ///< per particle (empty: none), see above
    bool enabled_ = false;
    std::vector<Mat3> G_;
    std::vector<std::uint8_t> damaged_, detached_;
    std::vector<std::uint8_t> stale_;       ///< per particle: BondView::stale
    std::vector<Index> changed_;            ///< per particle: bonds broken by the current call
    std::vector<double> released_;          ///< per particle: its share of the released energy
    std::vector<double> intactDetB_;        ///< |det B| with every bond, per particle
    std::vector<double> stepFactor_;        ///< per particle, see stepFactor
    std::vector<std::uint8_t> failedSeen_;  ///< Cut: failed at the last call (D ≥ 1)
    std::vector<std::uint8_t> newlyFailed_, nearNewlyFailed_;  ///< Cut: scratch of one call
    /// Cut, split runs: per pair, whether its neighbour failed since the last call (scratch).
    std::vector<std::uint8_t> neighbourFailed_;
    std::vector<Mat3> cellFrame_;  ///< Cut: (Δθ M)^{-1} per particle, physical → cell units
    bool anyCut_ = false;          ///< some body's rule is Cut
    bool breaksByDamage_ = false;  ///< some body's rule is not Keep
    Index brokenPairs_ = 0;
};

}  // namespace gsph
