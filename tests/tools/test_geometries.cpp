// SPDX-License-Identifier: MIT
// Every sample geometry in geometries/, converted in-process, checked against gmsh's own view of
// the same mesh: one particle per hex at its centre with its exact volume, θ on a uniform
// lattice whose neighbours are face neighbours in the mesh, bodies and sets as the .geo says,
// Σ V equal to the domain's volume (exact for straight-edged blocks, second order for curved).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "conversion.hpp"
#include "core/error.hpp"
#include "gmsh_input.hpp"
#include "gmsh_reference.hpp"
#include "mesh_errors.hpp"
#include "overset_checks.hpp"
#include "particle_checks.hpp"
#include "temp_dir.hpp"

namespace gsph::preproc {
namespace {

using Parameters = std::vector<std::pair<std::string, double>>;

std::string geometry(const std::string& name) {
    return std::string(GSPH_SOURCE_DIR) + "/geometries/" + name;
}

Conversion convert(const std::string& path, const Parameters& parameters = {}) {
    std::vector<std::string> warnings;
    const HexMesh mesh = readHexMesh(path, MeshReadOptions{parameters}, warnings);
    Conversion c = convertHexMesh(mesh);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    return c;
}

double totalVolume(const ParticleFile& f, Index body = -1) {
    double v = 0.0;
    for (Index a = 0; a < f.size(); ++a) v += (body < 0 || f.body[a] == body) ? f.volume[a] : 0.0;
    return v;
}

/// The checks shared by every sample: particle ↔ gmsh hex, centre, volume, lattice, neighbours.
void expectMatchesGmsh(const std::string& path, const Conversion& c,
                       const Parameters& parameters = {}) {
    const test::GmshHexes g = test::gmshHexes(path, parameters);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(static_cast<std::size_t>(f.size()), g.tags.size()) << "one particle per hex";
    test::expectLatticeLayout(f);
    validateParticleFile(f);

    double scale = 0.0, gmshTotal = 0.0;
    for (const Vec3& x : g.barycentre) scale = std::max(scale, x.cwiseAbs().maxCoeff());
    for (double v : g.volume) gmshTotal += v;
    std::vector<std::size_t> hexOf(f.size());
    std::vector<char> seen(g.tags.size(), 0);
    for (Index a = 0; a < f.size(); ++a) {
        const auto it = g.indexOfTag.find(c.elementOfParticle[a]);
        ASSERT_NE(it, g.indexOfTag.end());
        const std::size_t e = it->second;
        ASSERT_EQ(seen[e]++, 0) << "hex " << g.tags[e] << " gave two particles";
        hexOf[a] = e;
        // X(θ) is the hex's parametric centre = gmsh's barycentre of its 8 nodes.
        ASSERT_NEAR((f.X[a] - g.barycentre[e]).norm(), 0.0, 1e-14 * scale) << "particle " << a;
        ASSERT_NEAR(f.volume[a], g.volume[e], 1e-12 * g.volume[e]) << "particle " << a;
    }
    EXPECT_NEAR(totalVolume(f), gmshTotal, 1e-12 * gmshTotal);

    // Lattice neighbours (across periodic seams too) are face neighbours in gmsh's connectivity.
    Index first = 0;
    for (std::size_t s = 0; s < f.spaces.size(); ++s) {
        const auto n = f.spaces[s].cells;
        auto at = [&](int i, int j, int k) { return first + i + n[0] * (j + n[1] * k); };
        for (int k = 0; k < n[2]; ++k) {
            for (int j = 0; j < n[1]; ++j) {
                for (int i = 0; i < n[0]; ++i) {
                    for (int d = 0; d < 3; ++d) {
                        std::array<int, 3> m = {i, j, k};
                        if (++m[d] == n[d]) {
                            if (!f.spaces[s].periodic[d]) continue;
                            m[d] = 0;
                        }
                        const auto& p = g.nodes[hexOf[at(i, j, k)]];
                        const auto& q = g.nodes[hexOf[at(m[0], m[1], m[2])]];
                        int shared = 0;
                        for (std::size_t x : p)
                            shared += std::count(q.begin(), q.end(), x) > 0 ? 1 : 0;
                        ASSERT_EQ(shared, 4) << "space " << s << " cell " << i << "," << j << ","
                                             << k << " and its +"
                                             << "ijk"[d] << " neighbour";
                    }
                }
            }
        }
        first += n[0] * n[1] * n[2];
    }
}

int periodicAxes(const LatticeSpace& s) {
    return s.periodic[0] + s.periodic[1] + s.periodic[2];
}

TEST(Geometries, GradedBar) {
    const std::string path = geometry("graded_bar.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 1u);
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{20, 4, 4}));
    EXPECT_NEAR(totalVolume(f), 0.1 * 0.01 * 0.01, 1e-10 * 1e-5);  // straight edges: exact
    ASSERT_EQ(f.bodies.size(), 1u);
    EXPECT_EQ(f.bodies[0].name, "bar");
    ASSERT_EQ(f.sets.at("clamp").size(), 16u);
    for (Index a : f.sets.at("clamp")) EXPECT_EQ(f.latticeIndex[a][0], 0);
    for (Index a : f.sets.at("load")) EXPECT_EQ(f.latticeIndex[a][0], 19);
    // The sets' face areas: outward, and summing to the bar's section (planar faces: exact).
    Vec3 clamp = Vec3::Zero(), load = Vec3::Zero();
    for (const Vec3& A : f.setAreas.at("clamp")) clamp += A;
    for (const Vec3& A : f.setAreas.at("load")) load += A;
    EXPECT_LT((clamp - Vec3(-1e-4, 0, 0)).norm(), 1e-18);
    EXPECT_LT((load - Vec3(1e-4, 0, 0)).norm(), 1e-18);
    // Graded along x: cells grow by the grading ratio 1.1 from the clamp (gmsh places the
    // progression's nodes to about 1e-8).
    EXPECT_NEAR(f.volume[1] / f.volume[0], 1.1, 1e-6);
}

TEST(Geometries, BendingPlate) {
    const std::string path = geometry("bending_plate.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 1u) << "the 7 blocks along x glue into one space";
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{100, 20, 6}));
    EXPECT_EQ(c.stats.spaceVolumes[0].size(), 7u);
    EXPECT_NEAR(totalVolume(f), 0.2 * 0.04 * 0.005, 1e-10 * 4e-5);
    for (const char* set : {"support_left", "support_right", "load"}) {
        EXPECT_EQ(f.sets.at(set).size(), 40u) << set;  // a 2-cell strip across the 20-cell width
    }
    for (Index a : f.sets.at("load")) EXPECT_EQ(f.latticeIndex[a][2], 5);
    for (Index a : f.sets.at("support_left")) EXPECT_EQ(f.latticeIndex[a][2], 0);
}

// Both layouts of the three-point bending case: cells 3:1 (GSPH) and cubic (aspect = 1), the
// same thickness spacing, 9× the particles; a particle column under the indenter (x = 0) and
// over each support (x = ±10 mm) in both.
TEST(Geometries, ThreePointBendingLayouts) {
    // GSPH: graded along x (cubic 1/3 mm cells in |x| < 3.5 mm and within 1 mm of the supports,
    // up to 1 mm between and at the ends, neighbours within the ratio 1.25 but for the ≤ 3 %
    // fit of the graded part to the length); uniform (aspect = 1): cubic 1/3 mm cells, ≥ 4× the
    // particles.
    const std::string path = geometry("three_point_bending.geo");
    const double h = 0.002 / 6.0;
    Index gsphParticles = 0;
    for (const double aspect : {3.0, 1.0}) {
        const Conversion c = convert(path, {{"aspect", aspect}});
        if (aspect == 3.0) expectMatchesGmsh(path, c);
        const ParticleFile& f = c.particles;
        ASSERT_EQ(f.spaces.size(), 1u);
        const std::array<int, 3> cells =
            aspect == 3.0 ? std::array<int, 3>{67, 3, 6} : std::array<int, 3>{93, 9, 6};
        EXPECT_EQ(f.spaces[0].cells, cells) << "aspect " << aspect;
        EXPECT_NEAR(totalVolume(f), 0.031 * 0.003 * 0.002, 1e-10 * 1.86e-7);
        EXPECT_EQ(f.bodies.at(0).name, "plate");
        if (aspect == 3.0)
            gsphParticles = f.size();
        else
            EXPECT_GE(f.size(), 4 * gsphParticles) << "the uniform layout has >= 4x the particles";

        // Column centres along x: one at x = 0, mirror-symmetric, cell lengths (twice the
        // distance of a centre to its cell's edge) h in the band, between h and aspect·h.
        std::set<double> columns;
        for (const Vec3& X : f.X) columns.insert(std::round(X[0] * 1e12) / 1e12);
        ASSERT_EQ(columns.size(), static_cast<std::size_t>(cells[0])) << "aspect " << aspect;
        const std::vector<double> x(columns.begin(), columns.end());
        EXPECT_NEAR(x[x.size() / 2], 0.0, 1e-12);
        for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], -x[x.size() - 1 - i], 1e-9);
        double edge = -0.0155;
        std::vector<double> length;
        for (const double centre : x) {
            length.push_back(2.0 * (centre - edge));
            edge += length.back();
        }
        EXPECT_NEAR(edge, 0.0155, 1e-9) << "the cells tile the length";
        for (std::size_t i = 0; i < x.size(); ++i) {
            EXPECT_GE(length[i], h * 0.97) << "column " << i << ", aspect " << aspect;
            EXPECT_LE(length[i], aspect * h * 1.05) << "column " << i << ", aspect " << aspect;
            if (std::abs(std::abs(x[i]) - 0.01) < 0.0008) {
                EXPECT_LE(length[i], h * (1 + 1e-6)) << "over a support: x = " << x[i];
            }
            if (std::abs(x[i]) < 0.0034) {
                EXPECT_NEAR(length[i], h, 1e-10) << "x = " << x[i];
            }
            if (i > 0) {
                const double r = std::max(length[i] / length[i - 1], length[i - 1] / length[i]);
                EXPECT_LE(r, aspect == 3.0 ? 1.27 : 1.0 + 1e-6) << "x = " << x[i];
            }
        }
    }
}

TEST(Geometries, QuarterCylinder) {
    const std::string path = geometry("quarter_cylinder.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u) << "Cartesian core and cylindrical outer block";
    EXPECT_EQ(f.spaces[0].cells, (std::array<int, 3>{8, 8, 1}));
    EXPECT_EQ(f.spaces[1].cells[0] * f.spaces[1].cells[1], 16 * 6);
    EXPECT_EQ(periodicAxes(f.spaces[0]) + periodicAxes(f.spaces[1]), 0);
    const double exact = M_PI * 0.01 * 0.01 * 0.001 / 4.0;
    EXPECT_NEAR(totalVolume(f) / exact, 1.0, 2e-3);
    EXPECT_EQ(f.sets.at("outer").size(), 16u);
    EXPECT_EQ(f.sets.at("symmetry_x").size(), 14u);
}

TEST(Geometries, TaylorBarOgrid) {
    const std::string path = geometry("taylor_bar.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u);
    const LatticeSpace& core = f.spaces[0];
    const LatticeSpace& ring = f.spaces[1];
    EXPECT_EQ(core.cells, (std::array<int, 3>{8, 8, 40}));
    EXPECT_EQ(periodicAxes(core), 0);
    ASSERT_EQ(periodicAxes(ring), 1) << "the annulus closes on itself in its angular index";
    for (int d = 0; d < 3; ++d) {
        if (ring.periodic[d]) {
            EXPECT_EQ(ring.cells[d], 32);  // 4 quarters × 8
        }
    }
    EXPECT_EQ(c.stats.spaceVolumes[1].size(), 4u);
    const double exact = M_PI * 3.8e-3 * 3.8e-3 * 25.4e-3;
    EXPECT_NEAR(totalVolume(f) / exact, 1.0, 1e-2);
    ASSERT_EQ(f.sets.at("impact").size(), 8u * 8u + 4u * 8u * 4u);
    for (Index a : f.sets.at("impact")) EXPECT_EQ(f.latticeIndex[a][2], 0);
    // The impact face's areas point out of the rod (−z) and sum to the meshed face: the
    // circle's inscribed 32-gon at the rim, π R² · sin(2π/32)/(2π/32) = 0.99359 π R².
    Vec3 impact = Vec3::Zero();
    for (const Vec3& A : f.setAreas.at("impact")) impact += A;
    const double R = 3.8e-3, polygon = 0.5 * 32 * R * R * std::sin(2 * M_PI / 32);
    EXPECT_NEAR(impact[2] / -polygon, 1.0, 1e-9);
    EXPECT_LT(std::hypot(impact[0], impact[1]), 1e-12 * polygon);
    EXPECT_EQ(f.sets.at("lateral").size(), 32u * 40u);
}

/// Lattice layers from the overset interface: 0 for a particle whose hex shares a face (4
/// nodes) with a hex of the other space, else the smallest L∞ lattice distance (minimum image
/// on periodic axes) to such a particle of its own space.
std::vector<int> interfaceLayers(const std::string& path, const Conversion& c) {
    const test::GmshHexes g = test::gmshHexes(path);
    const ParticleFile& f = c.particles;
    std::set<std::size_t> nodesOf[2];
    std::vector<std::size_t> hexOf(f.size());
    for (Index a = 0; a < f.size(); ++a) {
        hexOf[a] = g.indexOfTag.at(c.elementOfParticle[a]);
        for (std::size_t n : g.nodes[hexOf[a]]) nodesOf[f.space[a]].insert(n);
    }
    std::vector<Index> touching[2];
    for (Index a = 0; a < f.size(); ++a) {
        const auto& other = nodesOf[1 - f.space[a]];
        int shared = 0;
        for (std::size_t n : g.nodes[hexOf[a]]) shared += other.count(n) > 0 ? 1 : 0;
        if (shared >= 4) touching[f.space[a]].push_back(a);
    }
    std::vector<int> layer(f.size(), 0);
    for (Index a = 0; a < f.size(); ++a) {
        const LatticeSpace& sp = f.spaces[f.space[a]];
        int best = 1 << 20;
        for (Index t : touching[f.space[a]]) {
            int distance = 0;
            for (int d = 0; d < 3; ++d) {
                int k = std::abs(f.latticeIndex[a][d] - f.latticeIndex[t][d]);
                if (sp.periodic[d]) k = std::min(k, sp.cells[d] - k);
                distance = std::max(distance, k);
            }
            best = std::min(best, distance);
        }
        layer[a] = best;
    }
    return layer;
}

/// DESIGN §6 across a core/annulus interface: every particle of the layer next to the
/// interface is transient in the other space, from both sides; no particle of space s at
/// layer ≥ farLayer[s] is (−1: no such bound); every entry's θ maps back to X. Prints the
/// transient counts per layer.
void expectTransientsAcrossTheInterface(const std::string& path, const Conversion& c,
                                        const std::array<int, 2>& farLayer, double scale) {
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 2u);
    validateParticleFile(f);
    const std::vector<int> layer = interfaceLayers(path, c);
    const auto entries = test::entryOf(f);
    std::map<std::pair<Index, int>, std::array<long, 2>>
        counts;  // (space, layer) → (transient, all)
    for (Index b = 0; b < f.size(); ++b) {
        const Index s = f.space[b];
        const bool transient = entries.count({b, 1 - s}) == 1;
        EXPECT_EQ(f.transient[b], transient ? 1 : 0);
        auto& n = counts[{s, layer[b]}];
        n[0] += transient;
        ++n[1];
        if (layer[b] == 0) {
            EXPECT_TRUE(transient) << "particle " << b << " next to the interface";
        }
        if (farLayer[s] >= 0 && layer[b] >= farLayer[s]) {
            EXPECT_FALSE(transient) << "particle " << b << " at layer " << layer[b];
        }
    }
    for (const auto& [key, n] : counts) {
        std::printf("  space %d, layer %d from the interface: %ld of %ld transient\n", key.first,
                    key.second, n[0], n[1]);
    }
    for (int s = 0; s < 2; ++s) {
        EXPECT_GT((counts[{s, 0}][1]), 0) << "space " << s << " touches the other";
        if (farLayer[s] >= 0) {
            long far = 0;
            for (const auto& [key, n] : counts)
                far += key.first == s && key.second >= farLayer[s] ? n[1] : 0;
            EXPECT_GT(far, 0) << "space " << s << " has particles far from the interface";
        }
    }
    std::vector<std::string> warnings;
    test::expectEntriesReproduceX(f, test::spaceMapsOf(readHexMesh(path, {}, warnings)), scale);
}

void printMetric(const char* name, const Conversion& c) {
    for (std::size_t s = 0; s < c.stats.metric.size(); ++s) {
        const MetricReport& m = c.stats.metric[s];
        std::printf("%s: space %zu: worst cond(dX/dtheta) at the particles %.3f", name, s,
                    m.condition);
        if (m.oneLayerAxis >= 0) std::printf(" (in-plane %.3f)", m.inPlaneCondition);
        std::printf(", det at cell corners >= %.3f of the centre's\n", m.cornerRatio);
        EXPECT_LT(m.condition, 5.0);
        EXPECT_GT(m.cornerRatio, 0.5);
    }
}

// --lattice on the Taylor bar: the uniform Cartesian layout of standard SPH from the same .geo.
// Kept: exactly the sites inside the meshed 32-gon (the polygon's apothem R cos(π/32) bounds
// the sites that must be kept, R those that may be); the sets hug their faces.
TEST(Geometries, TaylorBarUniformLattice) {
    std::vector<std::string> warnings;
    const HexMesh mesh = readHexMesh(geometry("taylor_bar.geo"), {}, warnings);
    ConversionOptions options;
    options.latticeSpacing = 0.95e-3;  // 8 cells across the 7.6 mm diameter
    const Conversion c = convertHexMesh(mesh, options);
    const ParticleFile& f = c.particles;
    validateParticleFile(f);
    EXPECT_TRUE(c.warnings.empty());
    ASSERT_EQ(f.spaces.size(), 1u);
    const double R = 3.8e-3, L = 25.4e-3;
    EXPECT_EQ(f.spaces[0].cells, (Int3{8, 8, 27}));
    const double h = 2 * R / 8, hz = L / 27;
    int inside = 0, kept = 0;
    std::vector<char> isKept(8 * 8, 0);
    for (Index a = 0; a < f.size(); ++a) {
        const auto& i = f.latticeIndex[a];
        if (i[2] == 0) isKept[i[0] + 8 * i[1]] = 1;
        EXPECT_NEAR(f.X[a][2], (i[2] + 0.5) * hz, 1e-15);
        EXPECT_NEAR(f.volume[a], h * h * hz, 1e-20);
    }
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const double r = std::hypot(-R + (i + 0.5) * h, -R + (j + 0.5) * h);
            if (r < R * std::cos(std::acos(-1.0) / 32)) {
                ++inside;
                EXPECT_TRUE(isKept[i + 8 * j]) << i << "," << j;
            }
            if (r > R) {
                EXPECT_FALSE(isKept[i + 8 * j]) << i << "," << j;
            }
            kept += isKept[i + 8 * j];
        }
    }
    EXPECT_EQ(f.size(), kept * 27);
    EXPECT_GE(kept, inside);
    EXPECT_EQ(f.sets.at("impact").size(), static_cast<std::size_t>(kept));
    for (Index a : f.sets.at("impact")) EXPECT_EQ(f.latticeIndex[a][2], 0);
    for (Index a : f.sets.at("free_end")) EXPECT_EQ(f.latticeIndex[a][2], 26);
    for (Index a : f.sets.at("lateral")) {
        EXPECT_GT(std::hypot(f.X[a][0], f.X[a][1]), R - 1.5 * h);
    }
    EXPECT_GE(f.sets.at("lateral").size(), 27u * 20u);  // the outer ring of 20 per layer
}

TEST(Geometries, QuarterCylinderTransientsOnBothSides) {
    // Core cells 0.625 mm, annulus cells 0.5 to 1 mm: each side reaches 3 of its cells (2κ,
    // κ = 1.5) into the other space, so from layer 3 on nothing is transient.
    const std::string path = geometry("quarter_cylinder.geo");
    const Conversion c = convert(path);
    expectTransientsAcrossTheInterface(path, c, {3, 3}, 0.01);
    printMetric("quarter cylinder", c);
}

TEST(Geometries, TaylorBarOgridTransientsOnBothSides) {
    // The annulus's radial cells (0.4 to 0.6 mm) are coarser than the core's (0.38 mm): its
    // reach of 3 radial cells covers the whole core (every core particle is transient), while
    // the core reaches 3 of its cells into the annulus: its outer two rows stay out.
    const std::string path = geometry("taylor_bar.geo");
    const Conversion c = convert(path);
    expectTransientsAcrossTheInterface(path, c, {-1, 2}, 0.03);
    long core = 0;
    for (Index b = 0; b < c.particles.size(); ++b) core += c.particles.space[b] == 0;
    EXPECT_EQ(c.stats.transients[1].particles, core);
    printMetric("Taylor bar O-grid", c);
}

TEST(Geometries, TwoBlocksAbuttingAndOverlapping) {
    const std::string path = geometry("two_blocks.geo");
    const double h = 1e-3, W = 4e-3;
    for (int plane : {0, 1}) {
        const double T = plane ? h : W;
        const Parameters layout = {{"plane", plane}};
        // Abutting: nothing cut, ω of a transient = the home cell's volume over the other
        // space's cell volume: (1/2)^d fine in coarse, 2^d coarse in fine (d = 3, or 2 in
        // the plane layout, whose cells are all T thick).
        const Conversion a = convert(path, layout);
        expectMatchesGmsh(path, a, layout);
        const ParticleFile& f = a.particles;
        ASSERT_EQ(f.spaces.size(), 2u);
        EXPECT_NEAR(totalVolume(f), 16e-3 * W * T, 1e-10 * 16e-3 * W * T);
        const double fineInCoarse = plane ? 0.25 : 0.125;
        long counted[2] = {0, 0};
        for (std::size_t e = 0; e < f.overset.size(); ++e) {
            const double expected = f.overset.space[e] == 0 ? fineInCoarse : 1.0 / fineInCoarse;
            // gmsh places the nodes to ~1e-13 relative
            EXPECT_NEAR(f.overset.omega[e], expected, 1e-10 * expected) << "entry " << e;
            ++counted[f.overset.space[e]];
        }
        EXPECT_GT(counted[0], 0);
        EXPECT_GT(counted[1], 0);
        std::vector<std::string> warnings;
        test::expectEntriesReproduceX(
            f, test::spaceMapsOf(readHexMesh(path, MeshReadOptions{layout}, warnings)), 0.016);

        // Overlap of 2 coarse cells (aligned): exactly the coarse particles whose centres lie
        // in the fine block go (2 columns), and the kept volume is the union's.
        Parameters overlap = layout;
        overlap.emplace_back("overlap", 2);
        const Conversion b = convert(path, overlap);
        const ParticleFile& g = b.particles;
        const long columns = plane ? 4 : 16;  // coarse cells in a column across y (and z)
        EXPECT_EQ(g.size(), f.size() - 2 * columns);
        for (Index p = 0; p < g.size(); ++p) {
            if (g.space[p] == 0) {
                EXPECT_LT(g.X[p][0], 6e-3);
            }
        }
        EXPECT_NEAR(totalVolume(g), 14e-3 * W * T, 1e-10 * 14e-3 * W * T);
        ASSERT_EQ(b.stats.cuts.size(), 1u);
        EXPECT_EQ(b.stats.cuts[0].particles, 2 * columns);

        // Overlap of 1.25 cells (not aligned): one coarse column goes, the next stays and
        // overlaps the fine block by a quarter cell: that much is counted twice, as reported.
        overlap.back().second = 1.25;
        const Conversion d = convert(path, overlap);
        const HoleCutReport& cut = d.stats.cuts.at(0);
        EXPECT_EQ(cut.particles, columns);
        EXPECT_NEAR(cut.gap, 0.0, 1e-22);
        const double quarter = 0.25 * h * W * T;
        EXPECT_NEAR(cut.doubleCounted, quarter, 1e-10 * quarter);
        EXPECT_NEAR(totalVolume(d.particles), 14.75e-3 * W * T + quarter, 1e-10 * 15e-3 * W * T);
        std::printf(
            "two blocks (plane %d), overlap 1.25 cells: gap %.3e m^3, double-counted %.3e "
            "m^3 (%.3f %% of the body)\n",
            plane, cut.gap, cut.doubleCounted,
            100.0 * cut.doubleCounted / totalVolume(d.particles));
    }
}

TEST(Geometries, NotchedPlate) {
    const std::string path = geometry("notched_plate.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.spaces.size(), 3u);
    EXPECT_EQ(f.spaces[2].cells, (std::array<int, 3>{25, 51, 2})) << "the ligament";
    EXPECT_NEAR(totalVolume(f), 0.1 * 0.1 * 0.004 - 0.05 * 0.002 * 0.004, 1e-10 * 4e-5);
    EXPECT_EQ(f.sets.at("notch_tip").size(), 2u);
}

// The Kalthoff–Winkler plate (200 mm long) with 1 mm cells where the cracks run: its transient
// particles lie up to 0.2 m from the origin, where the Newton iterations of the inverse map
// cannot step below ~ε|X|/h ≈ 2e-14 cells; an absolute 1e-14 stalled them (a MeshError below
// h ≈ 1.4 mm). Every overset entry must reproduce its X in the other space.
TEST(Geometries, KalthoffWinklerConvertsWithFineCellsFarFromTheOrigin) {
    const std::string path = geometry("kalthoff_winkler_slotted.geo");
    const Conversion c = convert(path, {{"h", 0.001}});
    validateParticleFile(c.particles);
    EXPECT_GT(c.particles.size(), 40000);
    EXPECT_GT(c.particles.overset.size(), 1000u);
}

TEST(Geometries, PlateAndProjectile) {
    const std::string path = geometry("plate_projectile.geo");
    const Conversion c = convert(path);
    expectMatchesGmsh(path, c);
    const ParticleFile& f = c.particles;
    ASSERT_EQ(f.bodies.size(), 2u);
    EXPECT_EQ(f.bodies[0].name, "plate");
    EXPECT_EQ(f.bodies[1].name, "projectile");
    ASSERT_EQ(f.spaces.size(), 3u);  // plate; projectile core; projectile annulus
    EXPECT_EQ(periodicAxes(f.spaces[2]), 1);
    EXPECT_NEAR(totalVolume(f, 0), 0.1 * 0.1 * 0.012, 1e-10 * 1.2e-4);
    EXPECT_NEAR(totalVolume(f, 1) / (M_PI * 0.01 * 0.01 * 0.08), 1.0, 2e-2);
    for (Index a : f.sets.at("nose")) EXPECT_EQ(f.body[a], 1);
    for (Index a : f.sets.at("plate_rim")) EXPECT_EQ(f.body[a], 0);
}

// The perforation plate, both layouts. Shear-zone (the defaults: h = 2 mm,
// hs = 0.67 mm): the ring's radial cells are graded down to hs at r = Rp = 10 mm, so a circle of
// cell faces lies at Rp and the two particle rows next to it sit ≈ hs/2 inside and outside it,
// 0.67–0.80 mm apart radially (diagonals–axes); the angular cells there stay ≈ h (32 around).
// Plain (hs = 0): the 2 mm ring of before, 3016 particles. Both: the plate's volume is its
// 24- or 32-gon prism's (straight-edged hexes), the rim set is on the plate.
TEST(Geometries, PlatePerforationShearZoneAndPlainLayouts) {
    const std::string path = geometry("plate_perforation.geo");
    for (const double hs : {0.00067, 0.0}) {
        const Parameters parameters = {{"hs", hs}};
        const Conversion c = convert(path, parameters);
        expectMatchesGmsh(path, c, parameters);
        const ParticleFile& f = c.particles;
        ASSERT_EQ(f.bodies.size(), 2u);
        const int sides = hs > 0.0 ? 32 : 24;
        const double polygon = 0.5 * sides * 0.05 * 0.05 * std::sin(2.0 * M_PI / sides);
        EXPECT_NEAR(totalVolume(f, 0) / (polygon * 0.012), 1.0, 1e-9) << "hs " << hs;
        for (Index a : f.sets.at("plate_rim")) EXPECT_EQ(f.body[a], 0);
        if (hs == 0.0) {
            EXPECT_EQ(f.size(), 3016);
            continue;
        }
        EXPECT_EQ(f.size(), 6208);
        // Bottom layer of the plate: the rows nearest Rp, 0.25–0.75 hs inside and outside it
        // (one ring of 32 particles each), none closer than 0.25 hs to the face circle at Rp.
        int inside = 0, outside = 0, onTheCircle = 0;
        for (Index a = 0; a < f.size(); ++a) {
            if (f.body[a] != 0 || f.X[a][2] > -0.010) continue;
            const double d = std::hypot(f.X[a][0], f.X[a][1]) - 0.01;
            if (std::abs(d) < 0.25 * hs) ++onTheCircle;
            if (d > -0.75 * hs && d < -0.25 * hs) ++inside;
            if (d > 0.25 * hs && d < 0.75 * hs) ++outside;
        }
        EXPECT_EQ(onTheCircle, 0);
        EXPECT_EQ(inside, 32);
        EXPECT_EQ(outside, 32);
    }
}

TEST(Geometries, MshGivesTheSameParticlesAsGeo) {
    test::TempDir dir;
    const std::string path = geometry("taylor_bar.geo");
    const std::string msh = (dir / "taylor_bar.msh").string();
    test::gmshHexes(path, {}, msh);  // gmsh -3 taylor_bar.geo -o taylor_bar.msh
    const Conversion a = convert(path);
    const Conversion b = convert(msh);
    ASSERT_EQ(a.particles.size(), b.particles.size());
    EXPECT_EQ(a.particles.latticeIndex, b.particles.latticeIndex);
    EXPECT_EQ(a.particles.space, b.particles.space);
    EXPECT_EQ(a.particles.sets, b.particles.sets);
    EXPECT_EQ(a.elementOfParticle, b.elementOfParticle);
    for (Index p = 0; p < a.particles.size(); ++p) {
        // The .msh stores coordinates in decimal: equal to round-off.
        ASSERT_NEAR((a.particles.X[p] - b.particles.X[p]).norm(), 0.0, 1e-15);
    }
}

/// Observed order of the volume error of a curved geometry over refinements 1, 2, 4.
std::vector<double> observedOrders(const std::string& name, const Parameters& fixed, double exact) {
    std::vector<double> errors;
    for (double refine : {1.0, 2.0, 4.0}) {
        Parameters p = fixed;
        p.emplace_back("refine", refine);
        const Conversion c = convert(geometry(name), p);
        errors.push_back(std::abs(totalVolume(c.particles) - exact) / exact);
    }
    const std::vector<double> orders = {std::log2(errors[0] / errors[1]),
                                        std::log2(errors[1] / errors[2])};
    std::printf("%s: relative volume errors %.3e %.3e %.3e, observed orders %.3f %.3f\n",
                name.c_str(), errors[0], errors[1], errors[2], orders[0], orders[1]);
    return orders;
}

TEST(Geometries, CurvedBlocksConvergeAtSecondOrder) {
    // Quarter cylinder (R = 10 mm, slab 1 mm thick) and the O-grid Taylor bar cut to one layer.
    for (double p : observedOrders("quarter_cylinder.geo", {}, M_PI * 1e-4 * 1e-3 / 4.0)) {
        EXPECT_GE(p, 1.8);
    }
    const double R = 3.8e-3, L = 1e-3;
    for (double p : observedOrders("taylor_bar.geo", {{"L", L}, {"nz", 1}}, M_PI * R * R * L)) {
        EXPECT_GE(p, 1.8);
    }
}

}  // namespace
}  // namespace gsph::preproc

namespace gsph::preproc {
namespace {

TEST(Geometries, ParametersDoNotLeakBetweenCalls) {
    // gmsh keeps some parser state for the whole process; readHexMesh must not let one call's
    // parameters (or one .geo's DefineConstant values) reach the next call.
    const std::string taylor = geometry("taylor_bar.geo");
    const double before = totalVolume(convert(taylor).particles);
    convert(geometry("quarter_cylinder.geo"), {{"R", 0.05}, {"refine", 2}});
    convert(taylor, {{"L", 0.001}, {"nz", 1}});
    const double after = totalVolume(convert(taylor).particles);
    EXPECT_EQ(before, after);  // the same mesh, converted the same way: bit-identical
}

TEST(PreprocErrors, BadInputsGiveClearErrors) {
    EXPECT_NE(test::meshErrorOf<InputError>("missing.geo").find("no such file"), std::string::npos);
    EXPECT_NE(test::meshErrorOf<InputError>("bad_syntax.geo").find("line 3: syntax error"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("tetrahedra.geo").find("4-node tetrahedra"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("mixed.msh").find("6-node prisms"), std::string::npos);
    EXPECT_NE(
        test::meshErrorOf<MeshError>("unstructured_hex.geo").find("not a structured hex block"),
        std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("inverted.msh").find("element 2 in volume 1 at ("),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("inverted.msh").find(") is inverted"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("folded.msh").find("folds"), std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("empty.msh").find("no hexahedra"), std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("no_volume.geo").find("no hexahedra"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("ungrouped_volume.geo")
                  .find("volume 2 is in no physical volume"),
              std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("bad_transfinite.geo").find("transfinite"),
              std::string::npos);
    EXPECT_NE(
        test::meshErrorOf<InputError>("inverted.msh", {{"refine", 2}}).find(".geo files only"),
        std::string::npos);
    EXPECT_NE(test::meshErrorOf<MeshError>("cylinder_single_space.geo")
                  .find("collapses onto the line from (0, 0, 0.002) to (0, 0, 0), like a single "
                        "cylindrical space on its axis"),
              std::string::npos);
}

TEST(PreprocErrors, SpaceCloseToAnAxisIsWarnedAbout) {
    // One cylindrical space whose inner radius is 1e-4 of the outer: converted, with a warning
    // naming the cell that nearly collapses and the axis.
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/tests/data/cylinder_near_axis.geo";
    std::vector<std::string> warnings;
    const Conversion c = convertHexMesh(readHexMesh(path, {}, warnings));
    ASSERT_EQ(c.warnings.size(), 1u);
    EXPECT_NE(c.warnings[0].find("space 0: the cell of particle"), std::string::npos)
        << c.warnings[0];
    EXPECT_NE(c.warnings[0].find("nearly collapses onto a line"), std::string::npos);
    EXPECT_NE(c.warnings[0].find("coordinate axis"), std::string::npos);
    EXPECT_LT(c.stats.metric[0].cornerRatio, 1e-3);
}

}  // namespace
}  // namespace gsph::preproc
