// SPDX-License-Identifier: MIT
// gsph-post on a real run: the arrays read back from the .vtu with VTK's reader equal the
// snapshot's, the .pvd lists every snapshot, and the pictures are real (expected size, not
// blank), also at chosen times and for the momentum. Bad input gets a one-line error.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/LU>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/hdf5_file.hpp"
#include "io/snapshot.hpp"
#include "pictures.hpp"
#include "support/sample_run.hpp"
#include "tools/temp_dir.hpp"
#include "vtk_output.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::runCommand;
using test::TempDir;

class PostRun : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        auto r = test::makeSampleParticles(*dir_ / "particles.h5");
        ASSERT_EQ(r.status, 0) << r.err;
        r = test::runSampleCase(*dir_ / "particles.h5", *dir_ / "run");
        ASSERT_EQ(r.status, 0) << r.err;
        r = runCommand(std::string(GSPH_POST_EXE) + " " + (*dir_ / "run").string());
        ASSERT_EQ(r.status, 0) << r.err;
        solidLine_ = r.out;
        r = runCommand(std::string(GSPH_POST_EXE) + " " + (*dir_ / "run").string() + " -o " +
                       (*dir_ / "pictures").string() + " --field displacement --times 1e-5,1");
        ASSERT_EQ(r.status, 0) << r.err;
        // The same particle file as an older gsph-preproc wrote it (no /spaces/nodes, 1.2).
        fs::copy_file(*dir_ / "particles.h5", *dir_ / "old.h5");
        r = runCommand("/usr/bin/python3 -c \"import h5py; f = h5py.File('" +
                       (*dir_ / "old.h5").string() +
                       "', 'r+'); del f['spaces/nodes']; f.attrs['format_version'] = '1.2'\"");
        ASSERT_EQ(r.status, 0) << r.err;
        r = runCommand(std::string(GSPH_POST_EXE) + " " + (*dir_ / "run").string() + " -o " +
                       (*dir_ / "post_old").string() + " --no-pictures --particles " +
                       (*dir_ / "old.h5").string());
        ASSERT_EQ(r.status, 0) << r.err;
        oldFileOutput_ = r.out;
    }
    static void TearDownTestSuite() { delete dir_; }
    static TempDir* dir_;
    static std::string solidLine_, oldFileOutput_;
};
TempDir* PostRun::dir_ = nullptr;
std::string PostRun::solidLine_, PostRun::oldFileOutput_;

// Every field of the snapshot, read back with VTK's reader: float64 arrays round-trip exactly.
TEST_F(PostRun, VtuArraysEqualTheSnapshot) {
    const Snapshot snap = readSnapshot(*dir_ / "run/snapshot_000007.h5");
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((*dir_ / "run/post/snapshot_000007.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), snap.size());
    ASSERT_EQ(grid->GetNumberOfCells(), snap.size());
    vtkPointData* pd = grid->GetPointData();
    const std::vector<std::pair<const char*, int>> arrays = {
        {"displacement", 3},     {"velocity", 3},   {"stress", 9},
        {"von_mises", 1},        {"pressure", 1},   {"plastic_strain", 1},
        {"temperature", 1},      {"damage", 1},     {"J", 1},
        {"reference_volume", 1}, {"body", 1},       {"space", 1},
        {"transient", 1},        {"bond_damage", 1}};
    for (const auto& [name, components] : arrays) {
        ASSERT_NE(pd->GetArray(name), nullptr) << name;
        EXPECT_EQ(pd->GetArray(name)->GetNumberOfComponents(), components) << name;
    }
    // The stress tensor's components carry their names, as ParaView lists them.
    const char* const components[] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    for (int c = 0; c < 9; ++c)
        EXPECT_STREQ(pd->GetArray("stress")->GetComponentName(c), components[c]) << c;
    // Every per-particle dataset of the snapshot states its unit.
    const h5::File file(*dir_ / "run/snapshot_000007.h5", h5::File::Mode::ReadOnly);
    EXPECT_EQ(file.stringAttribute("/particles/v", "units"), "m/s");
    EXPECT_EQ(file.stringAttribute("/particles/stress", "units"), "Pa");
    EXPECT_EQ(file.stringAttribute("/particles/temperature", "units"), "K");
    EXPECT_EQ(file.stringAttribute("/particles/volume", "units"), "m^3");
    auto scalar = [&](const char* name, vtkIdType a) { return pd->GetArray(name)->GetTuple1(a); };
    double worst = 0.0;
    for (vtkIdType a = 0; a < snap.size(); ++a) {
        const auto i = static_cast<std::size_t>(a);
        EXPECT_EQ(grid->GetCellType(a), VTK_VERTEX);
        double p[3];
        grid->GetPoint(a, p);
        worst = std::max(worst, (Vec3(p[0], p[1], p[2]) - snap.state.x[i]).norm());
        const double* u = pd->GetArray("displacement")->GetTuple3(a);
        worst = std::max(worst, (Vec3(u[0], u[1], u[2]) - (snap.state.x[i] - snap.X[i])).norm());
        const double* v = pd->GetArray("velocity")->GetTuple3(a);
        worst = std::max(worst, (Vec3(v[0], v[1], v[2]) - snap.state.v[i]).norm());
        const double* s = pd->GetArray("stress")->GetTuple9(a);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(s[3 * r + c], snap.state.cauchy[i](r, c));
        EXPECT_EQ(scalar("von_mises", a), post::vonMises(snap.state.cauchy[i]));
        EXPECT_EQ(scalar("pressure", a), -snap.state.cauchy[i].trace() / 3.0);
        EXPECT_EQ(scalar("plastic_strain", a), snap.state.plasticStrain[i]);
        EXPECT_EQ(scalar("temperature", a), snap.state.temperature[i]);
        EXPECT_EQ(scalar("damage", a), snap.state.damage[i]);
        EXPECT_EQ(scalar("J", a), snap.state.F[i].determinant());
        EXPECT_EQ(scalar("id", a), static_cast<double>(a));
        EXPECT_EQ(scalar("radius", a),
                  0.5 * std::cbrt(snap.volume[i] * snap.state.F[i].determinant()));
        EXPECT_EQ(scalar("reference_volume", a), snap.volume[i]);
        EXPECT_EQ(scalar("body", a), snap.body[i]);
        EXPECT_EQ(scalar("space", a), snap.space[i]);
        EXPECT_EQ(scalar("transient", a), snap.transient[i]);
    }
    EXPECT_EQ(worst, 0.0);  // written as float64: exact round trip
}

// The solid: solid.pvd of one .vtm per snapshot, each with one block (the bar is one space) of
// VTK_HEXAHEDRON cells, one per particle, whose cell arrays are the particles'; field data
// TimeValue, body and set names, units; the point cloud carries the same field data.
TEST_F(PostRun, SolidReadsBackWithVtk) {
    const Snapshot snap = readSnapshot(*dir_ / "run/snapshot_000007.h5");
    EXPECT_TRUE(fs::exists(*dir_ / "run/post/solid.pvd"));
    vtkNew<vtkXMLMultiBlockDataReader> blocks;
    blocks->SetFileName((*dir_ / "run/post/solid_000007.vtm").c_str());
    blocks->Update();
    auto* mb = vtkMultiBlockDataSet::SafeDownCast(blocks->GetOutput());
    ASSERT_NE(mb, nullptr);
    ASSERT_EQ(mb->GetNumberOfBlocks(), 1u);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((*dir_ / "run/post/solid_000007_s0.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfCells(), snap.size());
    EXPECT_EQ(grid->GetNumberOfPoints(), 21 * 5 * 5);  // the 20×4×4 cells' corners
    vtkCellData* cd = grid->GetCellData();
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
        EXPECT_EQ(grid->GetCellType(c), VTK_HEXAHEDRON);
        const auto a = static_cast<std::size_t>(cd->GetArray("id")->GetTuple1(c));
        ASSERT_LT(a, static_cast<std::size_t>(snap.size()));
        EXPECT_EQ(cd->GetArray("von_mises")->GetTuple1(c), post::vonMises(snap.state.cauchy[a]));
        for (int k = 0; k < 9; ++k)
            EXPECT_EQ(cd->GetArray("stress")->GetComponent(c, k),
                      snap.state.cauchy[a](k / 3, k % 3));
        EXPECT_EQ(cd->GetArray("radius")->GetTuple1(c),
                  0.5 * std::cbrt(snap.volume[a] * snap.state.F[a].determinant()));
        EXPECT_EQ(cd->GetArray("temperature")->GetTuple1(c), snap.state.temperature[a]);
    }
    EXPECT_STREQ(cd->GetArray("stress")->GetComponentName(8), "ZZ");
    for (const fs::path& vtu :
         {*dir_ / "run/post/solid_000007_s0.vtu", *dir_ / "run/post/snapshot_000007.vtu"}) {
        vtkNew<vtkXMLUnstructuredGridReader> r;
        r->SetFileName(vtu.c_str());
        r->Update();
        vtkFieldData* fd = r->GetOutput()->GetFieldData();
        ASSERT_NE(fd->GetArray("TimeValue"), nullptr) << vtu;
        EXPECT_EQ(fd->GetArray("TimeValue")->GetTuple1(0), snap.state.time);
        auto* sets = vtkStringArray::SafeDownCast(fd->GetAbstractArray("set_names"));
        ASSERT_NE(sets, nullptr) << vtu;
        ASSERT_EQ(sets->GetNumberOfValues(), 2);
        EXPECT_EQ(sets->GetValue(0), "clamp");
        EXPECT_EQ(sets->GetValue(1), "load");
        EXPECT_NE(fd->GetAbstractArray("body_names"), nullptr) << vtu;
        auto* units = vtkStringArray::SafeDownCast(fd->GetAbstractArray("units"));
        ASSERT_NE(units, nullptr) << vtu;
        EXPECT_GE(units->LookupValue("stress=Pa"), 0);
    }
    // gsph-post says where the nodes came from and how the volume compares with Σ V J.
    EXPECT_NE(solidLine_.find("1 spaces, 320 hexahedra, nodes from"), std::string::npos)
        << solidLine_;
    EXPECT_NE(solidLine_.find("solid volume: reference"), std::string::npos) << solidLine_;
}

// A particle file without nodes (an older gsph-preproc's) still gives the solid, from nodes
// estimated from the particles, and gsph-post says so.
TEST_F(PostRun, OldParticleFileWithoutNodesStillGivesTheSolid) {
    EXPECT_NE(oldFileOutput_.find("nodes estimated from the particles: no /spaces/nodes in"),
              std::string::npos)
        << oldFileOutput_;
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((*dir_ / "post_old/solid_000010_s0.vtu").c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 320);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 21 * 5 * 5);
}

// A particle file given with --particles that does not belong to the run is an error.
TEST_F(PostRun, AnotherRunsParticleFileIsAClearError) {
    TempDir other;
    auto r = runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                        (test::kSourceDir / "geometries/graded_bar.geo").string() +
                        " --set refine=2 -o " + (other / "p.h5").string());
    ASSERT_EQ(r.status, 0) << r.err;
    r = runCommand(std::string(GSPH_POST_EXE) + " " + (*dir_ / "run").string() + " -o " +
                   (other / "post").string() + " --no-pictures --particles " +
                   (other / "p.h5").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("not the run's particle file"), std::string::npos) << r.err;
}

// run.pvd and cracks.pvd list every snapshot with its /time as the timestep (what ParaView
// shows on its time axis); the sample run breaks no bond: its crack surfaces are empty.
TEST_F(PostRun, PvdListsEverySnapshot) {
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    const std::string pvd = slurp(*dir_ / "run/post/run.pvd");
    const std::string cracks = slurp(*dir_ / "run/post/cracks.pvd");
    for (int k = 0; k <= 10; ++k) {
        char index[16], entry[160];
        std::snprintf(index, sizeof index, "%06d", k);
        const double t =
            readSnapshot(*dir_ / "run" / ("snapshot_" + std::string(index) + ".h5")).state.time;
        std::snprintf(entry, sizeof entry, "timestep=\"%.9e\" part=\"0\" file=\"snapshot_%s.vtu\"",
                      t, index);
        EXPECT_NE(pvd.find(entry), std::string::npos) << entry;
        EXPECT_TRUE(fs::exists(*dir_ / "run/post" / ("snapshot_" + std::string(index) + ".vtu")));
        std::snprintf(entry, sizeof entry, "timestep=\"%.9e\" part=\"0\" file=\"crack_%s.vtp\"", t,
                      index);
        EXPECT_NE(cracks.find(entry), std::string::npos) << entry;
        EXPECT_TRUE(fs::exists(*dir_ / "run/post" / ("crack_" + std::string(index) + ".vtp")));
    }
}

// A picture is real: the expected size, and neither blank nor a single colour.
void expectRealPicture(const fs::path& png, int width, int height) {
    ASSERT_TRUE(fs::exists(png)) << png;
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], width);
    EXPECT_EQ(dims[1], height);
    const int comps = image->GetNumberOfScalarComponents();
    long nonWhite = 0, coloured = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            const int r = px[0], g = px[1 % comps], b = px[2 % comps];
            nonWhite += (r + g + b < 3 * 250);
            coloured += (std::max({r, g, b}) - std::min({r, g, b}) > 60);
        }
    const double total = static_cast<double>(dims[0]) * dims[1];
    EXPECT_GT(nonWhite / total, 0.02) << png << " is (nearly) blank";
    EXPECT_GT(coloured / total, 0.005) << png << " has no colour";
}

TEST_F(PostRun, PicturesAreReal) {
    expectRealPicture(*dir_ / "run/post/final_von_mises.png", 1200, 800);
    expectRealPicture(*dir_ / "run/post/history.png", 1000, 600);
    expectRealPicture(*dir_ / "run/post/momentum.png", 1000, 600);
}

// --field displacement --times 1e-5,1: the snapshots nearest to each time, by their /time.
TEST_F(PostRun, PicturesAtChosenTimes) {
    std::vector<std::pair<double, std::string>> snapshots;
    for (int k = 0; k <= 10; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "%06d", k);
        snapshots.emplace_back(
            readSnapshot(*dir_ / "run" / ("snapshot_" + std::string(name) + ".h5")).state.time,
            name);
    }
    for (double t : {1e-5, 1.0}) {
        const auto nearest =
            std::min_element(snapshots.begin(), snapshots.end(), [t](const auto& p, const auto& q) {
                return std::abs(p.first - t) < std::abs(q.first - t);
            });
        expectRealPicture(*dir_ / "pictures" / ("displacement_" + nearest->second + ".png"), 1200,
                          800);
    }
    EXPECT_TRUE(fs::exists(*dir_ / "pictures/displacement_000010.png"));  // t = 1 s: the last
}

// history.csv columns are found by name: other helpers add and reorder columns.
TEST(PostHistory, ColumnsAreReadByName) {
    TempDir dir;
    {
        std::ofstream csv(dir / "history.csv");
        csv << "time,new_column,momentum_x,kinetic_energy\n0,7,1.5,2\n1e-6,8,2.5,3\n";
    }
    const post::HistoryTable h = post::readHistory(dir / "history.csv");
    ASSERT_NE(h.column("kinetic_energy"), nullptr);
    EXPECT_EQ(*h.column("kinetic_energy"), (std::vector<double>{2.0, 3.0}));
    EXPECT_EQ(*h.column("momentum_x"), (std::vector<double>{1.5, 2.5}));
    EXPECT_EQ(h.column("total_energy"), nullptr);
    {
        std::ofstream csv(dir / "bad.csv");
        csv << "time,kinetic_energy\n0,1\n1e-6,oops\n";
    }
    try {
        post::readHistory(dir / "bad.csv");
        FAIL() << "a malformed row must be an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.csv:3: 'oops' is not a number"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PostCli, MissingRunFolderIsAClearError) {
    TempDir dir;
    const auto r = runCommand(std::string(GSPH_POST_EXE) + " " + (dir / "nothing").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("gsph-post: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no such run folder"), std::string::npos) << r.err;
    fs::create_directories(dir / "empty");
    const auto e = runCommand(std::string(GSPH_POST_EXE) + " " + (dir / "empty").string());
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.err.find("no snapshot_*.h5"), std::string::npos) << e.err;
}

}  // namespace
}  // namespace gsph
