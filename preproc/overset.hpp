// SPDX-License-Identifier: MIT
// Several generalized spaces in one body (DESIGN §6): hole cutting where blocks overlap, and
// transient particles near every interface between spaces. Runs on the particles of
// convertHexMesh before they are written; docs/formats.md states the rules for users.
//
// Priority: a space's priority is that of its gmsh volumes (`--priority VOLUME=N`, default 0;
// the volumes glued into one space must agree). Of two overlapping spaces of a body, the one of
// higher priority keeps its particles; at equal priority the finer one (smaller mean cell
// volume, by more than kSpacingTie) does; spaces equal in both may not overlap.
// Hole cutting: a particle is cut when its centre X lies inside (not on the boundary of) the
// meshed region of a space of its body that outranks its own. Cutting whole cells leaves no
// gap and no overlap when the overlap is aligned with the cut space's cells; otherwise the gap
// and the doubly counted volume are measured (per pair) and reported.
// Transients: particle b is transient in space s (another space of its body) when X_b has
// lattice coordinates u in s (s's map, extended at most 2κ cells past its boundary) with
// min over s's kept particles a of |θ_s(b) − θ_a| < 2κΔθ_s; its entry stores θ_s(b) = u Δθ_s
// and ω = V_b / det(∂X/∂θ_s) (DESIGN §3).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/particle_file.hpp"
#include "space_map.hpp"

namespace gsph::preproc {

/// Spacings within this relative difference are equal for the default priority rule.
inline constexpr double kSpacingTie = 1e-2;

/// `--priority VOLUME=N`: VOLUME is a gmsh volume tag or a physical volume group's name.
struct PriorityRule {
    std::string volume;
    int priority = 0;
};

/// Ranks the spaces for hole cutting.
struct SpaceRanking {
    std::vector<int> priority;    ///< per space
    std::vector<double> spacing;  ///< per space: (mean hex volume)^(1/3) [m]
    /// True if space t outranks space s.
    bool outranks(std::size_t t, std::size_t s) const;
    /// True if neither outranks the other.
    bool tied(std::size_t t, std::size_t s) const { return !outranks(t, s) && !outranks(s, t); }
};

/// Priorities of the spaces from the rules. Throws InputError (an unknown volume, a volume
/// given two priorities) or MeshError (volumes of one space with different priorities), each
/// naming `source`.
SpaceRanking rankSpaces(const std::string& source, const HexMesh& mesh,
                        const std::vector<BlockLattice>& blocks, const GluingResult& glued,
                        const ParticleFile& particles, const std::vector<PriorityRule>& rules);

/// Particles of `space` cut because their centres lie inside `by`.
struct HoleCutReport {
    Index space = 0, by = 0;
    long particles = 0;
    double volume = 0.0;         ///< Σ exact volume of the cut particles [m³]
    double gap = 0.0;            ///< of which outside `by`: volume left uncovered [m³]
    double doubleCounted = 0.0;  ///< volume of kept particles of `space` inside `by` [m³]
};

/// Particles of `space` that are transient in `in`.
struct TransientReport {
    Index space = 0, in = 0;
    long particles = 0;
    double maxExtrapolation = 0.0;  ///< largest distance of θ past `in`'s lattice box [Δθ]
    long ambiguous = 0;             ///< located by two extensions; the nearer one kept
};

/// Maps of the spaces of bodies with more than one space (null for the others).
using SpaceMaps = std::vector<std::unique_ptr<SpaceMap>>;

/// Which particles to keep (1) and what was cut, per pair (space, a space that outranks it)
/// of one body. Throws MeshError naming `source` and the spaces' gmsh volumes
/// (`spaceVolumes`) if two tied spaces overlap or a space loses every particle.
std::vector<char> cutHoles(const std::string& source, const ParticleFile& particles,
                           const SpaceMaps& maps, const SpaceRanking& ranking,
                           const std::vector<std::vector<int>>& spaceVolumes,
                           std::vector<HoleCutReport>& reports);

/// Fills particles.overset and particles.transient (DESIGN §6) for the kept particles. Throws
/// MeshError naming `source` when a particle within reach of a space can get no valid θ there
/// (the extended map folds, det ∂X/∂θ ≤ 0, or its inverse does not converge).
void findTransients(const std::string& source, ParticleFile& particles, const SpaceMaps& maps,
                    double kappa, std::vector<TransientReport>& reports);

}  // namespace gsph::preproc
