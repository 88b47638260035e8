// SPDX-License-Identifier: MIT
// The isoparametric map of one generalized space and its inverse (DESIGN §2, §6).
//
// Lattice coordinates u = θ/Δθ: cell c = (i,j,k) spans u ∈ c + [0,1]³ and maps to physical space
// by the trilinear polynomial of its hex, X(u) = Σ N(u − c) X_corner, so a particle at the cell
// centre has X = X(c + ½) exactly. The map is continuous across cells (neighbours share their
// face nodes). Past the lattice box [0, n]³ it is *extended*: a boundary cell's polynomial
// also holds beyond its boundary sides, so the extended map is continuous too. Periodic indices
// wrap (u in [0, n)).
//
// Inverse (locate): candidate cells from a bucket grid over the cells' bounding boxes (boxes of
// boundary cells cover their extension, exactly: a trilinear map takes its extreme values at
// the corners of a box in u), then Newton iterations on each candidate's polynomial from the
// cell's centre, retried with a backtracking line search on |X(u) − X| where they fail. A solution
// counts for a cell when u lies in the cell's own range, which for a boundary cell reaches
// `extension` cells past its boundary sides. Among several solutions the one nearest the lattice
// box wins, then the lowest cell (ties happen only where extensions of non-adjacent boundary
// cells overlap, e.g. around a re-entrant corner; `ambiguous` reports them).
// Ownership: a SpaceMap copies the node positions it needs; it is immutable after construction
// and its queries are thread-safe.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "block_indexing.hpp"
#include "hex_geometry.hpp"
#include "space_gluing.hpp"

namespace gsph::preproc {

/// Where a point lies in a space.
struct SpaceLocation {
    Vec3 u = Vec3::Zero();   ///< lattice coordinates θ/Δθ (wrapped into [0, n) on periodic axes)
    Int3 cell = {0, 0, 0};   ///< the cell whose polynomial maps u to the point
    double outside = 0.0;    ///< distance of u from the lattice box [0, n]³, in cells (0: inside)
    double detJ = 0.0;       ///< det ∂X/∂u at u [m³]
    bool ambiguous = false;  ///< another cell also reaches X, with a different u (reported)
    /// No cell gives X, but Newton stalled in `cell` (singular Jacobian, no convergence) near
    /// u: X may lie where the map is singular or folds. Only u and cell are set.
    bool unresolved = false;
};

class SpaceMap {
  public:
    /// @param extension how far (in cells) past the lattice box locate() may extrapolate
    SpaceMap(const HexMesh& mesh, const std::vector<BlockLattice>& blocks, const GluedSpace& space,
             double extension);

    const Int3& cells() const { return cells_; }
    const std::array<bool, 3>& periodic() const { return periodic_; }
    /// Bounding box of the meshed cells (without extension).
    const Eigen::AlignedBox3d& bounds() const { return bounds_; }

    /// The hex of a cell, corners in corner-bit order of the space frame.
    HexCorners corners(const Int3& cell) const;
    /// X(u), extended past the boundary by the boundary cells' polynomials.
    Vec3 position(const Vec3& u) const;
    /// ∂X/∂u at u (= Δθ ∂X/∂θ).
    Mat3 jacobian(const Vec3& u) const;

    /// The u with X(u) = X, at most `extension` cells outside the box (≤ the constructor's);
    /// none if there is no such u; an `unresolved` location if none was found but Newton
    /// stalled in a cell that might hold X.
    std::optional<SpaceLocation> locate(const Vec3& X, double extension) const;

    enum class Side { Inside, Boundary, Outside };
    /// Inside: X lies in the meshed region, farther than kFaceTolerance cells from its boundary
    /// (an unresolved location counts as Outside).
    Side side(const Vec3& X) const;

    /// Tolerance (in cells) for a point on a face: between two cells, or on the boundary.
    static constexpr double kFaceTolerance = 1e-9;

  private:
    Index nodeIndex(int i, int j, int k) const {
        return i + (cells_[0] + 1) * (j + (cells_[1] + 1) * k);
    }
    Int3 cellOf(const Vec3& u) const;                     ///< the cell whose polynomial holds at u
    Vec3 localOf(const Vec3& u, const Int3& cell) const;  ///< u − cell, u wrapped if periodic
    void buildBuckets(double extension);
    std::optional<SpaceLocation> solveInCell(const Int3& cell, const Vec3& X,
                                             double extension) const;

    Int3 cells_ = {0, 0, 0};
    std::array<bool, 3> periodic_ = {false, false, false};
    std::vector<Vec3> nodes_;  ///< (n+1)³ node positions, i fastest; a periodic seam twice
    Eigen::AlignedBox3d bounds_;
    // Bucket grid over the (extended) cell boxes: cells of bucket b are
    // bucketCells_[bucketStart_[b] .. bucketStart_[b+1]).
    Vec3 gridOrigin_ = Vec3::Zero(), gridStep_ = Vec3::Ones();
    Int3 gridDims_ = {1, 1, 1};
    std::vector<std::size_t> bucketStart_;
    std::vector<Index> bucketCells_;
    std::vector<Eigen::AlignedBox3d> cellBoxes_;
};

}  // namespace gsph::preproc
