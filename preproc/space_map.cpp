// SPDX-License-Identifier: MIT
#include "space_map.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace gsph::preproc {

namespace {

int floorMod(int a, int n) {
    return ((a % n) + n) % n;
}

// Newton iterations of the inverse trilinear map: a point inside or near a regular hex
// converges in 3 to 5; beyond kMaxNewton the point is taken as not reachable from this cell.
constexpr int kMaxNewton = 40;
// Converged when the step in local coordinates falls below this (cells): at round-off.
constexpr double kNewtonStep = 1e-14;
// A solution must reproduce X to this fraction of the cell's size.
constexpr double kResidual = 1e-11;
// Local coordinates beyond this are divergence, not a solution (cells).
constexpr double kDivergence = 1e3;
// Where plain Newton fails, a line search retries it: while the residual exceeds this fraction
// of the cell's size, a step is halved at most kMaxHalvings times until the residual drops
// (measured on random distorted cells extended up to 3 cells out: plain Newton misses 7 % of
// the points, mostly by settling on another root where the extension folds, which no search
// from the centre changes; the retry recovers 1 % of the misses).
constexpr double kLineSearchFrom = 1e-2;
constexpr int kMaxHalvings = 10;

/// A hex's trilinear polynomial at local ξ ∈ [0,1]³ in monomial form (corner-bit order, as
/// hex_geometry; there ξ ∈ [−1,1]³): X = a0 + a1 ξ1 + a2 ξ2 + a3 ξ3 + a12 ξ1ξ2 + a13 ξ1ξ3
/// + a23 ξ2ξ3 + a123 ξ1ξ2ξ3, cheap to evaluate in Newton iterations.
struct Trilinear {
    Vec3 a0, a1, a2, a3, a12, a13, a23, a123;

    explicit Trilinear(const HexCorners& x)
        : a0(x[0]),
          a1(x[1] - x[0]),
          a2(x[2] - x[0]),
          a3(x[4] - x[0]),
          a12(x[3] - x[1] - x[2] + x[0]),
          a13(x[5] - x[1] - x[4] + x[0]),
          a23(x[6] - x[2] - x[4] + x[0]),
          a123(x[7] - x[3] - x[5] - x[6] + x[1] + x[2] + x[4] - x[0]) {}

    Vec3 point(const Vec3& xi) const {
        return a0 + a1 * xi[0] + a2 * xi[1] + a3 * xi[2] + a12 * (xi[0] * xi[1]) +
               a13 * (xi[0] * xi[2]) + a23 * (xi[1] * xi[2]) + a123 * (xi[0] * xi[1] * xi[2]);
    }
    Mat3 jacobian(const Vec3& xi) const {
        Mat3 J;
        J.col(0) = a1 + a12 * xi[1] + a13 * xi[2] + a123 * (xi[1] * xi[2]);
        J.col(1) = a2 + a12 * xi[0] + a23 * xi[2] + a123 * (xi[0] * xi[2]);
        J.col(2) = a3 + a13 * xi[0] + a23 * xi[1] + a123 * (xi[0] * xi[1]);
        return J;
    }
};

}  // namespace

SpaceMap::SpaceMap(const HexMesh& mesh, const std::vector<BlockLattice>& blocks,
                   const GluedSpace& space, double extension)
    : cells_(space.cells), periodic_(space.periodic) {
    const auto count = static_cast<std::size_t>(cells_[0] + 1) * (cells_[1] + 1) * (cells_[2] + 1);
    nodes_.assign(count, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
    for (std::size_t e = 0; e < space.blocks.size(); ++e) {
        const BlockLattice& block = blocks[static_cast<std::size_t>(space.blocks[e])];
        for (int k = 0; k <= block.cells[2]; ++k) {
            for (int j = 0; j <= block.cells[1]; ++j) {
                for (int i = 0; i <= block.cells[0]; ++i) {
                    Int3 x = space.toSpace[e].node({i, j, k});
                    for (int d = 0; d < 3; ++d) {
                        if (periodic_[d]) x[d] = floorMod(x[d], cells_[d]);
                    }
                    const Vec3& X = mesh.nodes[static_cast<std::size_t>(block.node(i, j, k))];
                    // A node on a periodic seam (index 0) is also node n of that axis.
                    for (int seam = 0; seam < 8; ++seam) {
                        Int3 y = x;
                        bool valid = true;
                        for (int d = 0; d < 3; ++d) {
                            if (!(seam >> d & 1)) continue;
                            valid = valid && periodic_[d] && x[d] == 0;
                            y[d] = cells_[d];
                        }
                        if (valid)
                            nodes_[static_cast<std::size_t>(nodeIndex(y[0], y[1], y[2]))] = X;
                    }
                }
            }
        }
    }
    for (const Vec3& X : nodes_) {
        if (!X.allFinite()) {
            throw MeshError(mesh.source + ": internal error: a space's node lattice has a hole");
        }
        bounds_.extend(X);
    }
    buildBuckets(extension);
}

HexCorners SpaceMap::corners(const Int3& cell) const {
    HexCorners x;
    for (int c = 0; c < 8; ++c) {
        x[static_cast<std::size_t>(c)] = nodes_[static_cast<std::size_t>(
            nodeIndex(cell[0] + (c & 1), cell[1] + (c >> 1 & 1), cell[2] + (c >> 2 & 1)))];
    }
    return x;
}

Int3 SpaceMap::cellOf(const Vec3& u) const {
    Int3 c;
    for (int d = 0; d < 3; ++d) {
        const int i = static_cast<int>(std::floor(u[d]));
        c[d] = periodic_[d] ? floorMod(i, cells_[d]) : std::clamp(i, 0, cells_[d] - 1);
    }
    return c;
}

Vec3 SpaceMap::localOf(const Vec3& u, const Int3& cell) const {
    Vec3 xi;
    for (int d = 0; d < 3; ++d) {
        const double wrapped =
            periodic_[d] ? u[d] - std::floor(u[d] / cells_[d]) * cells_[d] : u[d];
        xi[d] = wrapped - cell[d];
    }
    return xi;
}

Vec3 SpaceMap::position(const Vec3& u) const {
    const Int3 c = cellOf(u);
    return Trilinear(corners(c)).point(localOf(u, c));
}

Mat3 SpaceMap::jacobian(const Vec3& u) const {
    const Int3 c = cellOf(u);
    return Trilinear(corners(c)).jacobian(localOf(u, c));
}

void SpaceMap::buildBuckets(double extension) {
    // Each cell's box covers its own range of u: [0,1] per axis, reaching `extension` further
    // on boundary sides. A trilinear map's extremes over a box are at the box's corners.
    const std::size_t n = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
    cellBoxes_.resize(n);
    Eigen::AlignedBox3d all;
    Vec3 meanSize = Vec3::Zero();
    for (int k = 0; k < cells_[2]; ++k) {
        for (int j = 0; j < cells_[1]; ++j) {
            for (int i = 0; i < cells_[0]; ++i) {
                const Int3 c = {i, j, k};
                const HexCorners x = corners(c);
                const Trilinear map(x);
                Vec3 lo = Vec3::Zero(), hi = Vec3::Ones();
                for (int d = 0; d < 3; ++d) {
                    if (periodic_[d]) continue;
                    if (c[d] == 0) lo[d] = -extension;
                    if (c[d] == cells_[d] - 1) hi[d] = 1.0 + extension;
                }
                Eigen::AlignedBox3d box, own;
                for (int b = 0; b < 8; ++b) {
                    box.extend(map.point(Vec3((b & 1) ? hi[0] : lo[0], (b & 2) ? hi[1] : lo[1],
                                              (b & 4) ? hi[2] : lo[2])));
                    own.extend(x[static_cast<std::size_t>(b)]);
                }
                // Pad by a sliver of the cell so that points on a face fall in both cells.
                const Vec3 pad = Vec3::Constant(1e-6 * own.sizes().maxCoeff());
                box = Eigen::AlignedBox3d(box.min() - pad, box.max() + pad);
                cellBoxes_[static_cast<std::size_t>(i + cells_[0] * (j + cells_[1] * k))] = box;
                all.extend(box);
                meanSize += own.sizes() / static_cast<double>(n);
            }
        }
    }
    // About one bucket per cell, shaped like a mean cell (never more than 4 per cell).
    gridOrigin_ = all.min();
    const Vec3 extent = all.sizes();
    double scale = std::cbrt(extent.prod() / (meanSize.prod() * static_cast<double>(n)));
    if (!(scale >= 1.0) || !std::isfinite(scale)) scale = 1.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        double buckets = 1.0;
        for (int d = 0; d < 3; ++d) {
            const double step = meanSize[d] * scale;
            gridDims_[d] = step > 0.0
                               ? static_cast<int>(std::clamp(std::ceil(extent[d] / step), 1.0, 1e6))
                               : 1;
            buckets *= gridDims_[d];
        }
        if (buckets <= 4.0 * static_cast<double>(n) + 8.0) break;
        scale *= 1.5;
    }
    for (int d = 0; d < 3; ++d) {
        gridStep_[d] = extent[d] > 0.0 ? extent[d] / gridDims_[d] : 1.0;
    }
    auto bucketRange = [&](const Eigen::AlignedBox3d& box, Int3& from, Int3& to) {
        for (int d = 0; d < 3; ++d) {
            from[d] = std::clamp(
                static_cast<int>(std::floor((box.min()[d] - gridOrigin_[d]) / gridStep_[d])), 0,
                gridDims_[d] - 1);
            to[d] = std::clamp(
                static_cast<int>(std::floor((box.max()[d] - gridOrigin_[d]) / gridStep_[d])), 0,
                gridDims_[d] - 1);
        }
    };
    const std::size_t buckets =
        static_cast<std::size_t>(gridDims_[0]) * gridDims_[1] * gridDims_[2];
    bucketStart_.assign(buckets + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {  // count, then fill (CSR)
        std::vector<std::size_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
        if (pass == 1) bucketCells_.resize(bucketStart_.back());
        for (std::size_t c = 0; c < n; ++c) {
            Int3 from, to;
            bucketRange(cellBoxes_[c], from, to);
            for (int k = from[2]; k <= to[2]; ++k) {
                for (int j = from[1]; j <= to[1]; ++j) {
                    for (int i = from[0]; i <= to[0]; ++i) {
                        const auto b = static_cast<std::size_t>(
                            i + gridDims_[0] * (j + static_cast<std::size_t>(gridDims_[1]) * k));
                        if (pass == 0) {
                            ++bucketStart_[b + 1];
                        } else {
                            bucketCells_[fill[b]++] = static_cast<Index>(c);
                        }
                    }
                }
            }
        }
        if (pass == 0) {
            for (std::size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
        }
    }
}

std::optional<SpaceLocation> SpaceMap::solveInCell(const Int3& cell, const Vec3& X,
                                                   double extension) const {
    const HexCorners x = corners(cell);
    const Trilinear map(x);
    double size = 0.0;
    for (std::size_t c = 1; c < 8; ++c) size = std::max(size, (x[c] - x[0]).norm());
    // The range of ξ that belongs to this cell: [0,1], reaching `extension` further on the
    // boundary sides of the lattice.
    Vec3 lo, hi;
    for (int d = 0; d < 3; ++d) {
        const bool open = !periodic_[d];
        lo[d] = (open && cell[d] == 0) ? -extension - kFaceTolerance : -kFaceTolerance;
        hi[d] = (open && cell[d] == cells_[d] - 1) ? 1.0 + extension + kFaceTolerance
                                                   : 1.0 + kFaceTolerance;
    }
    Vec3 xi = Vec3::Constant(0.5);
    // Newton stalls (a singular Jacobian, no convergence) within a cell of this cell's range:
    // X may well lie here, where the map is singular or folds; the caller decides.
    auto unresolved = [&]() -> std::optional<SpaceLocation> {
        if (!xi.allFinite() || (xi - hi).maxCoeff() > 1.0 || (lo - xi).maxCoeff() > 1.0) {
            return std::nullopt;
        }
        SpaceLocation loc;
        loc.unresolved = true;
        loc.cell = cell;
        for (int d = 0; d < 3; ++d) loc.u[d] = cell[d] + std::clamp(xi[d], lo[d], hi[d]);
        return loc;
    };
    // Round-off in X − X(ξ) is ~ε|X|, which is ε|X|/size in ξ: a cell far from the origin
    // cannot step below that, so the tolerance grows with it (a 1 mm cell 0.2 m away: 2e-14).
    const double roundOff = 64.0 * std::numeric_limits<double>::epsilon() *
                            X.cwiseAbs().maxCoeff() /
                            std::max(size, std::numeric_limits<double>::min());
    const double stepTolerance = std::max(kNewtonStep, roundOff);
    enum class Newton { Converged, Singular, Diverged, OtherCell, Stalled };
    // Newton iterations from the cell's centre; with `lineSearch`, each step far from a solution
    // is halved until the residual |X(ξ) − X| drops (a full step can overshoot where the cell is
    // strongly distorted).
    const auto newton = [&](bool lineSearch) {
        xi = Vec3::Constant(0.5);
        bool converged = false;
        for (int it = 0; it < kMaxNewton && !converged; ++it) {
            const Mat3 J = map.jacobian(xi);
            if (!(std::abs(J.determinant()) > 0.0)) return Newton::Singular;
            const Vec3 residual = map.point(xi) - X;
            Vec3 step = J.inverse() * residual;
            const double r0 = residual.norm();
            for (int halving = 0;
                 lineSearch && r0 > kLineSearchFrom * size && halving < kMaxHalvings; ++halving) {
                const Vec3 trial = xi - step;
                if (trial.allFinite() && (map.point(trial) - X).norm() < r0) break;
                step *= 0.5;
            }
            xi -= step;
            if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > kDivergence) return Newton::Diverged;
            const double change = step.cwiseAbs().maxCoeff();
            converged = change < stepTolerance;
            // Settling (steps below a tenth of a cell) more than a cell outside this cell's
            // range: the solution belongs to another cell.
            if (it >= 2 && change < 0.1 &&
                ((xi - hi).maxCoeff() > 1.0 || (lo - xi).maxCoeff() > 1.0)) {
                return Newton::OtherCell;
            }
        }
        if (!converged || (map.point(xi) - X).norm() > kResidual * size) return Newton::Stalled;
        return Newton::Converged;
    };
    // Plain Newton first; only where it fails, again with the line search (so every point plain
    // Newton locates keeps its bits).
    Newton result = newton(false);
    if (result == Newton::Singular || result == Newton::Diverged || result == Newton::Stalled) {
        const Vec3 plain = xi;
        const Newton searched = newton(true);
        if (searched == Newton::Converged || searched == Newton::OtherCell) {
            result = searched;
        } else {
            xi = plain;
        }
    }
    if (result == Newton::Diverged || result == Newton::OtherCell) return std::nullopt;
    if (result != Newton::Converged) return unresolved();
    // The solution belongs to this cell if u lies in the cell's own range.
    SpaceLocation loc;
    double outside2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        const bool open = !periodic_[d];
        if (xi[d] < lo[d] || xi[d] > hi[d]) return std::nullopt;
        double u = cell[d] + xi[d];
        if (!open) u -= std::floor(u / cells_[d]) * cells_[d];
        loc.u[d] = u;
        if (open) {
            const double out = std::max({0.0, -u, u - cells_[d]});
            outside2 += out * out;
        }
    }
    loc.outside = std::sqrt(outside2);
    if (loc.outside > extension + kFaceTolerance) return std::nullopt;
    loc.cell = cell;
    loc.detJ = map.jacobian(xi).determinant();
    return loc;
}

std::optional<SpaceLocation> SpaceMap::locate(const Vec3& X, double extension) const {
    Int3 b;
    for (int d = 0; d < 3; ++d) {
        const double t = (X[d] - gridOrigin_[d]) / gridStep_[d];
        if (!(t >= 0.0 && t <= gridDims_[d])) return std::nullopt;
        b[d] = std::min(static_cast<int>(t), gridDims_[d] - 1);
    }
    const auto bucket = static_cast<std::size_t>(
        b[0] + gridDims_[0] * (b[1] + static_cast<std::size_t>(gridDims_[1]) * b[2]));
    std::optional<SpaceLocation> best, stalled;
    for (std::size_t e = bucketStart_[bucket]; e < bucketStart_[bucket + 1]; ++e) {
        const Index c = bucketCells_[e];
        if (!cellBoxes_[static_cast<std::size_t>(c)].contains(X)) continue;
        const Int3 cell = {c % cells_[0], (c / cells_[0]) % cells_[1], c / (cells_[0] * cells_[1])};
        std::optional<SpaceLocation> loc = solveInCell(cell, X, extension);
        if (!loc) continue;
        if (loc->unresolved) {
            if (!stalled) stalled = loc;
            continue;
        }
        if (!best) {
            best = loc;
            continue;
        }
        // Two cells reach X with different u where extensions of non-adjacent boundary cells
        // overlap. The one nearer the lattice box wins; candidates come in ascending cell
        // order, so a later one must be strictly nearer.
        Vec3 gap = loc->u - best->u;
        for (int d = 0; d < 3; ++d) {
            if (periodic_[d]) gap[d] -= cells_[d] * std::round(gap[d] / cells_[d]);
        }
        const bool ambiguous = best->ambiguous || gap.norm() > 1e-6;
        if (loc->outside < best->outside - kFaceTolerance) best = loc;
        best->ambiguous = ambiguous;
    }
    if (!best) return stalled;  // nothing found: where Newton stalled, if it did
    {
        // On a face between cells both polynomials give X, but ∂X/∂u jumps there: report the
        // cell and Jacobian that position() and jacobian() use at u, so that they agree.
        best->cell = cellOf(best->u);
        best->detJ = jacobian(best->u).determinant();
    }
    return best;
}

SpaceMap::Side SpaceMap::side(const Vec3& X) const {
    const std::optional<SpaceLocation> loc = locate(X, kFaceTolerance);
    if (!loc || loc->unresolved) return Side::Outside;
    for (int d = 0; d < 3; ++d) {
        if (periodic_[d]) continue;
        if (loc->u[d] <= kFaceTolerance || loc->u[d] >= cells_[d] - kFaceTolerance) {
            return Side::Boundary;
        }
    }
    return Side::Inside;
}

}  // namespace gsph::preproc
