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
// Transients: particle b is transient in space s (another space of its body) when it has
// lattice coordinates u in s with min over s's kept particles a of |θ_s(b) − θ_a| < 2κΔθ_s; its
// entry stores θ_s(b) = u Δθ_s and ω = V_b / det(∂X/∂θ_s) (DESIGN §3). Two ways give u:
// - the extended map: X_b located in s's isoparametric map, extended at most 2κ cells past its
//   boundary (space_map.hpp). Smooth where s's boundary cells are, it folds past concave bends
//   of s's boundary (a cubed sphere's core and caps) and stalls there;
// - the continued lattice: where b's block shares a whole face with a block of s, s's lattice
//   continues across that face onto b's block node for node, exactly as it would if the two
//   blocks were glued into one space: u is b's cell centre under that integer map, and
//   ∂X/∂θ_s at b is b's own hex Jacobian, rotated. It never folds. Of several faces b's block
//   shares with s, the one b lies fewest cells beyond wins (then the first in gluing order).
//   Around a block edge where three blocks meet, the continued lattices leave a wedge of θ
//   empty, as a re-entrant corner does.
// TransientRule::Automatic takes the extended map, and the continued lattice for every pair of
// spaces (s, home of b) that shares faces and where the map fails for one of the pair's
// particles: one rule per pair, so no two transients of a pair come from different rules.
#pragma once

#include <memory>
#include <span>
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
    bool continued = false;         ///< θ from the continued lattice (else from the extended map)
    double maxExtrapolation = 0.0;  ///< largest distance of θ past `in`'s lattice box [Δθ]
    long ambiguous = 0;             ///< located by two extensions; the nearer one kept
};

/// Maps of the spaces of bodies with more than one space (null for the others).
using SpaceMaps = std::vector<std::unique_ptr<SpaceMap>>;

/// `--transients`: how transients get their θ in another space (see above).
enum class TransientRule {
    Automatic,  ///< the extended map; the continued lattice per pair where the map fails
    Map,        ///< the extended map only
    Lattice,    ///< the continued lattice for every pair of spaces sharing a face; else the map
};

/// Where the particles came from, for continuing a lattice across shared block faces and for
/// naming a particle in an error.
struct ParticleOrigins {
    const GluingResult* glued = nullptr;
    const std::vector<BlockLattice>* blocks = nullptr;
    std::span<const Index> block;          ///< per particle: its block (index into *blocks)
    std::span<const Int3> blockCell;       ///< per particle: its cell in its block's frame
    std::span<const std::size_t> element;  ///< per particle: gmsh element tag of its hex
    const std::vector<std::vector<int>>* volumes = nullptr;  ///< per space: its gmsh volumes
};

/// "space 1 of body 'rod' (gmsh volumes 2,3,4,5)".
std::string spaceLabel(std::size_t s, const ParticleFile& particles,
                       const std::vector<std::vector<int>>& spaceVolumes);

/// Which particles to keep (1) and what was cut, per pair (space, a space that outranks it)
/// of one body. Throws MeshError naming `source` and the spaces' gmsh volumes
/// (`spaceVolumes`) if two tied spaces overlap or a space loses every particle.
std::vector<char> cutHoles(const std::string& source, const ParticleFile& particles,
                           const SpaceMaps& maps, const SpaceRanking& ranking,
                           const std::vector<std::vector<int>>& spaceVolumes,
                           std::vector<HoleCutReport>& reports);

/// Fills particles.overset and particles.transient (DESIGN §6) for the kept particles. Throws
/// MeshError naming `source`, the particle's X and hex and both spaces when a particle within
/// reach of a space can get no valid θ there (the extended map folds, det ∂X/∂θ ≤ 0, or its
/// inverse does not converge, and the spaces share no block face to continue across).
void findTransients(const std::string& source, ParticleFile& particles, const SpaceMaps& maps,
                    const ParticleOrigins& origins, double kappa, TransientRule rule,
                    std::vector<TransientReport>& reports);

}  // namespace gsph::preproc
