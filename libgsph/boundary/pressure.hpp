// SPDX-License-Identifier: MIT
// Pressure on a particle set, a follower load (docs/case-format.md, [[set]] pressure). Each
// particle of the set carries the outward area vector A_a of its cell's faces on the loaded
// surface in the reference configuration (the particle file's /set_areas, written by
// gsph-preproc), and feels
//   f_a = −p(t) J_a F_a^{-T} A_a = −p(t) (cof F_a) A_a
// (Nanson's formula: the faces' current area vector as the particle's F deforms them), so the
// load follows the surface as it turns and stretches. p(t) is piecewise linear through a table
// of (t, p) points, constant before the first and after the last. Its power Σ f·v is external
// work (the external channel, forces/force_stage.hpp). Each particle writes only its own force.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "forces/force_stage.hpp"
#include "particles/reference.hpp"

namespace gsph {

struct PressureLoad {
    std::string name;              ///< the particle set's name (for messages)
    std::vector<Index> particles;  ///< sorted, unique
    /// per particle of the set: A_a [m²] (per metre in plane strain; in an axisymmetric run the
    /// ring its faces sweep, Σ_faces 2π r_f A_f with r_f the face's centroid radius)
    std::vector<Vec3> area;
    /// (t [s], p [Pa]) with t strictly increasing; one point: a constant pressure.
    std::vector<std::pair<double, double>> curve;

    /// p(t) [Pa].
    double at(double t) const;
};

class PressureStage final : public ForceStage {
  public:
    /// Throws InputError naming the set on an empty set or curve, indices out of range or not
    /// sorted, areas that do not match the particles or are not finite, or times that do not
    /// increase.
    PressureStage(const Reference& ref, PressureLoad load);
    std::string name() const override { return "pressure on '" + load_.name + "'"; }
    StageNeeds needs() const override { return {.external = true}; }
    StageReport addForces(const State& state, ForceChannels& out) override;
    const PressureLoad& load() const { return load_; }

  private:
    PressureLoad load_;
};

}  // namespace gsph
