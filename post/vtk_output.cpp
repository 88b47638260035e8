// SPDX-License-Identifier: MIT
#include "vtk_output.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <type_traits>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"

namespace gsph::post {
namespace {

template <class Array>
vtkNew<Array> namedArray(const char* name, int components, vtkIdType n) {
    vtkNew<Array> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(n);
    return a;
}

// VTK's XML writer in raw appended mode (the fastest to write and read), atomically.
template <class Writer, class Data>
void writeXml(const std::filesystem::path& path, Data* data) {
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        vtkNew<Writer> writer;
        writer->SetFileName(temp.c_str());
        writer->SetInputData(data);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        // LZ4: VTK's default zlib made writing 5× slower (measured at 1e5 particles).
        writer->SetCompressorTypeToLZ4();
        if (writer->Write() != 1) throw IoError(path.string() + ": VTK could not write the file");
    });
}

}  // namespace

namespace {

// A snapshot field's value at one particle as a scalar: a vector's length, a number as it is.
double scalarOf(const Vec3& v) {
    return v.norm();
}
double scalarOf(double x) {
    return x;
}
double scalarOf(Index x) {
    return x;
}
double scalarOf(std::uint8_t x) {
    return x;
}

// The fields that gsph-post derives, before the snapshot's own.
constexpr const char* kDerivedScalars[] = {"von_mises", "pressure", "displacement", "J"};

}  // namespace

const std::vector<std::string>& scalarFieldNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out(std::begin(kDerivedScalars), std::end(kDerivedScalars));
        Snapshot().forEachField([&](const Field& field, const auto& array) {
            using T = typename std::decay_t<decltype(array)>::value_type;
            if (field.vtuName != nullptr && !std::is_same_v<T, Mat3>) out.push_back(field.vtuName);
        });
        return out;
    }();
    return names;
}

bool isScalarField(const std::string& name) {
    for (const std::string& n : scalarFieldNames())
        if (n == name) return true;
    return false;
}

double scalarField(const Snapshot& s, std::size_t a, const std::string& name) {
    if (name == "von_mises") return vonMises(s.state.cauchy[a]);
    if (name == "pressure") return pressure(s.state.cauchy[a]);
    if (name == "displacement") return (s.state.x[a] - s.X[a]).norm();
    if (name == "J") return s.state.F[a].determinant();
    std::optional<double> value;
    s.forEachField([&](const Field& field, const auto& array) {
        using T = typename std::decay_t<decltype(array)>::value_type;
        if constexpr (!std::is_same_v<T, Mat3>)
            if (!value && field.vtuName != nullptr && name == field.vtuName)
                value = a < array.size() ? scalarOf(array[a]) : 0.0;
    });
    if (!value) throw InputError("unknown field '" + name + "'");
    return *value;
}

namespace {

// Rows of a per-particle array to write: every particle (pick == nullptr), or those of `pick`.
struct Rows {
    const std::vector<Index>* pick = nullptr;
    std::size_t all = 0;
    vtkIdType size() const { return static_cast<vtkIdType>(pick ? pick->size() : all); }
    std::size_t operator()(std::ptrdiff_t i) const {
        return pick ? static_cast<std::size_t>((*pick)[static_cast<std::size_t>(i)])
                    : static_cast<std::size_t>(i);
    }
};

// The array of a snapshot field (Snapshot::forEachField), filled in parallel through raw
// pointers (VTK's setters are not safe to call from several threads).
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Vec3>& a,
                                         const Rows& rows) {
    auto out = vtkSmartPointer<vtkDoubleArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(3);
    out->SetNumberOfTuples(rows.size());
    double* p = out->GetPointer(0);
    parallelFor(rows.size(), [&](std::ptrdiff_t i) {
        for (int d = 0; d < 3; ++d) p[3 * i + d] = a[rows(i)][d];
    });
    return out;
}
// Tensors: nine components named XX, XY, … ZZ (row-major), as ParaView lists them.
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Mat3>& a,
                                         const Rows& rows) {
    auto out = vtkSmartPointer<vtkDoubleArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(9);
    out->SetNumberOfTuples(rows.size());
    static const char* const kComponents[] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    for (int c = 0; c < 9; ++c) out->SetComponentName(c, kComponents[c]);
    double* p = out->GetPointer(0);
    parallelFor(rows.size(), [&](std::ptrdiff_t i) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) p[9 * i + 3 * r + c] = a[rows(i)](r, c);
    });
    return out;
}
template <class VtkArray, class T>
vtkSmartPointer<vtkDataArray> scalarArray(const char* name, const std::vector<T>& a,
                                          const Rows& rows) {
    auto out = vtkSmartPointer<VtkArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(1);
    out->SetNumberOfTuples(rows.size());
    auto* p = out->GetPointer(0);
    parallelFor(rows.size(), [&](std::ptrdiff_t i) { p[i] = a[rows(i)]; });
    return out;
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<double>& a,
                                         const Rows& rows) {
    return scalarArray<vtkDoubleArray>(name, a, rows);
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Index>& a,
                                         const Rows& rows) {
    return scalarArray<vtkIntArray>(name, a, rows);
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<std::uint8_t>& a,
                                         const Rows& rows) {
    return scalarArray<vtkUnsignedCharArray>(name, a, rows);
}

// Units of the arrays gsph-post derives (the snapshot's own carry theirs: Field::unit).
constexpr std::pair<const char*, const char*> kDerivedUnits[] = {
    {"displacement", "m"}, {"von_mises", "Pa"}, {"pressure", "Pa"},        {"J", "1"},
    {"id", "1"},           {"radius", "m"},     {"node_displacement", "m"}};

// The per-particle arrays (point data of the cloud, cell data of the solid): displacement,
// von_mises, pressure, J, id, radius, then every snapshot field with a vtuName (a field a
// snapshot built in code left empty is not written; readSnapshot fills every one).
void addParticleArrays(vtkDataSetAttributes* out, const Snapshot& snap, const Rows& rows) {
    const vtkIdType n = rows.size();
    auto displacement = namedArray<vtkDoubleArray>("displacement", 3, n);
    auto mises = namedArray<vtkDoubleArray>("von_mises", 1, n);
    auto pressure = namedArray<vtkDoubleArray>("pressure", 1, n);
    auto J = namedArray<vtkDoubleArray>("J", 1, n);
    // The particle's index (what the solver's messages name) and a radius for ParaView's Point
    // Gaussian: half the edge of a cube of its current volume, so neighbours' splats touch.
    auto id = namedArray<vtkIntArray>("id", 1, n);
    auto radius = namedArray<vtkDoubleArray>("radius", 1, n);
    // Filled through raw pointers: VTK's setters are not safe to call from several threads.
    double *u = displacement->GetPointer(0), *vm = mises->GetPointer(0),
           *p = pressure->GetPointer(0), *detF = J->GetPointer(0), *r = radius->GetPointer(0);
    int* ids = id->GetPointer(0);
    parallelFor(n, [&](std::ptrdiff_t k) {
        const std::size_t i = rows(k);
        for (int d = 0; d < 3; ++d) u[3 * k + d] = snap.state.x[i][d] - snap.X[i][d];
        vm[k] = vonMises(snap.state.cauchy[i]);
        p[k] = gsph::pressure(snap.state.cauchy[i]);
        detF[k] = snap.state.F[i].determinant();
        ids[k] = static_cast<int>(i);
        r[k] = splatRadius(snap, i);
    });
    for (vtkDataArray* arr :
         std::initializer_list<vtkDataArray*>{displacement, mises, pressure, J, id, radius})
        out->AddArray(arr);
    snap.forEachField([&](const Field& field, const auto& array) {
        if (field.vtuName != nullptr && !array.empty())
            out->AddArray(fieldArray(field.vtuName, array, rows));
    });
}

vtkSmartPointer<vtkStringArray> stringArray(const char* name,
                                            const std::vector<std::string>& values) {
    auto out = vtkSmartPointer<vtkStringArray>::New();
    out->SetName(name);
    out->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
    for (std::size_t k = 0; k < values.size(); ++k)
        out->SetValue(static_cast<vtkIdType>(k), values[k]);
    return out;
}

// Field data of every .vtu: the time (TimeValue, as ParaView names it), the body and set names,
// and the unit of every array ("NAME=UNIT").
void addFieldData(vtkDataObject* data, const Snapshot& snap, const RunLabels& labels) {
    vtkFieldData* fd = data->GetFieldData();
    auto time = namedArray<vtkDoubleArray>("TimeValue", 1, 1);
    time->SetValue(0, snap.state.time);
    fd->AddArray(time);
    std::vector<std::string> units;
    for (const auto& [name, unit] : kDerivedUnits) units.push_back(std::string(name) + "=" + unit);
    snap.forEachField([&](const Field& field, const auto& array) {
        if (field.vtuName != nullptr && !array.empty())
            units.push_back(std::string(field.vtuName) + "=" + field.unit);
    });
    units.push_back("TimeValue=s");
    units.push_back("Points=m");
    fd->AddArray(stringArray("units", units));
    if (!labels.bodyNames.empty()) fd->AddArray(stringArray("body_names", labels.bodyNames));
    if (!labels.setNames.empty()) fd->AddArray(stringArray("set_names", labels.setNames));
}

std::string xmlEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

}  // namespace

double splatRadius(const Snapshot& s, std::size_t i) {
    const double volume = s.volume[i] * s.state.F[i].determinant();
    if (s.dimension == 3) return 0.5 * std::cbrt(volume);
    const double ring = s.axisymmetric ? 2.0 * std::numbers::pi * s.state.x[i][0] : 1.0;
    return 0.5 * std::sqrt(volume / ring);
}

void writeVtu(const std::filesystem::path& path, const Snapshot& snap, const RunLabels& labels) {
    const vtkIdType n = snap.size();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    // One VTK_VERTEX per particle, built as flat offsets + connectivity (no per-cell insert).
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(n + 1);
    connectivity->SetNumberOfTuples(n);
    double* x = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
    vtkIdType* off = offsets->GetPointer(0);
    vtkIdType* con = connectivity->GetPointer(0);
    off[n] = n;
    parallelFor(n, [&](std::ptrdiff_t a) {
        off[a] = a;
        con[a] = a;
        for (int d = 0; d < 3; ++d) x[3 * a + d] = snap.state.x[static_cast<std::size_t>(a)][d];
    });
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->SetCells(VTK_VERTEX, cells);
    addParticleArrays(grid->GetPointData(), snap, Rows{nullptr, static_cast<std::size_t>(n)});
    addFieldData(grid, snap, labels);
    writeXml<vtkXMLUnstructuredGridWriter>(path, grid.GetPointer());
}

vtkSmartPointer<vtkCellArray> solidCells(const SolidPiece& piece) {
    const auto nc = static_cast<vtkIdType>(piece.cells());
    const int corners = piece.planar() ? 4 : 8;
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(nc + 1);
    connectivity->SetNumberOfTuples(corners * nc);
    vtkIdType* off = offsets->GetPointer(0);
    vtkIdType* con = connectivity->GetPointer(0);
    for (vtkIdType c = 0; c <= nc; ++c) off[c] = corners * c;
    for (vtkIdType c = 0; c < nc; ++c)
        for (int k = 0; k < corners; ++k)
            con[corners * c + k] = piece.planar() ? piece.quads[static_cast<std::size_t>(c)][k]
                                                  : piece.hexes[static_cast<std::size_t>(c)][k];
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, connectivity);
    return cells;
}

int solidCellType(const SolidPiece& piece) {
    return piece.planar() ? VTK_QUAD : VTK_HEXAHEDRON;
}

namespace {

// Points of a grid and their node_displacement array (x − X).
void setNodes(vtkUnstructuredGrid* grid, const std::vector<Vec3>& x, const std::vector<Vec3>& X) {
    const auto np = static_cast<vtkIdType>(x.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    auto nodeDisplacement = namedArray<vtkDoubleArray>("node_displacement", 3, np);
    double* xp = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
    double* up = nodeDisplacement->GetPointer(0);
    for (vtkIdType i = 0; i < np; ++i) {
        const auto k = static_cast<std::size_t>(i);
        for (int d = 0; d < 3; ++d) {
            xp[3 * i + d] = x[k][d];
            up[3 * i + d] = x[k][d] - X[k][d];
        }
    }
    grid->SetPoints(points);
    grid->GetPointData()->AddArray(nodeDisplacement);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> solidGrid(const HexSolid& solid, const SolidPiece& piece,
                                               const Snapshot& snap, const RunLabels& labels) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    setNodes(grid, solid.currentNodes(piece, snap), piece.nodeX);
    grid->SetCells(solidCellType(piece), solidCells(piece));
    addParticleArrays(grid->GetCellData(), snap, Rows{&piece.particle, 0});
    addFieldData(grid, snap, labels);
    return grid;
}

static_assert(RevolvedCells::kHexahedron == VTK_HEXAHEDRON && RevolvedCells::kWedge == VTK_WEDGE);

vtkSmartPointer<vtkUnstructuredGrid> revolvedGrid(const HexSolid& solid, const SolidPiece& piece,
                                                  const Snapshot& snap, const RunLabels& labels,
                                                  int sectors) {
    const RevolvedCells r = revolveSection(piece, solid.currentNodes(piece, snap), sectors);
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    setNodes(grid, r.nodes, r.nodeX);
    const auto nc = static_cast<vtkIdType>(r.cells());
    vtkNew<vtkUnsignedCharArray> types;
    types->SetNumberOfTuples(nc);
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(nc + 1);
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(r.connectivity.size()));
    for (vtkIdType c = 0; c < nc; ++c)
        types->SetValue(c, static_cast<unsigned char>(r.type[static_cast<std::size_t>(c)]));
    for (vtkIdType c = 0; c <= nc; ++c)
        offsets->SetValue(c, r.offsets[static_cast<std::size_t>(c)]);
    for (std::size_t k = 0; k < r.connectivity.size(); ++k)
        connectivity->SetValue(static_cast<vtkIdType>(k), r.connectivity[k]);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    grid->SetCells(types, cells);
    vtkCellData* cd = grid->GetCellData();
    addParticleArrays(cd, snap, Rows{&r.particle, 0});
    // Every 3-component array is a vector, every 9-component one a tensor (row-major), in the
    // run's (r, axis, hoop) frame: turned about y by the cell's angle.
    for (int k = 0; k < cd->GetNumberOfArrays(); ++k) {
        auto* array = vtkDoubleArray::SafeDownCast(cd->GetArray(k));
        if (array == nullptr) continue;
        const int components = array->GetNumberOfComponents();
        if (components != 3 && components != 9) continue;
        double* p = array->GetPointer(0);
        parallelFor(nc, [&](std::ptrdiff_t c) {
            const double phi = r.angle[static_cast<std::size_t>(c)];
            Mat3 R;
            R << std::cos(phi), 0.0, -std::sin(phi), 0.0, 1.0, 0.0, std::sin(phi), 0.0,
                std::cos(phi);
            if (components == 3) {
                const Vec3 v = R * Vec3(p[3 * c], p[3 * c + 1], p[3 * c + 2]);
                for (int d = 0; d < 3; ++d) p[3 * c + d] = v[d];
            } else {
                Mat3 t;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) t(i, j) = p[9 * c + 3 * i + j];
                const Mat3 turned = R * t * R.transpose();
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) p[9 * c + 3 * i + j] = turned(i, j);
            }
        });
    }
    addFieldData(grid, snap, labels);
    return grid;
}

std::string solidBlockName(const SolidPiece& piece, const RunLabels& labels) {
    const auto b = static_cast<std::size_t>(piece.body);
    const std::string body = b < labels.bodyNames.size() && !labels.bodyNames[b].empty()
                                 ? labels.bodyNames[b]
                                 : "body " + std::to_string(piece.body);
    return body + " space " + std::to_string(piece.space);
}

void writeSolid(const std::filesystem::path& vtm, const HexSolid& solid, const Snapshot& snap,
                const RunLabels& labels, int sectors) {
    const std::string stem = vtm.stem().string();
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
           "byte_order=\"LittleEndian\">\n  <vtkMultiBlockDataSet>\n";
    int index = 0;
    for (const SolidPiece& piece : solid.pieces()) {
        const std::string file = stem + "_s" + std::to_string(piece.space) + ".vtu";
        vtkSmartPointer<vtkUnstructuredGrid> grid =
            sectors > 0 ? revolvedGrid(solid, piece, snap, labels, sectors)
                        : solidGrid(solid, piece, snap, labels);
        writeXml<vtkXMLUnstructuredGridWriter>(vtm.parent_path() / file, grid.GetPointer());
        out << "    <DataSet index=\"" << index++ << "\" name=\""
            << xmlEscaped(solidBlockName(piece, labels)) << "\" file=\"" << xmlEscaped(file)
            << "\"/>\n";
    }
    out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
    writeTextAtomically(vtm, out.str());
}

void writeVtp(const std::filesystem::path& path, const CrackSurface& surface) {
    const auto np = static_cast<vtkIdType>(surface.points.size());
    const auto nc = static_cast<vtkIdType>(surface.polygons());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    for (vtkIdType p = 0; p < np; ++p)
        points->SetPoint(p, surface.points[static_cast<std::size_t>(p)].data());
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(nc + 1);
    for (vtkIdType c = 0; c <= nc; ++c)
        offsets->SetValue(c, surface.offsets[static_cast<std::size_t>(c)]);
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(surface.connectivity.size()));
    for (std::size_t k = 0; k < surface.connectivity.size(); ++k)
        connectivity->SetValue(static_cast<vtkIdType>(k), surface.connectivity[k]);
    vtkNew<vtkCellArray> polygons;
    polygons->SetData(offsets, connectivity);
    auto area = namedArray<vtkDoubleArray>("reference_area", 1, nc);
    auto projected = namedArray<vtkDoubleArray>("projected_area", 1, nc);
    auto bond = namedArray<vtkIntArray>("bond", 2, nc);
    for (vtkIdType c = 0; c < nc; ++c) {
        const auto i = static_cast<std::size_t>(c);
        area->SetValue(c, surface.referenceArea[i]);
        projected->SetValue(c, surface.projectedArea[i]);
        const int ab[2] = {surface.bond[i][0], surface.bond[i][1]};
        bond->SetTypedTuple(c, ab);
    }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetPolys(polygons);
    poly->GetCellData()->AddArray(area);
    poly->GetCellData()->AddArray(projected);
    poly->GetCellData()->AddArray(bond);
    writeXml<vtkXMLPolyDataWriter>(path, poly.GetPointer());
}

void writePvd(const std::filesystem::path& path,
              const std::vector<std::pair<double, std::string>>& entries) {
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  "
           "<Collection>\n";
    for (const auto& [time, file] : entries) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "    <DataSet timestep=\"%.9e\" part=\"0\" file=\"%s\"/>\n", time,
                      file.c_str());
        out << line;
    }
    out << "  </Collection>\n</VTKFile>\n";
    writeTextAtomically(path, out.str());
}

}  // namespace gsph::post
