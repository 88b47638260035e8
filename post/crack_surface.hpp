// SPDX-License-Identifier: MIT
// Crack surfaces of a run: the Voronoi facets dual to the reference Delaunay edges whose bond
// broke, carried to the current configuration (docs/formats.md, "Crack surfaces").
//
// Built once per run from the reference positions X, body by body (bonds never cross bodies,
// and another body nearby would cut into a body's Voronoi cells: a body's facets are those it
// has alone). Per body, CGAL's 3-D Delaunay triangulation (exact predicates, so the
// cospherical points of a lattice triangulate robustly; degenerate duals of cospherical cells
// have zero area and are dropped) of its particles and:
//   * ghost points half a spacing outside the body close the boundary particles' Voronoi cells:
//     for particle a and each Delaunay neighbour b at most 1.25 × a's nearest-neighbour distance
//     d_a away, g = 2X_a − X_b is a ghost unless a Delaunay neighbour of a lies within d_a / 2
//     of g (so on a lattice the boundary facets end on the body's faces, half a cell past the
//     outermost particles);
//   * the facet of a Delaunay edge (a, b) of two particles is the polygon of the circumcentres of
//     the cells around it, from its smallest Voronoi vertex, turning about a → b (a < b: its
//     normal points from a to b); circumcentres closer than 1e-7 d_min (the smallest spacing of
//     the body's particles) merge into one Voronoi vertex; facets with an infinite cell, with a
//     vertex farther than 2|X_b − X_a| from the bond's midpoint, or of area below
//     1e-12 |X_b − X_a|² are dropped (counted).
// A Delaunay edge is cut when the bond (a, b) is in the snapshot's /bonds/broken; broken bonds
// that are not Delaunay edges (longer-range neighbours) add no facet: their cut is represented
// by the facets of the shorter broken bonds around them.
// A Voronoi vertex c of cell (p_0 … p_3) moves as x̄ + F̄ (c − p̄), the means over the cell's
// particles (a ghost moves with its particle: x_a + F_a (g − X_a)): exact for affine motions.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "io/snapshot.hpp"

namespace gsph::post {

/// Polygons of one snapshot's crack surface.
struct CrackSurface {
    std::vector<Vec3> points;           ///< Voronoi vertices in the current configuration [m]
    std::vector<Index> offsets = {0};   ///< polygon p is connectivity[offsets[p] … offsets[p+1])
    std::vector<Index> connectivity;    ///< indices into points
    std::vector<double> referenceArea;  ///< per polygon, in the reference configuration [m²]
    /// Per polygon, referenceArea × |n_facet · n_crack|: n_crack the normal of the plane fitted
    /// (area-weighted principal axes) to the centroids of the facets within 3 facet sizes. On a
    /// lattice a tilted crack is a staircase of cell faces; this is its area on the crack's
    /// own plane, the crack's area without the staircase (a patch that spans no plane keeps
    /// the facet's area) [m²].
    std::vector<double> projectedArea;
    std::vector<std::array<Index, 2>> bond;   ///< per polygon, the broken bond (a, b), a < b
    std::size_t brokenBondsWithoutFacet = 0;  ///< broken bonds that are no (kept) Delaunay edge

    std::size_t polygons() const { return referenceArea.size(); }
    double totalReferenceArea() const;
    double totalProjectedArea() const;
};

class CrackSurfaces {
  public:
    /// Triangulates the reference positions of each body (3-D; once per run). `body`: per
    /// particle, its body id (the snapshot's); empty: one body. A body whose particles do not
    /// span three dimensions gets no facets (flatBodies). Throws InputError if no body spans
    /// three dimensions, or if `body` has another size than X.
    explicit CrackSurfaces(const std::vector<Vec3>& X, const std::vector<Index>& body = {});

    /// The facets of the broken bonds of `snapshot` (same particles as the constructor's X),
    /// in the order of its /bonds/broken. Throws InputError if the particle count differs.
    CrackSurface surface(const Snapshot& snapshot) const;

    std::size_t facets() const { return facetPartner_.size(); }
    std::size_t ghosts() const { return ghostSource_.size(); }
    /// Delaunay edges between particles whose facet was dropped (see the header comment).
    std::size_t droppedFacets() const { return droppedFacets_; }
    /// Bodies whose particles do not span three dimensions: no facets.
    std::size_t flatBodies() const { return flatBodies_; }

  private:
    struct Facet;
    /// Adds the ghosts, Voronoi vertices and facets of one body (`members`: its particles, in
    /// increasing order); false, adding nothing, if they do not span three dimensions.
    bool triangulate(const std::vector<Vec3>& X, const std::vector<Index>& members,
                     std::vector<Facet>& found);
    Index facetOf(Index a, Index b) const;  ///< facet of edge (a, b), a < b, or −1

    std::size_t particles_ = 0;
    std::vector<Index> body_;  ///< per particle (empty: one body)
    // Triangulation vertices: 0 … N−1 are the particles, N + g the ghost g.
    std::vector<Index> ghostSource_;
    std::vector<Vec3> ghostPosition_;
    // Voronoi vertices: reference position and the four triangulation vertices of their cell.
    std::vector<Vec3> voronoiPosition_;
    std::vector<std::array<Index, 4>> voronoiCell_;
    // Facets in CSR by the smaller particle a: row a holds partners b (sorted).
    std::vector<Index> rowBegin_;
    std::vector<Index> facetPartner_;
    std::vector<double> facetArea_;
    std::vector<Index> polygonBegin_, polygon_;  ///< facet f: Voronoi vertices, in order
    std::size_t droppedFacets_ = 0;
    std::size_t flatBodies_ = 0;
};

}  // namespace gsph::post
