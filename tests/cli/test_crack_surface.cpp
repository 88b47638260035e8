// SPDX-License-Identifier: MIT
// Crack surfaces of gsph-post (post/crack_surface.hpp): a block of 16³ particles whose bonds
// crossing a plane are broken (set in State::bondIntact, written with the library's snapshot
// writer) gives Voronoi facets whose area is the cut's area; no broken bond gives no facet;
// the facets move with an affine motion exactly; a second body beside the block leaves the
// block's facets as they are alone; ghosts that nearly meet across a gap keep the facets;
// gsph-post writes them as .vtp in cracks.pvd.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "crack_surface.hpp"
#include "io/snapshot.hpp"
#include "support/lattice_fixtures.hpp"
#include "support/process.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

constexpr int kCells = 16;  // per side of the unit cube: spacing 1/16

Reference unitCube() {
    const AxisGrading uniform;
    return testing::builtReference(gradedBoxMap(Vec3(1, 1, 1), {uniform, uniform, uniform}), 3,
                                   {kCells, kCells, kCells});
}

// State at rest with every bond crossing the plane n·(X − c) = 0 broken (both directions).
State cutAlong(const Reference& ref, const Vec3& normal, const Vec3& centre) {
    State s = State::atRest(ref.X, ref.pairs.neighbor.size());
    for (Index a = 0; a < ref.size(); ++a)
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const Index b = ref.pairs.neighbor[static_cast<std::size_t>(k)];
            const double da = normal.dot(ref.X[static_cast<std::size_t>(a)] - centre);
            const double db = normal.dot(ref.X[static_cast<std::size_t>(b)] - centre);
            if (da * db < 0.0) s.bondIntact[static_cast<std::size_t>(k)] = 0;
        }
    return s;
}

Snapshot throughFile(const Reference& ref, const State& state, const fs::path& file) {
    writeSnapshot(file, ref, state, Provenance{});
    return readSnapshot(file);
}

double polygonArea(const post::CrackSurface& c, std::size_t p) {
    const Vec3& o =
        c.points[static_cast<std::size_t>(c.connectivity[static_cast<std::size_t>(c.offsets[p])])];
    Vec3 s = Vec3::Zero();
    for (Index k = c.offsets[p] + 1; k + 1 < c.offsets[p + 1]; ++k)
        s += (c.points[static_cast<std::size_t>(c.connectivity[static_cast<std::size_t>(k)])] - o)
                 .cross(c.points[static_cast<std::size_t>(
                            c.connectivity[static_cast<std::size_t>(k + 1)])] -
                        o);
    return 0.5 * s.norm();
}

class CrackSurfaceTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        ref_ = new Reference(unitCube());
        cracks_ = new post::CrackSurfaces(ref_->X);
    }
    static void TearDownTestSuite() {
        delete cracks_;
        delete ref_;
    }
    static Reference* ref_;
    static post::CrackSurfaces* cracks_;
};
Reference* CrackSurfaceTest::ref_ = nullptr;
post::CrackSurfaces* CrackSurfaceTest::cracks_ = nullptr;

TEST_F(CrackSurfaceTest, FlatCutGivesTheCutsArea) {
    TempDir dir;
    const Snapshot s = throughFile(*ref_, cutAlong(*ref_, Vec3::UnitZ(), Vec3::Constant(0.5)),
                                   dir / "snapshot_000000.h5");
    ASSERT_FALSE(s.brokenBonds.empty());
    const post::CrackSurface c = cracks_->surface(s);
    const double area = c.totalReferenceArea();
    std::printf("flat cut: %zu facets, area %.6f (exact 1), error %.2e\n", c.polygons(), area,
                area - 1.0);
    EXPECT_NEAR(area, 1.0, 0.05);
    EXPECT_NEAR(c.totalProjectedArea(), 1.0, 1e-12);  // every facet on the plane
    EXPECT_EQ(c.polygons(), static_cast<std::size_t>(kCells * kCells));
    for (std::size_t p = 0; p < c.polygons(); ++p)
        EXPECT_NEAR(polygonArea(c, p), c.referenceArea[p], 1e-12);  // at rest: x = X
    for (const Vec3& x : c.points) EXPECT_NEAR(x[2], 0.5, 1e-12);   // on the plane itself
}

// The snapshot's bond damage (the peridynamic damage index) of the flat cut: per particle, the
// broken bonds it appears in over its bonds; zero beyond one support of the cut; the same for
// mirror images across the cut plane (z → 1 − z), and the layers next to the cut lose most.
TEST_F(CrackSurfaceTest, FlatCutBondDamageIsTheShareOfBrokenBonds) {
    TempDir dir;
    const Snapshot s = throughFile(*ref_, cutAlong(*ref_, Vec3::UnitZ(), Vec3::Constant(0.5)),
                                   dir / "snapshot_000000.h5");
    ASSERT_EQ(s.bondDamage.size(), static_cast<std::size_t>(ref_->size()));
    std::vector<int> broken(s.bondDamage.size(), 0);
    for (const auto& [a, b] : s.brokenBonds) {
        ++broken[static_cast<std::size_t>(a)];
        ++broken[static_cast<std::size_t>(b)];
    }
    const double h = 1.0 / kCells;
    const double support = 2.0 * 1.2 * h;  // the fixture's κ = 1.2
    double largest = 0.0;
    for (Index a = 0; a < ref_->size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const double bonds = static_cast<double>(ref_->pairs.end(a) - ref_->pairs.begin(a));
        EXPECT_DOUBLE_EQ(s.bondDamage[ia], broken[ia] / bonds);
        const double z = s.X[ia][2];
        if (std::abs(z - 0.5) > support) {
            EXPECT_EQ(s.bondDamage[ia], 0.0);
        }
        const Index mirror = a + static_cast<Index>(kCells * kCells) *
                                     (kCells - 1 - 2 * static_cast<Index>(z * kCells));
        ASSERT_NEAR(s.X[static_cast<std::size_t>(mirror)][2], 1.0 - z, 1e-12);
        EXPECT_DOUBLE_EQ(s.bondDamage[ia], s.bondDamage[static_cast<std::size_t>(mirror)]);
        largest = std::max(largest, s.bondDamage[ia]);
    }
    // The layers next to the cut (z = 0.5 ± h/2) hold the largest share.
    for (Index a = 0; a < ref_->size(); ++a) {
        if (s.bondDamage[static_cast<std::size_t>(a)] == largest) {
            EXPECT_NEAR(std::abs(s.X[static_cast<std::size_t>(a)][2] - 0.5), 0.5 * h, 1e-12);
        }
    }
    EXPECT_GT(largest, 0.25);
    EXPECT_LT(largest, 0.5);
}

TEST_F(CrackSurfaceTest, NoBrokenBondGivesNoSurface) {
    TempDir dir;
    const Snapshot s = throughFile(*ref_, State::atRest(ref_->X, ref_->pairs.neighbor.size()),
                                   dir / "snapshot_000000.h5");
    const post::CrackSurface c = cracks_->surface(s);
    EXPECT_EQ(c.polygons(), 0u);
    EXPECT_TRUE(c.points.empty());
    EXPECT_EQ(c.totalReferenceArea(), 0.0);
}

// A plane tilted by 30° (20°) about y cuts the lattice in a staircase of cell faces (the
// Voronoi facets of a cubic lattice): its area is h² per axis-neighbour pair that the plane
// separates, not the plane's area (+29.9 % at 30° here; |n_x| + |n_y| + |n_z| = 1.37 as
// h → 0). The projected area (facets on the fitted crack plane) gives the plane's area.
TEST_F(CrackSurfaceTest, TiltedCutIsTheLatticeStaircase) {
    for (const double degrees : {30.0, 20.0}) {
        TempDir dir;
        const double tilt = degrees * M_PI / 180.0;
        const Vec3 n(std::sin(tilt), 0.0, std::cos(tilt));
        const Vec3 centre = Vec3::Constant(0.5);
        const Snapshot s =
            throughFile(*ref_, cutAlong(*ref_, n, centre), dir / "snapshot_000000.h5");
        const post::CrackSurface c = cracks_->surface(s);
        const double h = 1.0 / kCells;
        long faces = 0;  // axis-neighbour pairs (a < b) on both sides of the plane
        for (const auto& [a, b] : s.brokenBonds) {
            const Vec3 d = s.X[static_cast<std::size_t>(b)] - s.X[static_cast<std::size_t>(a)];
            faces += std::abs(d.norm() - h) < 1e-9 * h;
        }
        const double staircase = static_cast<double>(faces) * h * h;
        const double plane = 1.0 / std::cos(tilt);  // through the centre, inside the cube
        const double area = c.totalReferenceArea();
        const double projected = c.totalProjectedArea();
        std::printf(
            "%.0f° cut: area %.6f, plane %.6f (error %+.1f %%), staircase %.6f; projected area "
            "%.6f (error %+.2f %%)\n",
            degrees, area, plane, 100.0 * (area / plane - 1.0), staircase, projected,
            100.0 * (projected / plane - 1.0));
        EXPECT_NEAR(area, staircase, 1e-12);
        EXPECT_EQ(c.polygons(), static_cast<std::size_t>(faces));
        EXPECT_NEAR(projected / plane, 1.0, 0.05) << degrees;
    }
}

TEST_F(CrackSurfaceTest, FacetsMoveWithAnAffineMotion) {
    TempDir dir;
    State state = cutAlong(*ref_, Vec3::UnitZ(), Vec3::Constant(0.5));
    Mat3 A;
    A << 1.1, 0.2, 0.0, -0.1, 0.9, 0.3, 0.05, 0.0, 1.2;
    const Vec3 shift(0.3, -0.2, 0.1);
    for (std::size_t a = 0; a < state.x.size(); ++a) {
        state.x[a] = A * ref_->X[a] + shift;
        state.F[a] = A;
    }
    const Snapshot s = throughFile(*ref_, state, dir / "snapshot_000000.h5");
    const post::CrackSurface moved = cracks_->surface(s);
    const Snapshot rest = throughFile(*ref_, cutAlong(*ref_, Vec3::UnitZ(), Vec3::Constant(0.5)),
                                      dir / "snapshot_000001.h5");
    const post::CrackSurface still = cracks_->surface(rest);
    ASSERT_EQ(moved.points.size(), still.points.size());
    double worst = 0.0;
    for (std::size_t p = 0; p < moved.points.size(); ++p)
        worst = std::max(worst, (moved.points[p] - (A * still.points[p] + shift)).norm());
    EXPECT_LT(worst, 1e-12);
}

// Two bodies: a striker (10 × 10 × 5 particles of spacing 0.8 h, its lattice off the cube's)
// whose face hovers h/10 above the cube's top face, then the cube, body 1 (its particles after
// the striker's). The cube is cut at mid-height, one layer below its top face (z = 15/16) and
// vertically (x = 1/2, under the striker). Each body is triangulated alone, so the cube's facets
// are those of the cube alone, bit for bit: the same polygons, areas, projected areas and points
// (the cube moved by an affine motion), their bonds shifted by the striker's particles. One
// triangulation over both bodies is printed beside.
TEST_F(CrackSurfaceTest, SecondBodyLeavesTheFacetsOfTheCubeAlone) {
    const double h = 1.0 / kCells;
    std::vector<Vec3> striker;
    const double hs = 0.8 * h;  // the striker's spacing, its lattice off the cube's
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 10; ++i)
                striker.emplace_back(0.3 + (i + 0.5) * hs, 0.27 + (j + 0.5) * hs,
                                     1.0 + 0.1 * h + (k + 0.5) * hs);
    const auto shift = static_cast<Index>(striker.size());
    std::vector<Vec3> X = striker;
    X.insert(X.end(), ref_->X.begin(), ref_->X.end());
    std::vector<Index> body(striker.size(), 0);
    body.resize(X.size(), 1);
    const post::CrackSurfaces both(X, body);
    EXPECT_EQ(both.flatBodies(), 0u);
    Mat3 A;
    A << 1.05, 0.1, 0.0, -0.05, 0.95, 0.2, 0.0, 0.03, 1.1;
    const std::pair<Vec3, Vec3> cuts[] = {{Vec3::UnitZ(), Vec3(0.5, 0.5, 0.5)},
                                          {Vec3::UnitZ(), Vec3(0.5, 0.5, 15.0 / 16.0)},
                                          {Vec3::UnitX(), Vec3(0.5, 0.5, 0.5)}};
    for (const auto& [normal, centre] : cuts) {
        TempDir dir;
        State state = cutAlong(*ref_, normal, centre);
        for (std::size_t a = 0; a < state.x.size(); ++a) {
            state.x[a] = A * ref_->X[a] + Vec3(0.01, 0.0, -0.02);
            state.F[a] = A;
        }
        const Snapshot alone = throughFile(*ref_, state, dir / "snapshot_000000.h5");
        // The two-body snapshot: the striker at rest, then the cube's particles and bonds.
        Snapshot two;
        two.X = X;
        two.state.x = striker;
        two.state.x.insert(two.state.x.end(), alone.state.x.begin(), alone.state.x.end());
        two.state.F.assign(striker.size(), Mat3::Identity());
        two.state.F.insert(two.state.F.end(), alone.state.F.begin(), alone.state.F.end());
        two.body = body;
        for (const auto& [a, b] : alone.brokenBonds)
            two.brokenBonds.push_back({a + shift, b + shift});
        const post::CrackSurface c1 = cracks_->surface(alone);
        const post::CrackSurface c2 = both.surface(two);
        const post::CrackSurface joint = post::CrackSurfaces(X).surface(two);
        std::printf(
            "cut %s: the cube alone %zu facets (%zu broken bonds without), with the "
            "striker %zu facets (%zu without); one triangulation over both bodies: %zu facets "
            "(%zu without)\n",
            normal[0] > 0.0   ? "x = 0.5"
            : centre[2] > 0.9 ? "z = 15/16"
                              : "z = 0.5",
            c1.polygons(), c1.brokenBondsWithoutFacet, c2.polygons(), c2.brokenBondsWithoutFacet,
            joint.polygons(), joint.brokenBondsWithoutFacet);
        ASSERT_GT(c1.polygons(), 0u);
        ASSERT_EQ(c2.polygons(), c1.polygons());
        EXPECT_EQ(c2.brokenBondsWithoutFacet, c1.brokenBondsWithoutFacet);
        EXPECT_EQ(c2.offsets, c1.offsets);
        EXPECT_EQ(c2.connectivity, c1.connectivity);
        EXPECT_EQ(c2.referenceArea, c1.referenceArea);
        EXPECT_EQ(c2.projectedArea, c1.projectedArea);
        ASSERT_EQ(c2.points.size(), c1.points.size());
        for (std::size_t p = 0; p < c1.points.size(); ++p) EXPECT_EQ(c2.points[p], c1.points[p]);
        for (std::size_t p = 0; p < c1.polygons(); ++p) {
            EXPECT_EQ(c2.bond[p][0], c1.bond[p][0] + shift);
            EXPECT_EQ(c2.bond[p][1], c1.bond[p][1] + shift);
        }
    }
}

// One body of two slabs: a lattice of 12 × 12 × 9 particles (spacing h = 13 mm) with its middle
// layer left out and the upper slab raised by 1e-16 m: the ghosts of the two faces across the
// gap nearly coincide. A cut through the lower slab still gives its 12 × 12 facets of area h²
// each (a merge tolerance from the ghosts' spacing would merge every Voronoi vertex into one:
// no facet at all).
TEST(CrackSurface, GhostsMeetingAcrossAGapKeepTheFacets) {
    const double h = 0.013;
    const int n = 12;
    Snapshot s;
    for (int k = 0; k < 9; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (k != 4)
                    s.X.emplace_back((i + 0.5) * h, (j + 0.5) * h,
                                     (k + 0.5) * h + (k > 4 ? 1e-16 : 0.0));
    s.state.x = s.X;
    s.state.F.assign(s.X.size(), Mat3::Identity());
    s.body.assign(s.X.size(), 0);
    // The axis bonds across z = 2h (between layers 1 and 2).
    const Index perLayer = n * n;
    for (Index a = perLayer; a < 2 * perLayer; ++a) s.brokenBonds.push_back({a, a + perLayer});
    const post::CrackSurfaces slabs(s.X, s.body);
    const post::CrackSurface c = slabs.surface(s);
    std::printf("two slabs: %zu facets, area %.9e m² (exact %.9e), %zu ghosts\n", c.polygons(),
                c.totalReferenceArea(), perLayer * h * h, slabs.ghosts());
    EXPECT_EQ(c.polygons(), static_cast<std::size_t>(perLayer));
    EXPECT_NEAR(c.totalReferenceArea(), perLayer * h * h, 1e-12 * perLayer * h * h);
}

// gsph-post on a run folder: an intact snapshot and a cut one; crack_*.vtp in cracks.pvd, the
// .vtu carries the transient flag of the particle file's overset entries.
TEST_F(CrackSurfaceTest, GsphPostWritesTheSurfacesAsVtp) {
    TempDir dir;
    Reference ref = *ref_;
    ref.overset = {OversetEntry{3, 0, Vec3::Zero(), 1.0}, OversetEntry{5, 0, Vec3::Zero(), 1.0}};
    fs::create_directories(dir / "run");
    writeSnapshot(dir / "run/snapshot_000000.h5", ref,
                  State::atRest(ref.X, ref.pairs.neighbor.size()), Provenance{});
    State cut = cutAlong(ref, Vec3::UnitZ(), Vec3::Constant(0.5));
    cut.time = 1e-3;
    writeSnapshot(dir / "run/snapshot_000001.h5", ref, cut, Provenance{});
    const auto r =
        test::runCommand(std::string(GSPH_POST_EXE) + " --no-pictures " + (dir / "run").string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream in(dir / "run/post/cracks.pvd");
    std::stringstream pvd;
    pvd << in.rdbuf();
    EXPECT_NE(pvd.str().find("crack_000000.vtp"), std::string::npos);
    EXPECT_NE(pvd.str().find("timestep=\"1.000000000e-03\" part=\"0\" file=\"crack_000001.vtp\""),
              std::string::npos)
        << pvd.str();
    const double expected[2] = {0.0, 1.0};
    for (int k = 0; k < 2; ++k) {
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName((dir / ("run/post/crack_00000" + std::to_string(k) + ".vtp")).c_str());
        reader->Update();
        vtkPolyData* poly = reader->GetOutput();
        double area = 0.0;
        if (poly->GetNumberOfCells() > 0) {
            vtkDataArray* a = poly->GetCellData()->GetArray("reference_area");
            ASSERT_NE(a, nullptr);
            vtkDataArray* projected = poly->GetCellData()->GetArray("projected_area");
            ASSERT_NE(projected, nullptr);
            double sum = 0.0;
            for (vtkIdType c = 0; c < projected->GetNumberOfTuples(); ++c)
                sum += projected->GetTuple1(c);
            EXPECT_NEAR(sum, expected[k], 1e-12);
            ASSERT_NE(poly->GetCellData()->GetArray("bond"), nullptr);
            EXPECT_EQ(poly->GetCellData()->GetArray("bond")->GetNumberOfComponents(), 2);
            for (vtkIdType c = 0; c < a->GetNumberOfTuples(); ++c) area += a->GetTuple1(c);
        }
        EXPECT_NEAR(area, expected[k], 0.05) << k;
        EXPECT_EQ(poly->GetNumberOfCells(), k == 0 ? 0 : kCells * kCells);
    }
    vtkNew<vtkXMLUnstructuredGridReader> grid;
    grid->SetFileName((dir / "run/post/snapshot_000001.vtu").c_str());
    grid->Update();
    vtkDataArray* transient = grid->GetOutput()->GetPointData()->GetArray("transient");
    ASSERT_NE(transient, nullptr);
    for (vtkIdType a = 0; a < transient->GetNumberOfTuples(); ++a)
        EXPECT_EQ(transient->GetTuple1(a), (a == 3 || a == 5) ? 1.0 : 0.0) << a;
}

}  // namespace
}  // namespace gsph
