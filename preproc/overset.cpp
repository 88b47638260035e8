// SPDX-License-Identifier: MIT
#include "overset.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph::preproc {

namespace {

std::string point(const Vec3& X) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", X[0], X[1], X[2]);
    return text;
}

std::vector<Index> bodyOfSpaces(const ParticleFile& pf) {
    std::vector<Index> body(pf.spaces.size(), -1);
    for (Index a = 0; a < pf.size(); ++a) body[static_cast<std::size_t>(pf.space[a])] = pf.body[a];
    return body;
}

/// The gmsh volume tags a --priority rule names: a volume tag, or a physical volume group.
std::vector<int> volumesOfRule(const std::string& source, const HexMesh& mesh,
                               const PriorityRule& rule) {
    const std::string label =
        "--priority " + rule.volume + "=" + std::to_string(rule.priority) + ": ";
    const bool number =
        !rule.volume.empty() && std::all_of(rule.volume.begin(), rule.volume.end(),
                                            [](unsigned char c) { return std::isdigit(c) != 0; });
    std::vector<int> tags;
    for (const HexVolume& v : mesh.volumes) {
        if (number && std::to_string(v.tag) == rule.volume) tags.push_back(v.tag);
    }
    for (const VolumeGroup& g : mesh.volumeGroups) {
        if (g.name != rule.volume) continue;
        for (int tag : g.volumes) {
            const bool meshed = std::any_of(mesh.volumes.begin(), mesh.volumes.end(),
                                            [&](const HexVolume& v) { return v.tag == tag; });
            if (meshed) tags.push_back(tag);
        }
    }
    if (tags.empty()) {
        throw InputError(source + ": " + label + "no gmsh volume " + rule.volume +
                         " and no physical volume group named '" + rule.volume + "'");
    }
    return tags;
}

}  // namespace

std::string spaceLabel(std::size_t s, const ParticleFile& pf,
                       const std::vector<std::vector<int>>& spaceVolumes) {
    std::string volumes;
    for (int v : spaceVolumes[s]) {
        if (!volumes.empty()) volumes += ',';
        volumes += std::to_string(v);
    }
    std::string body;
    for (Index a = 0; a < pf.size() && body.empty(); ++a) {
        if (pf.space[a] != static_cast<Index>(s)) continue;
        const BodyInfo& info = pf.bodies[static_cast<std::size_t>(pf.body[a])];
        body = " of body ";
        if (info.name.empty()) {
            body += std::to_string(pf.body[a]);
        } else {
            body.append(1, '\'').append(info.name).append(1, '\'');
        }
    }
    return "space " + std::to_string(s) + body + " (gmsh volume" +
           (spaceVolumes[s].size() == 1 ? " " : "s ") + volumes + ")";
}

bool SpaceRanking::outranks(std::size_t t, std::size_t s) const {
    if (priority[t] != priority[s]) return priority[t] > priority[s];
    return spacing[t] < (1.0 - kSpacingTie) * spacing[s];
}

SpaceRanking rankSpaces(const std::string& source, const HexMesh& mesh,
                        const std::vector<BlockLattice>& blocks, const GluingResult& glued,
                        const ParticleFile& pf, const std::vector<PriorityRule>& rules) {
    std::map<int, std::pair<int, std::string>> byVolume;  // tag → (priority, the rule's text)
    for (const PriorityRule& rule : rules) {
        const std::string text = rule.volume + "=" + std::to_string(rule.priority);
        for (int tag : volumesOfRule(source, mesh, rule)) {
            const auto [it, added] = byVolume.try_emplace(tag, rule.priority, text);
            if (!added && it->second.first != rule.priority) {
                throw InputError(source + ": conflicting priorities: --priority " +
                                 it->second.second + " and --priority " + text +
                                 " both set gmsh volume " + std::to_string(tag));
            }
        }
    }
    SpaceRanking r;
    const std::size_t spaces = glued.spaces.size();
    r.priority.assign(spaces, 0);
    for (std::size_t s = 0; s < spaces; ++s) {
        const std::vector<Index>& members = glued.spaces[s].blocks;
        auto priorityOf = [&](Index b) {
            const auto it = byVolume.find(blocks[static_cast<std::size_t>(b)].volumeTag);
            return it == byVolume.end() ? 0 : it->second.first;
        };
        r.priority[s] = priorityOf(members.front());
        for (Index b : members) {
            if (priorityOf(b) == r.priority[s]) continue;
            throw MeshError(
                source + ": conflicting priorities: gmsh volumes " +
                std::to_string(blocks[static_cast<std::size_t>(members.front())].volumeTag) +
                " and " + std::to_string(blocks[static_cast<std::size_t>(b)].volumeTag) +
                " glue into one generalized space but have priorities " +
                std::to_string(r.priority[s]) + " and " + std::to_string(priorityOf(b)) +
                "; give them the same --priority");
        }
    }
    std::vector<double> volume(spaces, 0.0), count(spaces, 0.0);
    for (Index a = 0; a < pf.size(); ++a) {
        volume[static_cast<std::size_t>(pf.space[a])] += pf.volume[a];
        count[static_cast<std::size_t>(pf.space[a])] += 1.0;
    }
    r.spacing.resize(spaces);
    for (std::size_t s = 0; s < spaces; ++s) r.spacing[s] = std::cbrt(volume[s] / count[s]);
    return r;
}

namespace {

/// Fraction of a hex's volume inside space `t` (not on its boundary): 1 if its corners and
/// centre all lie inside; otherwise the det J-weighted share of 4×4×4 sub-cell centres inside
/// (exact for a parallelepiped cell whose sub-cells t's boundary does not cross, e.g. an
/// overlap aligned with the sub-cell faces).
double insideFraction(const HexCorners& x, const SpaceMap& t) {
    bool allInside = t.side(hexCentre(x)) == SpaceMap::Side::Inside;
    for (std::size_t c = 0; c < 8 && allInside; ++c) {
        allInside = t.side(x[c]) == SpaceMap::Side::Inside;
    }
    if (allInside) return 1.0;
    constexpr int kSub = 4;
    double inside = 0.0, total = 0.0;
    for (int q = 0; q < kSub * kSub * kSub; ++q) {
        const Vec3 xi(-1.0 + (2 * (q % kSub) + 1.0) / kSub,
                      -1.0 + (2 * (q / kSub % kSub) + 1.0) / kSub,
                      -1.0 + (2 * (q / (kSub * kSub)) + 1.0) / kSub);
        const double w = hexJacobian(x, xi).determinant();
        total += w;
        if (t.side(hexPoint(x, xi)) == SpaceMap::Side::Inside) inside += w;
    }
    return inside / total;
}

Eigen::AlignedBox3d boxOf(const HexCorners& x) {
    Eigen::AlignedBox3d box;
    for (const Vec3& c : x) box.extend(c);
    return box;
}

/// Gap and doubly counted volume of space s against t (t outranks s), from cutBy.
HoleCutReport measureCut(const ParticleFile& pf, const SpaceMaps& maps, Index s, Index t,
                         const std::vector<Index>& cutBy) {
    HoleCutReport r;
    r.space = s;
    r.by = t;
    const SpaceMap& mapS = *maps[static_cast<std::size_t>(s)];
    const SpaceMap& mapT = *maps[static_cast<std::size_t>(t)];
    std::vector<double> gap(static_cast<std::size_t>(pf.size()), 0.0), extra(gap.size(), 0.0);
    parallelFor(pf.size(), [&](std::ptrdiff_t a) {
        if (pf.space[a] != s || (cutBy[a] >= 0 && cutBy[a] != t)) return;
        const auto& ijk = pf.latticeIndex[a];
        const HexCorners x = mapS.corners({ijk[0], ijk[1], ijk[2]});
        if (!boxOf(x).intersects(mapT.bounds())) {
            if (cutBy[a] == t) gap[a] = pf.volume[a];
            return;
        }
        const double inside = insideFraction(x, mapT);
        if (cutBy[a] == t) {
            gap[a] = (1.0 - inside) * pf.volume[a];
        } else {
            extra[a] = inside * pf.volume[a];
        }
    });
    for (Index a = 0; a < pf.size(); ++a) {
        if (cutBy[a] == t && pf.space[a] == s) {
            ++r.particles;
            r.volume += pf.volume[a];
        }
        r.gap += gap[a];
        r.doubleCounted += extra[a];
    }
    return r;
}

}  // namespace

std::vector<char> cutHoles(const std::string& source, const ParticleFile& pf, const SpaceMaps& maps,
                           const SpaceRanking& ranking,
                           const std::vector<std::vector<int>>& spaceVolumes,
                           std::vector<HoleCutReport>& reports) {
    const std::vector<Index> body = bodyOfSpaces(pf);
    const auto spaces = static_cast<Index>(pf.spaces.size());
    std::vector<Index> cutBy(static_cast<std::size_t>(pf.size()), -1);
    std::vector<Index> tiedOverlap(cutBy.size(), -1);
    parallelFor(pf.size(), [&](std::ptrdiff_t a) {
        const Index s = pf.space[a];
        if (!maps[static_cast<std::size_t>(s)]) return;
        for (Index t = 0; t < spaces; ++t) {
            if (t == s || body[t] != body[s]) continue;
            const bool wins = ranking.outranks(t, s), tie = ranking.tied(t, s);
            if (!wins && !tie) continue;
            const SpaceMap& map = *maps[static_cast<std::size_t>(t)];
            if (!map.bounds().contains(pf.X[a]) || map.side(pf.X[a]) != SpaceMap::Side::Inside) {
                continue;
            }
            if (wins && cutBy[a] < 0) cutBy[a] = t;
            if (tie) tiedOverlap[a] = t;
        }
    });
    for (Index a = 0; a < pf.size(); ++a) {
        if (tiedOverlap[a] < 0) continue;
        const auto s = static_cast<std::size_t>(pf.space[a]);
        const auto t = static_cast<std::size_t>(tiedOverlap[a]);
        throw MeshError(source + ": " + spaceLabel(s, pf, spaceVolumes) + " and " +
                        spaceLabel(t, pf, spaceVolumes) + " overlap (particle " +
                        std::to_string(a) + " at " + point(pf.X[a]) +
                        " lies in both) with the same priority and the same spacing: which one "
                        "keeps its particles is undecided; give one a higher --priority");
    }
    std::vector<long> kept(pf.spaces.size(), 0);
    for (Index a = 0; a < pf.size(); ++a)
        kept[static_cast<std::size_t>(pf.space[a])] += cutBy[a] < 0;
    for (Index s = 0; s < spaces; ++s) {
        if (kept[static_cast<std::size_t>(s)] > 0) continue;
        throw MeshError(source + ": " + spaceLabel(s, pf, spaceVolumes) +
                        " lies entirely inside spaces that outrank it: hole cutting leaves none of "
                        "its particles; remove it or raise its --priority");
    }
    for (Index s = 0; s < spaces; ++s) {
        for (Index t = 0; t < spaces; ++t) {
            if (t == s || body[t] != body[s] || !maps[static_cast<std::size_t>(s)]) continue;
            if (ranking.outranks(t, s)) reports.push_back(measureCut(pf, maps, s, t, cutBy));
        }
    }
    std::vector<char> keep(cutBy.size());
    for (std::size_t a = 0; a < keep.size(); ++a) keep[a] = cutBy[a] < 0 ? 1 : 0;
    return keep;
}

namespace {

/// Kept particles per cell of a space, for the distance test of transients.
struct Occupancy {
    Int3 cells = {0, 0, 0};
    std::array<bool, 3> periodic = {false, false, false};
    std::vector<char> used;

    /// True if a used cell's centre lies closer than `radius` to u (lattice units).
    bool near(const Vec3& u, double radius) const {
        Int3 lo, hi;
        for (int d = 0; d < 3; ++d) {
            lo[d] = static_cast<int>(std::floor(u[d] - radius - 0.5));
            hi[d] = static_cast<int>(std::ceil(u[d] + radius - 0.5));
            if (!periodic[d]) {
                lo[d] = std::max(lo[d], 0);
                hi[d] = std::min(hi[d], cells[d] - 1);
            }
        }
        const double r2 = radius * radius;
        for (int k = lo[2]; k <= hi[2]; ++k) {
            for (int j = lo[1]; j <= hi[1]; ++j) {
                for (int i = lo[0]; i <= hi[0]; ++i) {
                    const Vec3 offset = u - Vec3(i + 0.5, j + 0.5, k + 0.5);
                    if (offset.squaredNorm() >= r2) continue;
                    if (used[indexOf({i, j, k})]) return true;
                }
            }
        }
        return false;
    }

    /// True if u lies in a used cell.
    bool holds(const Vec3& u) const {
        const Int3 c = {static_cast<int>(std::floor(u[0])), static_cast<int>(std::floor(u[1])),
                        static_cast<int>(std::floor(u[2]))};
        for (int d = 0; d < 3; ++d) {
            if (!periodic[d] && (c[d] < 0 || c[d] >= cells[d])) return false;
        }
        return used[indexOf(c)] != 0;
    }

    /// Row of cell c in `used` (i fastest), periodic indices wrapped.
    std::size_t indexOf(const Int3& c) const {
        std::size_t index = 0;
        for (int d = 2; d >= 0; --d) {
            const int w = periodic[d] ? ((c[d] % cells[d]) + cells[d]) % cells[d] : c[d];
            index = index * static_cast<std::size_t>(cells[d]) + static_cast<std::size_t>(w);
        }
        return index;
    }
};

Occupancy occupancyOf(const ParticleFile& pf, Index s) {
    Occupancy o;
    const LatticeSpace& sp = pf.spaces[static_cast<std::size_t>(s)];
    o.cells = {sp.cells[0], sp.cells[1], sp.cells[2]};
    o.periodic = sp.periodic;
    o.used.assign(static_cast<std::size_t>(o.cells[0]) * o.cells[1] * o.cells[2], 0);
    for (Index a = 0; a < pf.size(); ++a) {
        if (pf.space[a] != s) continue;
        const auto& c = pf.latticeIndex[a];
        o.used[static_cast<std::size_t>(c[0]) +
               static_cast<std::size_t>(o.cells[0]) *
                   (c[1] + static_cast<std::size_t>(o.cells[1]) * c[2])] = 1;
    }
    return o;
}

}  // namespace

namespace {

/// The block's entry in its space.
std::size_t entryOf(const GluedSpace& space, Index block) {
    const auto it = std::find(space.blocks.begin(), space.blocks.end(), block);
    return static_cast<std::size_t>(it - space.blocks.begin());
}

/// Cells a cell of a block's frame lies outside the block (0 inside).
int cellsOutside(const Int3& cell, const Int3& cells) {
    int out = 0;
    for (int d = 0; d < 3; ++d) out = std::max({out, -cell[d], cell[d] - cells[d] + 1});
    return out;
}

/// u of particle b (of space t) in space s by the continued lattice, or none.
std::optional<SpaceLocation> continueLattice(const ParticleFile& pf, const SpaceMaps& maps,
                                             const ParticleOrigins& origins, Index s, Index b,
                                             const std::vector<Index>& spaceOfBlock) {
    const GluingResult& glued = *origins.glued;
    const std::vector<BlockLattice>& blocks = *origins.blocks;
    const Index B = origins.block[static_cast<std::size_t>(b)];
    const Int3& cb = origins.blockCell[static_cast<std::size_t>(b)];
    std::optional<SpaceLocation> best;
    int bestDepth = 0;
    for (const SharedFace& f : glued.interfaces) {
        // The face seen from B: B → A with A in space s.
        Index A = -1;
        LatticeTransform toA;
        if (f.b == B && spaceOfBlock[static_cast<std::size_t>(f.a)] == s) {
            A = f.a;
            toA = f.bToA;
        } else if (f.a == B && spaceOfBlock[static_cast<std::size_t>(f.b)] == s) {
            A = f.b;
            toA = f.bToA.inverse();
        }
        if (A < 0) continue;
        const Int3 inA = toA.cell(cb);
        const int depth = cellsOutside(inA, blocks[static_cast<std::size_t>(A)].cells);
        if (best && depth >= bestDepth) continue;
        const GluedSpace& space = glued.spaces[static_cast<std::size_t>(s)];
        const std::size_t entry = entryOf(space, A);
        const Int3 c = space.cellOf(entry, inA);
        SpaceLocation loc;
        double outside2 = 0.0;
        for (int d = 0; d < 3; ++d) {
            loc.u[d] = c[d] + 0.5;
            if (space.periodic[d]) continue;
            const double out = std::max({0.0, -loc.u[d], loc.u[d] - space.cells[d]});
            outside2 += out * out;
        }
        loc.outside = std::sqrt(outside2);
        loc.cell = c;
        // ∂X/∂u_s = ∂X/∂u_B R⁻¹ with R a rotation: det is b's own (ξ ∈ [−1,1]: ∂X/∂u = 2 ∂X/∂ξ).
        const HexCorners x =
            maps[static_cast<std::size_t>(pf.space[b])]->corners(pf.latticeIndex[b]);
        loc.detJ = 8.0 * hexJacobian(x, Vec3::Zero()).determinant();
        best = loc;
        bestDepth = depth;
    }
    return best;
}

}  // namespace

void findTransients(const std::string& source, ParticleFile& pf, const SpaceMaps& maps,
                    const ParticleOrigins& origins, double kappa, TransientRule rule,
                    std::vector<TransientReport>& reports) {
    const double reach = 2.0 * kappa;  // one kernel support 2h = 2κΔθ, in lattice units
    const std::vector<Index> body = bodyOfSpaces(pf);
    const auto spaces = static_cast<Index>(pf.spaces.size());
    std::vector<Index> spaceOfBlock(origins.blocks->size(), -1);
    for (std::size_t s = 0; s < origins.glued->spaces.size(); ++s) {
        for (Index blk : origins.glued->spaces[s].blocks) {
            spaceOfBlock[static_cast<std::size_t>(blk)] = static_cast<Index>(s);
        }
    }
    // shares[s][t]: a block of t shares a face with a block of s.
    std::vector<std::vector<char>> shares(static_cast<std::size_t>(spaces),
                                          std::vector<char>(static_cast<std::size_t>(spaces), 0));
    for (const SharedFace& f : origins.glued->interfaces) {
        const auto sa = static_cast<std::size_t>(spaceOfBlock[static_cast<std::size_t>(f.a)]);
        const auto sb = static_cast<std::size_t>(spaceOfBlock[static_cast<std::size_t>(f.b)]);
        shares[sa][sb] = shares[sb][sa] = 1;
    }
    OversetEntries& o = pf.overset;
    o = OversetEntries{};
    o.kappa = kappa;
    pf.transient.assign(static_cast<std::size_t>(pf.size()), 0);
    std::vector<std::optional<SpaceLocation>> found(static_cast<std::size_t>(pf.size()));
    for (Index s = 0; s < spaces; ++s) {
        const SpaceMap* map = maps[static_cast<std::size_t>(s)].get();
        if (map == nullptr) continue;
        const Occupancy occupancy = occupancyOf(pf, s);
        // Per home space t: take the continued lattice?
        std::vector<char> continued(static_cast<std::size_t>(spaces), 0);
        for (Index t = 0; t < spaces; ++t) {
            continued[static_cast<std::size_t>(t)] =
                rule == TransientRule::Lattice &&
                shares[static_cast<std::size_t>(s)][static_cast<std::size_t>(t)];
        }
        parallelFor(pf.size(), [&](std::ptrdiff_t b) {
            found[b].reset();
            if (pf.space[b] == s || pf.body[b] != body[s] || continued[pf.space[b]]) return;
            std::optional<SpaceLocation> loc = map->locate(pf.X[b], reach);
            if (loc && occupancy.near(loc->u, reach)) found[b] = loc;
        });
        if (rule == TransientRule::Automatic) {
            for (Index b = 0; b < pf.size(); ++b) {
                const auto t = static_cast<std::size_t>(pf.space[b]);
                if (found[b] && (found[b]->unresolved || !(found[b]->detJ > 0.0)) &&
                    shares[static_cast<std::size_t>(s)][t]) {
                    continued[t] = 1;
                }
            }
        }
        parallelFor(pf.size(), [&](std::ptrdiff_t b) {
            if (pf.space[b] == s || pf.body[b] != body[s] || !continued[pf.space[b]]) return;
            found[b].reset();
            std::optional<SpaceLocation> loc =
                continueLattice(pf, maps, origins, s, static_cast<Index>(b), spaceOfBlock);
            if (loc && occupancy.near(loc->u, reach)) found[b] = loc;
        });
        std::map<Index, TransientReport> bySpace;  // home space of b → report
        for (Index t = 0; t < spaces; ++t) {
            if (t != s && body[t] == body[s] && maps[static_cast<std::size_t>(t)]) {
                bySpace[t] =
                    TransientReport{t, s, 0, continued[static_cast<std::size_t>(t)] != 0, 0.0, 0};
            }
        }
        const double dtheta = pf.spaces[static_cast<std::size_t>(s)].dtheta;
        char reachText[32];
        std::snprintf(reachText, sizeof reachText, "%g", reach);
        const std::string remedy = ": " +
                                   spaceLabel(static_cast<std::size_t>(s), pf, *origins.volumes) +
                                   " has cells next to its boundary too coarse or distorted to "
                                   "reach this far (2 kappa = " +
                                   reachText +
                                   " cells), and no block face it shares with the particle's "
                                   "space to continue across; refine them, move the interface, "
                                   "or lower --overset-kappa";
        auto where = [&](Index b) {
            return "particle " + std::to_string(b) + " at X = " + point(pf.X[b]) +
                   " (gmsh element " +
                   std::to_string(origins.element[static_cast<std::size_t>(b)]) + ") of " +
                   spaceLabel(static_cast<std::size_t>(pf.space[b]), pf, *origins.volumes) +
                   " is within one kernel support of " +
                   spaceLabel(static_cast<std::size_t>(s), pf, *origins.volumes) +
                   " but cannot be located there: ";
        };
        // Cells of s taken by a transient of a continued pair: two may not share one.
        std::map<std::array<long, 3>, Index> taken;
        for (Index b = 0; b < pf.size(); ++b) {
            if (!found[b]) continue;
            const SpaceLocation& loc = *found[b];
            if (loc.unresolved) {
                throw MeshError(source + ": " + where(b) +
                                "the Newton iterations of the inverse map stall near theta = " +
                                point(loc.u) + " (the map is singular or folds there)" + remedy);
            }
            if (!(loc.detJ > 0.0)) {
                throw MeshError(source + ": " + where(b) +
                                "the map, extended past the boundary to reach it, folds (det "
                                "dX/dtheta <= 0 at theta = " +
                                point(loc.u) + ")" + remedy);
            }
            if (continued[static_cast<std::size_t>(pf.space[b])]) {
                const std::array<long, 3> key = {std::lround(loc.u[0] * 2.0),
                                                 std::lround(loc.u[1] * 2.0),
                                                 std::lround(loc.u[2] * 2.0)};
                const auto [it, added] = taken.try_emplace(key, b);
                if (!added || occupancy.holds(loc.u)) {
                    const std::string other = added ? "a particle of that space"
                                                    : "particle " + std::to_string(it->second);
                    throw MeshError(source + ": " + where(b) +
                                    "continued across a shared block face, it lands on the "
                                    "theta = " +
                                    point(loc.u) + " of " + other +
                                    "; give the blocks around it other --priority or mesh the "
                                    "region as one block");
                }
            }
            o.particle.push_back(b);
            o.space.push_back(s);
            o.theta.push_back(loc.u * dtheta);
            // DESIGN §3: ω = V / det(∂X/∂θ), with ∂X/∂θ = (∂X/∂u)/Δθ.
            o.omega.push_back(pf.volume[b] * dtheta * dtheta * dtheta / loc.detJ);
            pf.transient[b] = 1;
            TransientReport& r = bySpace[pf.space[b]];
            ++r.particles;
            r.maxExtrapolation = std::max(r.maxExtrapolation, loc.outside);
            r.ambiguous += loc.ambiguous ? 1 : 0;
        }
        for (const auto& [t, r] : bySpace) reports.push_back(r);
    }
}

}  // namespace gsph::preproc
