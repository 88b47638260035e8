// SPDX-License-Identifier: MIT
#include "space_gluing.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <tuple>

namespace gsph::preproc {

namespace {

using Glue = SharedFace;

/// The shared faces, in search order, and the triples of faces around an edge where exactly
/// three blocks meet: at most one face of such a triple can lie inside a space (three blocks
/// cannot sit in three mutually adjacent quadrants around a lattice line).
struct GlueSet {
    std::vector<Glue> glues;
    std::vector<std::array<int, 3>> triples;
};

Index nodeAt(const BlockLattice& blk, const Int3& x) {
    return blk.node(x[0], x[1], x[2]);
}

/// Node coordinates of point (u, v) on side (axis, end) of a block.
Int3 sideNode(const BlockLattice& blk, int axis, int end, int u, int v) {
    Int3 x{};
    x[axis] = end * blk.cells[axis];
    x[(axis + 1) % 3] = u;
    x[(axis + 2) % 3] = v;
    return x;
}

std::array<Index, 4> sideCorners(const BlockLattice& blk, int axis, int end) {
    const int nu = blk.cells[(axis + 1) % 3], nv = blk.cells[(axis + 2) % 3];
    std::array<Index, 4> c = {nodeAt(blk, sideNode(blk, axis, end, 0, 0)),
                              nodeAt(blk, sideNode(blk, axis, end, nu, 0)),
                              nodeAt(blk, sideNode(blk, axis, end, 0, nv)),
                              nodeAt(blk, sideNode(blk, axis, end, nu, nv))};
    std::sort(c.begin(), c.end());
    return c;
}

/// The rotation + shift that lays side (dB, eB) of B onto side (dA, eA) of A, node for node,
/// with B outside A; none if the sides do not coincide.
std::optional<LatticeTransform> matchSides(const BlockLattice& A, int dA, int eA,
                                           const BlockLattice& B, int dB, int eB) {
    Int3 inwardB{0, 0, 0}, outwardA{0, 0, 0};
    inwardB[dB] = eB == 0 ? 1 : -1;
    outwardA[dA] = eA == 0 ? -1 : 1;
    const Int3 xb0 = sideNode(B, dB, eB, 0, 0);
    const Index n0 = nodeAt(B, xb0);
    const int nuA = A.cells[(dA + 1) % 3], nvA = A.cells[(dA + 2) % 3];
    const int nuB = B.cells[(dB + 1) % 3], nvB = B.cells[(dB + 2) % 3];
    for (const SignedPermutation& R : SignedPermutation::rotations()) {
        if (R.apply(inwardB) != outwardA) continue;
        for (int cu = 0; cu <= 1; ++cu) {
            for (int cv = 0; cv <= 1; ++cv) {
                const Int3 xa0 = sideNode(A, dA, eA, cu * nuA, cv * nvA);
                if (nodeAt(A, xa0) != n0) continue;
                const Int3 rb = R.apply(xb0);
                const LatticeTransform T{R, {xa0[0] - rb[0], xa0[1] - rb[1], xa0[2] - rb[2]}};
                bool same = true;
                for (int u = 0; u <= nuB && same; ++u) {
                    for (int v = 0; v <= nvB && same; ++v) {
                        const Int3 xb = sideNode(B, dB, eB, u, v);
                        const Int3 xa = T.node(xb);
                        for (int d = 0; d < 3; ++d)
                            same = same && xa[d] >= 0 && xa[d] <= A.cells[d];
                        same = same && xa[dA] == eA * A.cells[dA] && nodeAt(A, xa) == nodeAt(B, xb);
                    }
                }
                if (same) return T;
            }
        }
    }
    return std::nullopt;
}

/// The 12 block edges as (smaller, larger) end-node pairs, and how many blocks have each.
using EdgeKey = std::pair<Index, Index>;

EdgeKey edgeKey(Index a, Index b) {
    return {std::min(a, b), std::max(a, b)};
}

std::array<EdgeKey, 4> sideEdges(const BlockLattice& blk, int axis, int end) {
    const int nu = blk.cells[(axis + 1) % 3], nv = blk.cells[(axis + 2) % 3];
    auto at = [&](int u, int v) { return nodeAt(blk, sideNode(blk, axis, end, u, v)); };
    return {edgeKey(at(0, 0), at(nu, 0)), edgeKey(at(0, nv), at(nu, nv)),
            edgeKey(at(0, 0), at(0, nv)), edgeKey(at(nu, 0), at(nu, nv))};
}

GlueSet findGlues(const std::vector<BlockLattice>& blocks, const std::vector<Index>& bodyOfBlock) {
    struct Side {
        Index block;
        int axis, end;
    };
    std::map<std::array<Index, 4>, std::vector<Side>> byCorners;
    std::map<EdgeKey, int> blocksAtEdge;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        std::map<EdgeKey, int> own;  // each of the block's 12 edges once
        for (int axis = 0; axis < 3; ++axis) {
            for (int end = 0; end <= 1; ++end) {
                byCorners[sideCorners(blocks[b], axis, end)].push_back(
                    {static_cast<Index>(b), axis, end});
                for (const EdgeKey& e : sideEdges(blocks[b], axis, end)) own[e] = 1;
            }
        }
        for (const auto& [e, one] : own) blocksAtEdge[e] += one;
    }
    struct Candidate {
        int irregular;  // edges of the shared face where 3 or ≥ 5 blocks meet
        Glue glue;
        std::array<EdgeKey, 4> edges;
    };
    std::vector<Candidate> found;
    for (const auto& [corners, sides] : byCorners) {
        for (std::size_t p = 0; p < sides.size(); ++p) {
            for (std::size_t q = p + 1; q < sides.size(); ++q) {
                const Side& s = sides[p];
                const Side& r = sides[q];
                if (s.block == r.block || bodyOfBlock[s.block] != bodyOfBlock[r.block]) continue;
                const auto T =
                    matchSides(blocks[s.block], s.axis, s.end, blocks[r.block], r.axis, r.end);
                if (!T) continue;
                int irregular = 0;
                const auto edges = sideEdges(blocks[s.block], s.axis, s.end);
                for (const EdgeKey& e : edges) {
                    const int valence = blocksAtEdge[e];
                    irregular += (valence == 3 || valence >= 5) ? 1 : 0;
                }
                found.push_back({irregular, {s.block, r.block, *T}, edges});
            }
        }
    }
    // Search order: faces away from irregular block edges first. Around an edge where 3 blocks
    // meet (an O-grid core corner) at most one of the 3 faces can lie inside a space, so such
    // faces are the likely interfaces; trying the others first makes the first solution the
    // search finds a good one (the annulus ring before the core–annulus faces).
    std::sort(found.begin(), found.end(), [](const Candidate& x, const Candidate& y) {
        return std::tie(x.irregular, x.glue.a, x.glue.b, x.glue.bToA.t) <
               std::tie(y.irregular, y.glue.a, y.glue.b, y.glue.bToA.t);
    });
    GlueSet set;
    std::map<EdgeKey, std::vector<int>> gluesAtEdge;
    for (std::size_t g = 0; g < found.size(); ++g) {
        set.glues.push_back(found[g].glue);
        for (const EdgeKey& e : found[g].edges) gluesAtEdge[e].push_back(static_cast<int>(g));
    }
    for (const auto& [edge, at] : gluesAtEdge) {
        if (blocksAtEdge[edge] == 3 && at.size() == 3) set.triples.push_back({at[0], at[1], at[2]});
    }
    return set;
}

int floorMod(int x, int p) {
    return ((x % p) + p) % p;
}

/// Do intervals [lo1, lo1+len1) and [lo2, lo2+len2) meet (modulo p when p > 0)?
bool intervalsMeet(int lo1, int len1, int lo2, int len2, int p) {
    if (p == 0) return lo1 < lo2 + len2 && lo2 < lo1 + len1;
    const int s = lo1 + floorMod(lo2 - lo1, p);  // lo2 moved into [lo1, lo1 + p)
    return s < lo1 + len1 || s + len2 - p > lo1;
}

/// Blocks grouped into spaces, each block with its map into its space's frame.
struct Partition {
    std::vector<Index> rep;                 // per block: representative block of its space
    std::vector<LatticeTransform> toSpace;  // per block
    std::vector<Int3> period;               // per representative: 0 = not periodic
};

struct Score {
    int honoured = -1;
    int spaces = 0;
    std::vector<long> sizes;  // cells per space, descending

    bool betterThan(const Score& o) const {
        if (honoured != o.honoured) return honoured > o.honoured;
        if (spaces != o.spaces) return spaces < o.spaces;
        return sizes > o.sizes;
    }
};

class Search {
  public:
    Search(const std::vector<BlockLattice>& blocks, const GlueSet& set)
        : blocks_(blocks),
          glues_(set.glues),
          triples_(set.triples),
          inTriple_(set.glues.size(), 0) {
        for (const auto& t : triples_) {
            for (int g : t) inTriple_[g] = 1;
        }
    }

    Partition run(bool& exhaustive) {
        Partition p;
        for (std::size_t b = 0; b < blocks_.size(); ++b) {
            p.rep.push_back(static_cast<Index>(b));
            p.toSpace.push_back({});
            p.period.push_back({0, 0, 0});
        }
        dfs(0, p);
        exhaustive = steps_ <= kMaxSearchSteps;
        return best_ ? *best_ : p;  // every block alone is always consistent
    }

  private:
    Int3 lower(const Partition& p, Index c) const {
        const Int3 a = p.toSpace[c].node({0, 0, 0}), b = p.toSpace[c].node(blocks_[c].cells);
        return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])};
    }
    Int3 extent(const Partition& p, Index c) const {
        const Int3 e = p.toSpace[c].R.apply(blocks_[c].cells);
        return {std::abs(e[0]), std::abs(e[1]), std::abs(e[2])};
    }

    /// Checks every glue inside space `r`, discovering periods; then that no blocks overlap.
    bool consistent(Partition& p, Index r) const {
        Int3& P = p.period[r];
        for (const Glue& g : glues_) {
            if (p.rep[g.a] != r || p.rep[g.b] != r) continue;
            const LatticeTransform implied = p.toSpace[g.a].after(g.bToA);
            const LatticeTransform& actual = p.toSpace[g.b];
            if (!(implied.R == actual.R)) return false;
            int offAxis = -1;
            for (int d = 0; d < 3; ++d) {
                int delta = implied.t[d] - actual.t[d];
                if (P[d] > 0) delta %= P[d];
                if (delta == 0) continue;
                if (P[d] > 0 || offAxis >= 0) return false;  // not a whole period, or helical
                offAxis = d;
            }
            if (offAxis >= 0) P[offAxis] = std::abs(implied.t[offAxis] - actual.t[offAxis]);
        }
        std::vector<Index> members;
        for (std::size_t c = 0; c < blocks_.size(); ++c) {
            if (p.rep[c] == r) members.push_back(static_cast<Index>(c));
        }
        for (std::size_t x = 0; x < members.size(); ++x) {
            const Int3 lo1 = lower(p, members[x]), e1 = extent(p, members[x]);
            for (int d = 0; d < 3; ++d) {
                if (P[d] > 0 && e1[d] > P[d]) return false;
            }
            for (std::size_t y = x + 1; y < members.size(); ++y) {
                const Int3 lo2 = lower(p, members[y]), e2 = extent(p, members[y]);
                bool meet = true;
                for (int d = 0; d < 3; ++d)
                    meet = meet && intervalsMeet(lo1[d], e1[d], lo2[d], e2[d], P[d]);
                if (meet) return false;
            }
        }
        return true;
    }

    std::optional<Partition> merge(const Partition& p, const Glue& g) const {
        const Index ra = p.rep[g.a], rb = p.rep[g.b];
        for (const auto& [x, y] : cuts_) {
            if ((p.rep[x] == ra && p.rep[y] == rb) || (p.rep[x] == rb && p.rep[y] == ra)) {
                return std::nullopt;
            }
        }
        // Space b's frame → space a's frame.
        const LatticeTransform M = p.toSpace[g.a].after(g.bToA).after(p.toSpace[g.b].inverse());
        Partition q = p;
        for (std::size_t c = 0; c < blocks_.size(); ++c) {
            if (p.rep[c] != rb) continue;
            q.rep[c] = ra;
            q.toSpace[c] = M.after(p.toSpace[c]);
        }
        Int3& P = q.period[ra];
        for (int d = 0; d < 3; ++d) {
            const int fromB = p.period[rb][M.R.perm[d]];
            if (fromB == 0) continue;
            if (P[d] != 0 && P[d] != fromB) return std::nullopt;
            P[d] = fromB;
        }
        if (!consistent(q, ra)) return std::nullopt;
        return q;
    }

    /// Score of a complete partition, or nothing if a space does not tile a box.
    std::optional<Score> evaluate(const Partition& p) const {
        Score s;
        s.honoured = 0;
        for (const Glue& g : glues_) s.honoured += p.rep[g.a] == p.rep[g.b] ? 1 : 0;
        for (std::size_t r = 0; r < blocks_.size(); ++r) {
            if (p.rep[r] != static_cast<Index>(r)) continue;
            Int3 lo = {1 << 30, 1 << 30, 1 << 30}, hi = {-(1 << 30), -(1 << 30), -(1 << 30)};
            long cells = 0;
            for (std::size_t c = 0; c < blocks_.size(); ++c) {
                if (p.rep[c] != static_cast<Index>(r)) continue;
                const Int3 l = lower(p, static_cast<Index>(c)),
                           e = extent(p, static_cast<Index>(c));
                for (int d = 0; d < 3; ++d) {
                    lo[d] = std::min(lo[d], l[d]);
                    hi[d] = std::max(hi[d], l[d] + e[d]);
                }
                cells += long(e[0]) * e[1] * e[2];
            }
            long box = 1;
            for (int d = 0; d < 3; ++d) box *= p.period[r][d] > 0 ? p.period[r][d] : hi[d] - lo[d];
            if (box != cells) return std::nullopt;  // holes: not a box
            ++s.spaces;
            s.sizes.push_back(cells);
        }
        std::sort(s.sizes.rbegin(), s.sizes.rend());
        return s;
    }

    /// Most faces a completion of `p` can have inside spaces, once faces before `g` are decided
    /// (those not inside by now never will be: they were cut). Each triple admits one face.
    int upperBound(std::size_t g, const Partition& p) const {
        std::vector<char> inside(glues_.size()), open(glues_.size());
        int bound = 0;
        for (std::size_t k = 0; k < glues_.size(); ++k) {
            inside[k] = p.rep[glues_[k].a] == p.rep[glues_[k].b];
            open[k] = !inside[k] && k >= g;
            bound += inside[k] || (open[k] && !inTriple_[k]) ? 1 : 0;
        }
        for (const auto& t : triples_) {
            int done = 0, left = 0;
            for (int k : t) {
                done += inside[k];
                left += open[k];
            }
            bound += std::min(left, std::max(0, 1 - done));
        }
        return bound;
    }

    void dfs(std::size_t g, const Partition& p) {
        if (++steps_ > kMaxSearchSteps) return;
        if (best_ && upperBound(g, p) < bestScore_.honoured) return;
        if (g == glues_.size()) {
            const auto s = evaluate(p);
            if (s && (!best_ || s->betterThan(bestScore_))) {
                best_ = p;
                bestScore_ = *s;
            }
            return;
        }
        const Glue& gl = glues_[g];
        if (p.rep[gl.a] == p.rep[gl.b]) {
            dfs(g + 1, p);
            return;
        }
        if (const auto q = merge(p, gl)) dfs(g + 1, *q);
        if (best_ && bestScore_.honoured == static_cast<int>(glues_.size())) return;
        cuts_.emplace_back(gl.a, gl.b);  // this face stays an interface between two spaces
        dfs(g + 1, p);
        cuts_.pop_back();
    }

    const std::vector<BlockLattice>& blocks_;
    const std::vector<Glue>& glues_;
    const std::vector<std::array<int, 3>>& triples_;
    std::vector<char> inTriple_;
    std::vector<std::pair<Index, Index>> cuts_;
    std::optional<Partition> best_;
    Score bestScore_;
    long steps_ = 0;
};

}  // namespace

Int3 GluedSpace::cellOf(std::size_t entry, const Int3& blockCell) const {
    Int3 c = toSpace[entry].cell(blockCell);
    for (int d = 0; d < 3; ++d) {
        if (periodic[d]) c[d] = floorMod(c[d], cells[d]);
    }
    return c;
}

GluingResult glueBlocks(const std::vector<BlockLattice>& blocks,
                        const std::vector<Index>& bodyOfBlock) {
    const GlueSet set = findGlues(blocks, bodyOfBlock);
    const std::vector<Glue>& glues = set.glues;
    GluingResult result;
    const Partition p = Search(blocks, set).run(result.exhaustive);
    result.sharedFaces = static_cast<int>(glues.size());
    for (const Glue& g : glues) {
        if (p.rep[g.a] == p.rep[g.b]) {
            ++result.honouredFaces;
        } else {
            result.interfaces.push_back(g);
        }
    }

    for (std::size_t seed = 0; seed < blocks.size(); ++seed) {
        // Visit each space once, from its smallest block (the seed): its frame is the space's.
        bool isSeed = true;
        for (std::size_t c = 0; c < seed; ++c) isSeed = isSeed && p.rep[c] != p.rep[seed];
        if (!isSeed) continue;
        GluedSpace space;
        space.body = bodyOfBlock[seed];
        const LatticeTransform toSeed = p.toSpace[seed].inverse();
        const Int3 P = p.period[p.rep[seed]];
        Int3 period{};
        for (int d = 0; d < 3; ++d) period[d] = P[toSeed.R.perm[d]];
        for (std::size_t c = seed; c < blocks.size(); ++c) {
            if (p.rep[c] != p.rep[seed]) continue;
            space.blocks.push_back(static_cast<Index>(c));
            space.toSpace.push_back(toSeed.after(p.toSpace[c]));
        }
        Int3 lo = {0, 0, 0}, hi = {0, 0, 0};
        for (std::size_t e = 0; e < space.blocks.size(); ++e) {
            const Int3 a = space.toSpace[e].node({0, 0, 0});
            const Int3 b = space.toSpace[e].node(blocks[space.blocks[e]].cells);
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min({lo[d], a[d], b[d]});
                hi[d] = std::max({hi[d], a[d], b[d]});
            }
        }
        for (int d = 0; d < 3; ++d) {
            space.periodic[d] = period[d] > 0;
            space.cells[d] = space.periodic[d] ? period[d] : hi[d] - lo[d];
            const int shift = space.periodic[d] ? 0 : -lo[d];  // the seed starts a periodic index
            for (LatticeTransform& T : space.toSpace) T.t[d] += shift;
        }
        result.spaces.push_back(std::move(space));
    }
    std::stable_sort(result.spaces.begin(), result.spaces.end(),
                     [](const GluedSpace& x, const GluedSpace& y) {
                         return std::tie(x.body, x.blocks[0]) < std::tie(y.body, y.blocks[0]);
                     });
    return result;
}

}  // namespace gsph::preproc
