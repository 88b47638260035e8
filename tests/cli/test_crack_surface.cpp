// SPDX-License-Identifier: MIT
// Crack surfaces of gsph-post (post/crack_surface.hpp): a block of 16³ particles whose bonds
// crossing a plane are broken (set in State::bondIntact, written with the library's snapshot
// writer) gives Voronoi facets whose area is the cut's area; no broken bond gives no facet;
// the facets move with an affine motion exactly; gsph-post writes them as .vtp in cracks.pvd.
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
