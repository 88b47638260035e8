// SPDX-License-Identifier: MIT
// The hoop stress's force in an axisymmetric run (particles/axisymmetry.hpp; docs/theory.md
// "Axisymmetric runs"): the energy Σ_a V_a Ψ(F_a) depends on x_a through the hoop stretch
// F_zz = r_a/R_a too, which adds to the internal force
//   f_a −= V_a P_zz(a) / R_a e_r,   P_zz = J σ_zz / F_zz,
// so f_a·v_a books exactly the hoop part V J σ_zz v_r/r of the stress power. A composed stage
// right after the internal force; each particle writes only its own force.
#pragma once

#include "forces/force_stage.hpp"
#include "particles/reference.hpp"

namespace gsph {

class HoopStressStage final : public ForceStage {
  public:
    /// Throws InputError unless `ref` is axisymmetric. `ref` must outlive the stage.
    explicit HoopStressStage(const Reference& ref);
    std::string name() const override { return "hoop stress"; }
    StageReport addForces(const State& state, ForceChannels& out) override;

  private:
    const Reference& ref_;
};

}  // namespace gsph
