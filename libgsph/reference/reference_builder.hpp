// SPDX-License-Identifier: MIT
// The reference configuration of a run (particles/reference.hpp), built once: from a particle
// file, with the run's κ, then completed with what the total Lagrangian form fixes at t = 0:
// the θ-space pairs (neighbors/theta_search.hpp) and the geometry (spaces/metric.hpp: metric,
// corrected gradients, masses, and for overset layouts the band and the corrected interface
// weights of overset/). This module is the one place that decides κ and checks it against the
// κ the file's overset entries were made for; io/ only reads and writes files.
#pragma once

#include <span>

#include "io/particle_file.hpp"
#include "neighbors/theta_search.hpp"
#include "overset/interface_weights.hpp"
#include "particles/reference.hpp"

namespace gsph {

/// The reference configuration of a run from a particle file: X, θ, volume, body, space,
/// spaces, overset entries (copied as they are), the file's dimension (a 2-D run is plane
/// strain unless the caller sets dim.axisymmetric before completeReference), κ, and ρ0 per
/// particle. Derived fields (pairs, metrics, mass) are left to completeReference (mass = ρ0 ω det
/// M: docs/theory.md).
/// @param[in] densityPerBody ρ0 [kg/m³] indexed by body id; needs one entry per body.
/// @param[in] kappa h = κΔθ (DESIGN §3).
/// Throws InputError if a density is missing or not positive, κ is not positive, or κ exceeds
/// the κ the file's overset entries were selected with.
Reference buildReference(const ParticleFile& file, std::span<const double> densityPerBody,
                         double kappa);

/// Fills the derived fields of a reference that has its particles: the pairs (unless
/// ref.pairs already holds them) and the geometry (unless ref.G does). Throws InputError on
/// an invalid reference (buildPairs, computeGeometry). `progress`: the overset interface
/// weights' solve, the long part of a large band's set-up (overset/interface_weights.hpp).
void completeReference(Reference& ref, SearchMethod search = SearchMethod::CellList,
                       const InterfaceSolveProgress& progress = {});

}  // namespace gsph
