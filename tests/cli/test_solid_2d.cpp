// SPDX-License-Identifier: MIT
// gsph-post on 2-D runs (a particle file of dimension 2 and snapshots written in code): the
// solid is the section's quadrilaterals in the x-y plane, at the corners at rest and following
// a uniform stretch to round-off; --revolve N sweeps it about the y axis into N sectors whose
// volume is the N-gon's share of the solid of revolution to round-off, with the vectors and
// tensors turned into each sector; a 3-D particle file with --revolve is a one-line error.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCellSizeFilter.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <type_traits>

#include "core/error.hpp"
#include "hex_solid.hpp"
#include "io/particle_file.hpp"
#include "io/snapshot.hpp"
#include "support/process.hpp"
#include "tools/temp_dir.hpp"
#include "vtk_output.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::quote;
using test::runCommand;
using test::TempDir;

// The section: a rectangle of kCells[0] × kCells[1] cells, x = r in [0, kR] (on the axis),
// y in [kY0, kY0 + kL].
constexpr int kCells[2] = {4, 3};
constexpr double kR = 0.4, kL = 0.3, kY0 = -0.1;

// A rectangle of nx × ny cells, x in [0, R], y in [y0, y0 + L], as a particle file: dimension
// 2 (nodes at z = 0 and z = 1, X_z = 0, areas as volumes), or 3 (the same cells as a slab of
// unit depth, X_z = ½).
ParticleFile rectangle(int dimension, int nx = kCells[0], int ny = kCells[1], double R = kR,
                       double L = kL, double y0 = kY0) {
    ParticleFile f;
    f.dimension = dimension;
    const double dx = R / nx, dy = L / ny;
    LatticeSpace space;
    space.cells = {nx, ny, 1};
    f.spaces.push_back(space);
    f.bodies.push_back({"disc", -1});
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            f.X.emplace_back((i + 0.5) * dx, y0 + (j + 0.5) * dy, dimension == 2 ? 0.0 : 0.5);
            f.theta.emplace_back(i + 0.5, j + 0.5, dimension == 2 ? 0.0 : 0.5);
            f.volume.push_back(dx * dy);
            f.space.push_back(0);
            f.body.push_back(0);
            f.latticeIndex.push_back({i, j, 0});
        }
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) f.nodes.emplace_back(i * dx, y0 + j * dy, k);
    return f;
}

// A snapshot of the file's particles moved by x = A X + c (A in the plane, F = A with F_zz =
// hoop: an axisymmetric run's r/R, which must not change the section), v = (2, −1, 0) and a
// stress with a hoop component.
void writeStretched(const fs::path& path, const ParticleFile& f, const Mat3& A, const Vec3& c,
                    double time, bool axisymmetric) {
    Reference ref;
    ref.dim = Dimension{f.dimension, axisymmetric};
    ref.X = f.X;
    ref.quadVolume = f.volume;
    ref.body = f.body;
    ref.space = f.space;
    ref.pairs.offset.assign(f.X.size() + 1, 0);  // no neighbours: no bonds
    State state;
    const auto n = static_cast<std::size_t>(f.size());
    state.forEachArray([&](const Field& field, auto& array) {
        using T = typename std::decay_t<decltype(array)>::value_type;
        if (!field.isSavedIn(kSnapshot)) return;
        if constexpr (std::is_same_v<T, Vec3>)
            array.assign(n, Vec3::Zero());
        else if constexpr (std::is_same_v<T, Mat3>)
            array.assign(n, Mat3::Identity());
        else
            array.assign(n, T(0));
    });
    state.time = time;
    for (std::size_t a = 0; a < n; ++a) {
        state.x[a] = A * f.X[a] + c;
        state.F[a] = A;
        state.v[a] = Vec3(2.0, -1.0, 0.0);
        state.cauchy[a] << 1e6 * (1.0 + a), 3e5, 0.0, 3e5, -2e6, 0.0, 0.0, 0.0, 5e5 * (1.0 + a);
    }
    writeSnapshot(path, ref, state, Provenance{});
}

struct Grid {
    vtkSmartPointer<vtkUnstructuredGrid> grid;
    vtkUnstructuredGrid* operator->() const { return grid.GetPointer(); }
};

Grid readGrid(const fs::path& vtu) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(vtu.c_str());
    reader->Update();
    Grid g{vtkSmartPointer<vtkUnstructuredGrid>::New()};
    g.grid->ShallowCopy(reader->GetOutput());
    return g;
}

Vec3 pointOf(const Grid& g, vtkIdType i) {
    Vec3 p;
    g->GetPoint(i, p.data());
    return p;
}

// A 2-D run folder: the rectangle's particle file (found as RUNDIR/particles.h5), a snapshot at
// rest and one stretched by kA.
const Mat3 kA = (Mat3() << 1.2, 0.0, 0.0, 0.3, 0.9, 0.0, 0.0, 0.0, 1.3).finished();
const Vec3 kShift(0.0, 0.02, 0.0);  // along the axis: an axisymmetric motion

fs::path makeRun(const TempDir& dir, int dimension, bool axisymmetric = true) {
    const fs::path run = dir / ("run" + std::to_string(dimension) + "d");
    fs::create_directories(run);
    const ParticleFile f = rectangle(dimension);
    writeParticleFile(run / "particles.h5", f);
    axisymmetric = axisymmetric && dimension == 2;
    writeStretched(run / "snapshot_000000.h5", f, Mat3::Identity(), Vec3::Zero(), 0.0,
                   axisymmetric);
    writeStretched(run / "snapshot_000001.h5", f, kA, kShift, 1e-5, axisymmetric);
    return run;
}

// The solid of a 2-D file: 12 quadrilaterals in the plane, nodes at the corners at rest and at
// A X + c after the stretch, area det(A_2) R L; pictures of the section do not fail.
TEST(PlanarSolid, QuadrilateralsFollowAUniformStretch) {
    TempDir dir;
    const fs::path run = makeRun(dir, 2);
    const auto r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("12 quadrilaterals"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(run / "post/final_von_mises.png"));
    EXPECT_TRUE(fs::exists(run / "post/snapshot_000001.vtu"));
    // A planar run has no crack surfaces: said once, no empty files.
    EXPECT_NE(r.out.find("a planar (2-D) run: no crack surfaces"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(run / "post/cracks.pvd"));
    EXPECT_FALSE(fs::exists(run / "post/crack_000000.vtp"));

    const Grid rest = readGrid(run / "post/solid_000000_s0.vtu");
    const Grid moved = readGrid(run / "post/solid_000001_s0.vtu");
    ASSERT_EQ(rest->GetNumberOfCells(), kCells[0] * kCells[1]);
    ASSERT_EQ(rest->GetNumberOfPoints(), (kCells[0] + 1) * (kCells[1] + 1));
    ASSERT_EQ(moved->GetNumberOfPoints(), rest->GetNumberOfPoints());
    // At rest every node is a corner of the rectangle's lattice.
    const double dx = kR / kCells[0], dy = kL / kCells[1];
    double cornerError = 0.0, stretchError = 0.0;
    for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i) {
        const Vec3 p = pointOf(rest, i);
        const Vec3 corner(std::round(p[0] / dx) * dx, kY0 + std::round((p[1] - kY0) / dy) * dy,
                          0.0);
        cornerError = std::max(cornerError, (p - corner).norm());
        stretchError = std::max(stretchError, (pointOf(moved, i) - (kA * p + kShift)).norm());
    }
    double area = 0.0;
    for (vtkIdType c = 0; c < moved->GetNumberOfCells(); ++c) {
        EXPECT_EQ(rest->GetCellType(c), VTK_QUAD);
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        moved->GetCellPoints(c, npts, ids);
        ASSERT_EQ(npts, 4);
        std::array<Vec3, 4> x;
        for (int k = 0; k < 4; ++k) x[k] = pointOf(moved, ids[k]);
        const double a = post::quadrilateralArea(x);
        EXPECT_GT(a, 0.0) << "cell " << c << " turns clockwise";
        area += a;
    }
    const double expectedArea = (kA(0, 0) * kA(1, 1) - kA(0, 1) * kA(1, 0)) * kR * kL;
    std::printf(
        "[ measured ] 2-D solid: corners at rest to %.2e m, stretched nodes off A X + c by %.2e "
        "m, area %.15g m² (det A₂ R L %.15g m²)\n",
        cornerError, stretchError, area, expectedArea);
    EXPECT_LT(cornerError, 1e-15);
    EXPECT_LT(stretchError, 1e-15);
    EXPECT_NEAR(area, expectedArea, 1e-14 * expectedArea);
    // The fields are cell data of each quadrilateral's particle.
    vtkDataArray* id = moved->GetCellData()->GetArray("id");
    ASSERT_NE(id, nullptr);
    for (vtkIdType c = 0; c < moved->GetNumberOfCells(); ++c) EXPECT_EQ(id->GetTuple1(c), c);
    ASSERT_NE(moved->GetCellData()->GetArray("stress"), nullptr);
    ASSERT_NE(moved->GetPointData()->GetArray("node_displacement"), nullptr);
}

// A 2-D file without /spaces/nodes: the estimated nodes are the lattice's corners in the plane
// z = 0 (the lattice is an affine map of the cells).
TEST(PlanarSolid, EstimatedNodesAreTheCorners) {
    ParticleFile f = rectangle(2);
    const std::vector<Vec3> given = [&] {
        const post::HexSolid solid(f, f.X, "rectangle.h5");
        return solid.pieces().at(0).nodeX;
    }();
    f.nodes.clear();
    const post::HexSolid solid(f, f.X, "rectangle.h5");
    ASSERT_TRUE(solid.estimatedNodes());
    ASSERT_EQ(solid.quadrilaterals(), 12u);
    const std::vector<Vec3>& estimated = solid.pieces().at(0).nodeX;
    ASSERT_EQ(estimated.size(), given.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < given.size(); ++i)
        worst = std::max(worst, (estimated[i] - given[i]).norm());
    std::printf("[ measured ] 2-D estimated nodes off the corners by %.2e m\n", worst);
    EXPECT_LT(worst, 1e-15);
    EXPECT_NEAR(solid.referenceVolume(), kR * kL, 1e-15);
}

// Σ of the cells' volumes by VTK's own cell size filter (signed: an inverted cell would count
// against the sum), and the smallest of them.
std::pair<double, double> cellVolumes(const Grid& g) {
    vtkNew<vtkCellSizeFilter> sizes;
    sizes->SetInputData(g.grid);
    sizes->ComputeVolumeOn();
    sizes->Update();
    vtkDataArray* volume =
        vtkDataSet::SafeDownCast(sizes->GetOutput())->GetCellData()->GetArray("Volume");
    double total = 0.0, smallest = INFINITY;
    for (vtkIdType c = 0; c < volume->GetNumberOfTuples(); ++c) {
        total += volume->GetTuple1(c);
        smallest = std::min(smallest, volume->GetTuple1(c));
    }
    return {total, smallest};
}

// --revolve 8: 8 × 12 cells (wedges along the axis), volume N/(2π) sin(2π/N) · π R² L at rest
// and the same share of the stretched section's solid of revolution; velocity and stress
// turned into each sector.
TEST(RevolvedSolid, EightSectorsOfARectangleOnTheAxis) {
    TempDir dir;
    const fs::path run = makeRun(dir, 2);
    constexpr int kSectors = 8;
    const auto r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()) +
                              " --no-pictures --revolve " + std::to_string(kSectors));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("revolved solid"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(run / "post/solid_revolved.pvd"));
    EXPECT_TRUE(fs::exists(run / "post/solid_revolved_000001.vtm"));
    const double share =
        kSectors / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi / kSectors);

    const Grid rest = readGrid(run / "post/solid_revolved_000000_s0.vtu");
    ASSERT_EQ(rest->GetNumberOfCells(), kSectors * kCells[0] * kCells[1]);
    // One node per sector off the axis, one node for every sector on it.
    EXPECT_EQ(rest->GetNumberOfPoints(), kSectors * kCells[0] * (kCells[1] + 1) + (kCells[1] + 1));
    int wedges = 0;
    for (vtkIdType c = 0; c < rest->GetNumberOfCells(); ++c) {
        const int type = rest->GetCellType(c);
        EXPECT_TRUE(type == VTK_HEXAHEDRON || type == VTK_WEDGE) << type;
        wedges += type == VTK_WEDGE;
    }
    EXPECT_EQ(wedges, kSectors * kCells[1]);  // the column of cells on the axis
    const auto [restVolume, restSmallest] = cellVolumes(rest);
    const double cylinder = share * std::numbers::pi * kR * kR * kL;
    EXPECT_GT(restSmallest, 0.0);

    const Grid moved = readGrid(run / "post/solid_revolved_000001_s0.vtu");
    const auto [movedVolume, movedSmallest] = cellVolumes(moved);
    // x' = A_00 X, y' = A_10 X + A_11 Y: ∫ r dA = A_00 det A₂ R² L / 2.
    const double stretched =
        share * 2.0 * std::numbers::pi * kA(0, 0) * (kA(0, 0) * kA(1, 1)) * 0.5 * kR * kR * kL;
    EXPECT_GT(movedSmallest, 0.0);
    std::printf(
        "[ measured ] --revolve %d: at rest %.15g m³ against the %d-gon's share %.6f of π R² L "
        "(%.15g m³), relative %.2e; stretched %.15g m³ against %.15g m³, relative %.2e\n",
        kSectors, restVolume, kSectors, share, cylinder, (restVolume - cylinder) / cylinder,
        movedVolume, stretched, (movedVolume - stretched) / stretched);
    EXPECT_NEAR(restVolume, cylinder, 1e-12 * cylinder);
    EXPECT_NEAR(movedVolume, stretched, 1e-12 * stretched);

    // Each cell carries its particle's fields, turned by its sector's middle angle φ: v = (2,
    // −1, 0) in (r, axis, hoop) is (2 cos φ, −1, 2 sin φ); σ_θθ = e_θ·σ e_θ keeps its value.
    vtkCellData* cd = moved->GetCellData();
    vtkDataArray* velocity = cd->GetArray("velocity");
    vtkDataArray* stress = cd->GetArray("stress");
    vtkDataArray* id = cd->GetArray("id");
    ASSERT_NE(velocity, nullptr);
    ASSERT_NE(stress, nullptr);
    ASSERT_NE(id, nullptr);
    double worstVelocity = 0.0, worstHoop = 0.0;
    for (vtkIdType c = 0; c < moved->GetNumberOfCells(); ++c) {
        const vtkIdType sector = c / (kCells[0] * kCells[1]);
        EXPECT_EQ(id->GetTuple1(c), c % (kCells[0] * kCells[1]));
        const double phi = (sector + 0.5) * 2.0 * std::numbers::pi / kSectors;
        const double* v = velocity->GetTuple3(c);
        worstVelocity = std::max(
            worstVelocity,
            (Vec3(v[0], v[1], v[2]) - Vec3(2.0 * std::cos(phi), -1.0, 2.0 * std::sin(phi))).norm());
        const double* s = stress->GetTuple9(c);
        Mat3 sigma;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) sigma(i, j) = s[3 * i + j];
        const Vec3 hoop(-std::sin(phi), 0.0, std::cos(phi));
        const double hoopStress = 5e5 * (1.0 + static_cast<double>(id->GetTuple1(c)));
        worstHoop = std::max(worstHoop, std::abs(hoop.dot(sigma * hoop) - hoopStress) / hoopStress);
        EXPECT_NEAR(sigma(1, 1), -2e6, 1e-9);
    }
    EXPECT_LT(worstVelocity, 1e-14);
    EXPECT_LT(worstHoop, 1e-14);
}

// An axisymmetric gsph-solve run (a steel cylinder, 10 × 20 cells, flung outwards at 20 m/s)
// revolved into 16 sectors: every cell has a positive volume, the whole is the 16-gon's share of
// the written section's solid of revolution to round-off, and each cell's velocity is its
// particle's turned into the sector: no hoop component, the axial one unchanged.
TEST(RevolvedSolid, AxisymmetricSolverRun) {
    TempDir dir;
    writeParticleFile(dir / "cylinder.h5", rectangle(2, 10, 20, 0.01, 0.02, 0.0));
    std::ofstream(dir / "case.toml") << R"([run]
particles = "cylinder.h5"
end_time = 2.0e-6
output_interval = 1.0e-6
dimension = "axisymmetric"
[[material]]
name = "steel"
model = "elastic"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.3
[[body]]
group = "disc"
material = "steel"
velocity = [20.0, 0.0, 0.0]
)";
    auto r = runCommand(std::string(GSPH_SOLVE_EXE) + " " + quote((dir / "case.toml").string()) +
                        " -o " + quote((dir / "run").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    constexpr int kSectors = 16;
    r = runCommand(std::string(GSPH_POST_EXE) + " " + quote((dir / "run").string()) +
                   " --no-pictures --revolve " + std::to_string(kSectors));
    ASSERT_EQ(r.status, 0) << r.err;
    const Grid section = readGrid(dir / "run/post/solid_000002_s0.vtu");
    const Grid revolved = readGrid(dir / "run/post/solid_revolved_000002_s0.vtu");
    const vtkIdType cells = section->GetNumberOfCells();
    ASSERT_EQ(cells, 200);
    ASSERT_EQ(revolved->GetNumberOfCells(), kSectors * cells);
    // 2π ∫ r dA of the written quadrilaterals (Σ over edges of (r_i + r_j)(r_i y_j − r_j y_i)/6;
    // the axis nodes' r is 0 in the revolved solid, and so taken here).
    double moment = 0.0, worstZ = 0.0, axisDrift = 0.0;
    for (vtkIdType c = 0; c < cells; ++c) {
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        section->GetCellPoints(c, npts, ids);
        for (int k = 0; k < 4; ++k) {
            Vec3 p = pointOf(section, ids[k]), q = pointOf(section, ids[(k + 1) % 4]);
            worstZ = std::max(worstZ, std::abs(p[2]));
            const double reference =
                p[0] -
                section->GetPointData()->GetArray("node_displacement")->GetComponent(ids[k], 0);
            const double referenceNext = q[0] - section->GetPointData()
                                                    ->GetArray("node_displacement")
                                                    ->GetComponent(ids[(k + 1) % 4], 0);
            if (std::abs(reference) < 1e-12) {
                axisDrift = std::max(axisDrift, std::abs(p[0]));
                p[0] = 0.0;
            }
            if (std::abs(referenceNext) < 1e-12) q[0] = 0.0;
            moment += (p[0] + q[0]) * (p[0] * q[1] - q[0] * p[1]) / 6.0;
        }
    }
    EXPECT_EQ(worstZ, 0.0);
    const double share =
        kSectors / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi / kSectors);
    const double expected = share * 2.0 * std::numbers::pi * moment;
    const auto [volume, smallest] = cellVolumes(revolved);
    std::printf(
        "[ measured ] axisymmetric run, --revolve %d: %.15g m³ against the %d-gon's share of 2π "
        "∫ r dA %.15g m³, relative %.2e; smallest cell %.3e m³; the section's axis nodes lie "
        "up to %.2e m off the axis (put on it)\n",
        kSectors, volume, kSectors, expected, (volume - expected) / expected, smallest, axisDrift);
    EXPECT_GT(smallest, 0.0);
    EXPECT_NEAR(volume, expected, 1e-12 * expected);
    vtkDataArray* flat = section->GetCellData()->GetArray("velocity");
    vtkDataArray* turned = revolved->GetCellData()->GetArray("velocity");
    ASSERT_NE(flat, nullptr);
    ASSERT_NE(turned, nullptr);
    double worst = 0.0;
    for (vtkIdType c = 0; c < revolved->GetNumberOfCells(); ++c) {
        const double phi = (c / cells + 0.5) * 2.0 * std::numbers::pi / kSectors;
        const double* v = flat->GetTuple3(c % cells);
        const double vr = v[0], vy = v[1];
        const double* w = turned->GetTuple3(c);
        worst = std::max(
            worst,
            (Vec3(w[0], w[1], w[2]) - Vec3(vr * std::cos(phi), vy, vr * std::sin(phi))).norm());
    }
    EXPECT_LT(worst, 1e-12);
}

// A section reaching x < 0 is no half-plane of a body of revolution: refused, naming the file.
TEST(RevolvedSolid, SectionAcrossTheAxisIsRefused) {
    ParticleFile f = rectangle(2);
    for (Vec3& X : f.X) X[0] -= 0.1;
    for (Vec3& X : f.nodes) X[0] -= 0.1;
    const post::HexSolid solid(f, f.X, "across.h5");
    try {
        post::requireRevolvableSection(solid, 8, "across.h5");
        FAIL() << "a section across the axis must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("across.h5: a node of space 0 lies at (-0.1, "),
                  std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(post::requireRevolvableSection(
        post::HexSolid(rectangle(2), rectangle(2).X, "rectangle.h5"), 8, "rectangle.h5"));
}

// --revolve on a 3-D particle file: one line naming the file and the fault, exit code 1; and
// fewer than 3 sectors is a bad option.
TEST(RevolvedSolid, ThreeDimensionalFileIsRefused) {
    TempDir dir;
    const fs::path run = makeRun(dir, 3);
    auto r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()) +
                        " --no-pictures --revolve 8");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find((run / "particles.h5").string() + ": a 3-D particle file"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(run / "post/solid_revolved.pvd"));
    r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()) +
                   " --no-pictures --revolve 2");
    EXPECT_EQ(r.status, 1) << r.out;
    // Without --revolve the same 3-D file still gives its hexahedra.
    r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()) + " --no-pictures");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("12 hexahedra"), std::string::npos) << r.out;
}

// --revolve on a plane-strain run's snapshots (a 2-D file, the snapshot not marked
// axisymmetric): one line naming the snapshot, exit code 1, nothing revolved.
TEST(RevolvedSolid, PlaneStrainRunIsRefused) {
    TempDir dir;
    const fs::path run = makeRun(dir, 2, false);
    const auto r = runCommand(std::string(GSPH_POST_EXE) + " " + quote(run.string()) +
                              " --no-pictures --revolve 8");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("snapshot_000000.h5: --revolve sweeps an axisymmetric run's section"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(run / "post/solid_revolved.pvd"));
}

}  // namespace
}  // namespace gsph

namespace gsph {
namespace {

// The splat radius is half the edge of the particle's current cell: a cube in 3-D, a square of
// its area per metre in plane strain, of its ring's cross-section in an axisymmetric run.
TEST(SplatRadius, HalfTheCurrentCellsEdgeInEachDimension) {
    Snapshot s;
    s.volume = {8e-9};
    s.state.F = {Vec3(1.5, 1.0, 1.0).asDiagonal()};
    s.state.x = {Vec3(0.25, 0.0, 0.0)};
    EXPECT_NEAR(post::splatRadius(s, 0), 0.5 * std::cbrt(1.2e-8), 1e-18);
    s.dimension = 2;
    s.volume = {4e-6};  // 2 mm × 2 mm per metre of depth
    EXPECT_NEAR(post::splatRadius(s, 0), 0.5 * std::sqrt(6e-6), 1e-18);
    s.axisymmetric = true;  // the ring of that section at R = 0.2, now at r = 0.25, F_zz = 1.25
    s.volume = {2 * std::numbers::pi * 0.2 * 4e-6};
    s.state.F = {Vec3(1.5, 1.0, 1.25).asDiagonal()};
    EXPECT_NEAR(post::splatRadius(s, 0), 0.5 * std::sqrt(6e-6), 1e-15);
}

}  // namespace
}  // namespace gsph
