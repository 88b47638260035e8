// SPDX-License-Identifier: MIT
// Steps 3–4 of Algorithm 1 (DESIGN §4), fused per particle and run block by block (stencil
// blocks vectorise the θ-gradient sums, neighbors/stencil_blocks.hpp):
//   3. F_{n+1} from x_{n+1}, Ḟ from v_{n+½}; L = Ḟ F_{n+½}^{-1}, F_{n+½} = ½(F_n + F_{n+1})
//   4. σ_{n+1} by the body's material (Jaumann rate), P = J σ F^{-T}; models with a history
//      (Johnson–Cook) also advance ε̄p, T, D, e (a nonlocal damage from the average of its
//      drivers at t_n, failure/nonlocal_damage.hpp), add their plastic work to the particle's
//      (State::plasticWork) and give the energy lost by failing particles; a particle detached by
//      broken bonds releases the elastic energy its stress held as fracture energy
//      (failure/brittle_bonds.hpp)
// and from F_{n+1}, σ_{n+1} the factors the internal force reads (K = V P G, N = V J F^{-T} G,
// sound speed, density, the viscosity's compression switch α from tr D) and each particle's
// current spacing ℓ_a for the time step.
// Reads the SoA x, v that pack() copied during the drift. Allocation-free after construction.
// Keeps nothing across steps that the State does not hold.
#pragma once

#include <cstdint>
#include <vector>

#include "distributed/domain.hpp"
#include "failure/brittle_bonds.hpp"
#include "failure/nonlocal_damage.hpp"
#include "forces/hourglass.hpp"
#include "forces/internal_force.hpp"
#include "integrator/body_range.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

class StressUpdate {
  public:
    /// `bodies` and `bonds` must outlive it; `viscosity` sets the compression switch,
    /// `hourglass` how plastic flow scales the hourglass penalty (forces/hourglass.hpp).
    StressUpdate(const Reference& ref, const std::vector<BodyRange>& bodies,
                 const BrittleBonds& bonds, const ViscosityCoefficients& viscosity = {},
                 HourglassModulus hourglass = HourglassModulus::Elastic);

    /// SoA copies of x_a and v_a for the stencil loops.
    void pack(const State& state, Index a) {
        const auto ia = static_cast<std::size_t>(a);
        fields_.x.set(ia, state.x[ia]);
        fields_.v.set(ia, state.v[ia]);
    }
    /// Steps 3–4 over Δt (atRest: only the factors, from the current F and σ: initialisation).
    /// Throws NumericalError naming the first particle that inverted (J ≤ 0) or whose F or σ is
    /// not finite.
    void advance(State& state, double dt, bool atRest);
    /// Adds this step's failure losses and fracture energy of detached particles of the
    /// `owned` particles, summed over the domain's processes, to the state's ledger, in a fixed
    /// order (the plastic work is booked per particle by advance).
    void bookDissipation(State& state, ParticleRange owned, Domain& domain);
    /// Keeps only the blocks of the `owned` particles (a range distributed/halo_plan.hpp cut
    /// between blocks or inside a strided one): advance() and the force loops then run on those
    /// alone.
    void restrictTo(ParticleRange owned);

    const StressFactors& factors() const { return factors_; }
    const ParticleFields& fields() const { return fields_; }
    /// For the exchange of the ghosts' columns (distributed/domain.hpp).
    StressFactors& factors() { return factors_; }
    ParticleFields& fields() { return fields_; }
    /// Per body: its stencil and CSR blocks.
    const std::vector<StencilBlocks>& blocks() const { return blocks_; }
    /// Per body, as blocks(): its CSR particles' pairs staged once (neighbors/staged_pairs.hpp).
    const std::vector<CsrPairWeights>& staged() const { return staged_; }
    /// The CSR blocks' far ends' fields as rows, x and v current after advance() (the internal
    /// force refreshes the rest and reads them).
    PairFieldRows& rows() { return rows_; }
    /// Current spacing ℓ_a of each particle [m].
    const std::vector<double>& lengthScale() const { return lengthScale_; }
    /// Whether some body's damage is nonlocal: advance() then reads the damage driver of every
    /// particle within its material length (driverReads), ghosts included.
    bool averagesDriver() const { return !averagedDriver_.empty(); }
    /// The particles whose damage driver a particle's nonlocal average reads (none outside a
    /// body with a nonlocal damage).
    Reads driverReads() const;

  private:
    void throwOnFailure(const State& state) const;
    /// Stages body b's CSR pairs from blocks_[b] and writes their far ends' X into the rows.
    void stageRuns(std::size_t b);

    const Reference& ref_;
    const std::vector<BodyRange>& bodies_;
    const BrittleBonds& bonds_;
    ViscosityCoefficients viscosity_;
    HourglassModulus hourglass_;
    StressFactors factors_;
    ParticleFields fields_;
    std::vector<StencilBlocks> blocks_;
    std::vector<CsrPairWeights> staged_;
    /// The CSR blocks' far ends' fields (neighbors/pair_field_rows.hpp): x and v refreshed here,
    /// the rest by the internal force.
    PairFieldRows rows_;
    std::vector<double> lengthScale_;
    std::vector<std::uint8_t> failure_;  ///< per particle: why the update failed (0: it did not)
    /// Per particle, this step's failure loss [J] (sized only when a body's model tracks a
    /// history).
    std::vector<double> damageDissipation_;
    /// Per particle, the elastic energy released when it was detached [J] (sized only when
    /// bonds can break; written by the detaching step alone, zero before and after it).
    std::vector<double> fractureEnergy_;
    std::vector<ExactSum> dissipated_;  ///< scratch of bookDissipation: per body, then fracture
    /// Per body, the nonlocal average of its damage driver (empty for local damage), and per
    /// particle the averages of this step (sized only when a body's damage is nonlocal).
    std::vector<NonlocalAverage> nonlocal_;
    std::vector<double> averagedDriver_;
    ParticleRange owned_;  ///< the particles advance() updates (restrictTo)
};

}  // namespace gsph
