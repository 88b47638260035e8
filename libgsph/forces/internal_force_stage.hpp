// SPDX-License-Identifier: MIT
// The internal force (with artificial viscosity and hourglass control) as the first force stage
// of the step (forces/force_stage.hpp): for each body, internalForce() of
// forces/internal_force.hpp over its stencil and CSR blocks, from the factors K, N and the SoA
// fields the kinematics stage left (integrator/stress_update.hpp). It sets `force` (every
// particle belongs to one body), so later stages add to it; viscosity and hourglass control
// write their parts into the viscous and hourglass channels for the energy ledger. The CSR
// blocks' gathered runs read their far ends' fields from rows (neighbors/pair_field_rows.hpp).
#pragma once

#include <vector>

#include "failure/brittle_bonds.hpp"
#include "forces/force_stage.hpp"
#include "forces/internal_force.hpp"
#include "neighbors/stencil_blocks.hpp"
#include "particles/reference.hpp"

namespace gsph {

class InternalForceStage final : public ForceStage {
  public:
    /// Reads `fields`, `factors`, `blocks` and `staged` (one per body) and the bonds at every
    /// evaluation, and `rows`, whose x and v the caller refreshes before each
    /// (refreshMotionRows); they must outlive the stage. `youngsModulus`: E per body, as
    /// `blocks` (scales the hourglass penalty) [Pa]; `modulus`: the penalty's in plastic flow
    /// (forces/hourglass.hpp).
    InternalForceStage(const Reference& ref, std::vector<double> youngsModulus,
                       const ParticleFields& fields, const StressFactors& factors,
                       const std::vector<StencilBlocks>& blocks,
                       const std::vector<CsrPairWeights>& staged, PairFieldRows& rows,
                       ViscosityCoefficients viscosity, double hourglass, HourglassModulus modulus,
                       const BrittleBonds& bonds);

    std::string name() const override { return "internal force"; }
    StageNeeds needs() const override;
    StageReport addForces(const State& state, ForceChannels& out) override;

  private:
    const Reference& ref_;
    std::vector<double> youngsModulus_;
    const ParticleFields& fields_;
    const StressFactors& factors_;
    const std::vector<StencilBlocks>& blocks_;
    const std::vector<CsrPairWeights>& staged_;  ///< per body, as blocks_
    ViscosityCoefficients viscosity_;
    double hourglass_;
    HourglassModulus modulus_;
    const BrittleBonds& bonds_;
    PairFieldRows& rows_;  ///< the gathered runs' far ends, refreshed body by body
};

}  // namespace gsph
