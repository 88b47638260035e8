// SPDX-License-Identifier: MIT
#include "forces/internal_force_stage.hpp"

namespace gsph {

InternalForceStage::InternalForceStage(const Reference& ref, std::vector<double> youngsModulus,
                                       const ParticleFields& fields, const StressFactors& factors,
                                       const std::vector<StencilBlocks>& blocks,
                                       const std::vector<CsrPairWeights>& staged,
                                       PairFieldRows& rows, ViscosityCoefficients viscosity,
                                       double hourglass, HourglassModulus modulus,
                                       const BrittleBonds& bonds)
    : ref_(ref),
      youngsModulus_(std::move(youngsModulus)),
      fields_(fields),
      factors_(factors),
      blocks_(blocks),
      staged_(staged),
      viscosity_(viscosity),
      hourglass_(hourglass),
      modulus_(modulus),
      bonds_(bonds),
      rows_(rows) {}

StageNeeds InternalForceStage::needs() const {
    StageNeeds needs;
    needs.viscous = viscosity_.enabled();
    needs.hourglass = hourglass_ != 0.0;
    return needs;
}

StageReport InternalForceStage::addForces(const State& state, ForceChannels& out) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        ForceOptions options;
        options.viscosity = viscosity_;
        options.hourglass = hourglass_;
        options.youngsModulus = youngsModulus_[b];
        options.hourglassModulus = modulus_;
        internalForce(ref_, fields_, factors_, blocks_[b], options, out.force, out.parts,
                      bonds_.view(state), bonds_.G().data(), &staged_[b], &rows_);
    }
    return {};
}

}  // namespace gsph
