// SPDX-License-Identifier: MIT
// Internal force of the total Lagrangian form (DESIGN §4), = −∂E/∂x of E = Σ_a V_a Ψ(F(a)):
//   f_c = Σ_b [V_c ω_b P(c) g_cb − V_b ω_c P(b) g_bc] = Σ_b (ω_b K_c + ω_c K_b) ∇W_cb,
// with K = V P G and P = J σ F^{-T} (using g_ab = G(a) ∇W_ab and ∇W_bc = −∇W_cb). Each
// particle gathers from its own list only (no scatter), so the loop is thread-count-independent
// and Σ_c f_c = 0 to round-off. Artificial viscosity adds the pair pressure q_cb through
// N = V J F^{-T} G the same way; hourglass control adds central pair forces.
//
// Speed: particles in stencil blocks (neighbors/stencil_blocks.hpp) run the pair
// terms stencil entry by stencil entry across the block on SoA fields, vectorised across
// particles; the other particles take their CSR lists, staged as SoA weights
// (neighbors/staged_pairs.hpp) and vectorised across each particle's pairs (their far ends'
// fields read as rows, neighbors/pair_field_rows.hpp). Both evaluate the
// same pair formulas (forces/artificial_viscosity.hpp, forces/hourglass.hpp) in fixed orders; the
// block a particle belongs to is fixed at setup, so results stay independent of the thread count
// and the strip width. Allocation-free once the per-thread staging buffers have grown.
//
// Overset (DESIGN §6): a pair across spaces has no mirror, so its transposed term is read from
// the other side's list (Reference::crossPair). Near an interface the weights carry the
// corrections of overset/interface_weights.hpp, so the stress force stays −∂E/∂x (momentum
// and energy conserved to round-off) and is exact for uniform and linear stress there too.
#pragma once

#include <vector>

#include "core/soa_field.hpp"
#include "failure/brittle_bonds.hpp"
#include "forces/artificial_viscosity.hpp"
#include "forces/force_stage.hpp"  // ForceParts
#include "forces/hourglass.hpp"
#include "neighbors/pair_field_rows.hpp"
#include "neighbors/staged_pairs.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// Per-particle quantities the force loop reads, derived from F and σ each step.
struct StressFactors {
    Mat3Field K;                     ///< V J σ F^{-T} G
    Mat3Field N;                     ///< V J F^{-T} G
    std::vector<double> soundSpeed;  ///< c [m/s]
    std::vector<double> density;     ///< ρ0/J [kg/m³]
    /// α of the viscosity's compression switch (forces/artificial_viscosity.hpp; 1 when off)
    std::vector<double> viscositySwitch;
    /// s_a of the hourglass penalty in plastic flow (forces/hourglass.hpp; 1 elastic)
    std::vector<double> hourglassScale;
    void resize(std::size_t n) {
        K.resize(n);
        N.resize(n);
        soundSpeed.resize(n);
        density.resize(n);
        viscositySwitch.assign(n, 1.0);
        hourglassScale.assign(n, 1.0);
    }
};

/// SoA copies of the kinematic fields the pair terms read (the State keeps its own layout for
/// checkpoints); the integrator refreshes x, v and F each step, X once.
struct ParticleFields {
    Vec3Field X;  ///< reference position [m]
    Vec3Field x;  ///< current position [m]
    Vec3Field v;  ///< velocity [m/s]
    Mat3Field F;  ///< deformation gradient
    void resize(std::size_t n) {
        X.resize(n);
        x.resize(n);
        v.resize(n);
        F.resize(n);
    }
};

struct ForceOptions {
    ViscosityCoefficients viscosity;
    double hourglass = 0.0;      ///< α (0 = off)
    double youngsModulus = 0.0;  ///< E of the body, scales the hourglass penalty [Pa]
    /// E throughout, or × ½(s_a + s_b) of StressFactors::hourglassScale (forces/hourglass.hpp)
    HourglassModulus hourglassModulus = HourglassModulus::Elastic;
};

/// f_c for the particles of one body, partitioned into `blocks` (built from ref.pairs).
/// Writes force[c]; parts.* only when that term is on (sized by the caller: ref.size()).
/// Broken bonds (`bonds`) leave every pair term; a block with a damaged particle takes the
/// CSR path, and so do particles with interface weight corrections (ref.pairCorrections), which
/// apply while a particle keeps all its bonds. G per particle from `G` (null: ref.G). `staged`:
/// the body's CsrPairWeights (null: staged here each time; same result). `rows`: with `staged`,
/// read by the CSR blocks' gathered runs (null: they gather from the SoA fields; the same
/// result); its slots from kMotionSlots to kSlotReferenceX are refreshed here for
/// staged->gathered, its x and v must hold `fields` x and v there (refreshMotionRows, after the
/// drift) and its X the reference positions (refreshReferenceRows, once).
void internalForce(const Reference& ref, const ParticleFields& fields, const StressFactors& factors,
                   const StencilBlocks& blocks, const ForceOptions& options,
                   std::vector<Vec3>& force, ForceParts& parts, const BondView& bonds = {},
                   const Mat3* G = nullptr, const CsrPairWeights* staged = nullptr,
                   PairFieldRows* rows = nullptr);

/// Copies x and v of the particles the CSR blocks' runs read (staged.gathered) from `fields`
/// into their rows (n: the particle count): after the drift, before the θ-gradients
/// (kinematics/deformation_gradient.hpp) and internalForce read them.
void refreshMotionRows(PairFieldRows& rows, const ParticleFields& fields,
                       const CsrPairWeights& staged, std::size_t n);

/// Copies the reference positions X of the same particles into their rows, once the runs are
/// staged (reference data: never refreshed again).
void refreshReferenceRows(PairFieldRows& rows, const ParticleFields& fields,
                          const CsrPairWeights& staged, std::size_t n);

}  // namespace gsph
