// SPDX-License-Identifier: MIT
#include "vtk_output.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
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

double vonMises(const Mat3& sigma) {
    const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    return std::sqrt(1.5 * s.squaredNorm());
}

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
        Snapshot().forEachField([&](const SnapshotField& field, const auto& array) {
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
    if (name == "von_mises") return vonMises(s.stress[a]);
    if (name == "pressure") return -s.stress[a].trace() / 3.0;
    if (name == "displacement") return (s.x[a] - s.X[a]).norm();
    if (name == "J") return s.F[a].determinant();
    std::optional<double> value;
    s.forEachField([&](const SnapshotField& field, const auto& array) {
        using T = typename std::decay_t<decltype(array)>::value_type;
        if constexpr (!std::is_same_v<T, Mat3>)
            if (!value && field.vtuName != nullptr && name == field.vtuName)
                value = a < array.size() ? scalarOf(array[a]) : 0.0;
    });
    if (!value) throw InputError("unknown field '" + name + "'");
    return *value;
}

namespace {

// The .vtu point-data array of a snapshot field (Snapshot::forEachField), filled in parallel
// through raw pointers (VTK's setters are not safe to call from several threads).
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Vec3>& a) {
    auto out = vtkSmartPointer<vtkDoubleArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(3);
    out->SetNumberOfTuples(static_cast<vtkIdType>(a.size()));
    double* p = out->GetPointer(0);
    parallelFor(static_cast<std::ptrdiff_t>(a.size()), [&](std::ptrdiff_t i) {
        for (int d = 0; d < 3; ++d) p[3 * i + d] = a[static_cast<std::size_t>(i)][d];
    });
    return out;
}
// Tensors: nine components named XX, XY, … ZZ (row-major), as ParaView lists them.
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Mat3>& a) {
    auto out = vtkSmartPointer<vtkDoubleArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(9);
    out->SetNumberOfTuples(static_cast<vtkIdType>(a.size()));
    static const char* const kComponents[] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    for (int c = 0; c < 9; ++c) out->SetComponentName(c, kComponents[c]);
    double* p = out->GetPointer(0);
    parallelFor(static_cast<std::ptrdiff_t>(a.size()), [&](std::ptrdiff_t i) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) p[9 * i + 3 * r + c] = a[static_cast<std::size_t>(i)](r, c);
    });
    return out;
}
template <class VtkArray, class T>
vtkSmartPointer<vtkDataArray> scalarArray(const char* name, const std::vector<T>& a) {
    auto out = vtkSmartPointer<VtkArray>::New();
    out->SetName(name);
    out->SetNumberOfComponents(1);
    out->SetNumberOfTuples(static_cast<vtkIdType>(a.size()));
    auto* p = out->GetPointer(0);
    parallelFor(static_cast<std::ptrdiff_t>(a.size()),
                [&](std::ptrdiff_t i) { p[i] = a[static_cast<std::size_t>(i)]; });
    return out;
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<double>& a) {
    return scalarArray<vtkDoubleArray>(name, a);
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<Index>& a) {
    return scalarArray<vtkIntArray>(name, a);
}
vtkSmartPointer<vtkDataArray> fieldArray(const char* name, const std::vector<std::uint8_t>& a) {
    return scalarArray<vtkUnsignedCharArray>(name, a);
}

}  // namespace

void writeVtu(const std::filesystem::path& path, const Snapshot& snap) {
    const vtkIdType n = snap.size();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    // One VTK_VERTEX per particle, built as flat offsets + connectivity (no per-cell insert).
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfTuples(n + 1);
    connectivity->SetNumberOfTuples(n);
    // Derived from the snapshot's fields; the fields themselves follow (Snapshot::forEachField).
    auto displacement = namedArray<vtkDoubleArray>("displacement", 3, n);
    auto mises = namedArray<vtkDoubleArray>("von_mises", 1, n);
    auto pressure = namedArray<vtkDoubleArray>("pressure", 1, n);
    auto J = namedArray<vtkDoubleArray>("J", 1, n);
    // The particle's index (what the solver's messages name) and a radius for ParaView's Point
    // Gaussian: half the edge of a cube of its current volume, so neighbours' splats touch.
    auto id = namedArray<vtkIntArray>("id", 1, n);
    auto radius = namedArray<vtkDoubleArray>("radius", 1, n);
    // Filled through raw pointers: VTK's setters are not safe to call from several threads.
    double* X = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
    vtkIdType* off = offsets->GetPointer(0);
    vtkIdType* con = connectivity->GetPointer(0);
    double *u = displacement->GetPointer(0), *vm = mises->GetPointer(0),
           *p = pressure->GetPointer(0), *detF = J->GetPointer(0), *r = radius->GetPointer(0);
    int* ids = id->GetPointer(0);
    off[n] = n;
    parallelFor(n, [&](std::ptrdiff_t a) {
        const auto i = static_cast<std::size_t>(a);
        off[a] = a;
        con[a] = a;
        for (int d = 0; d < 3; ++d) {
            X[3 * a + d] = snap.x[i][d];
            u[3 * a + d] = snap.x[i][d] - snap.X[i][d];
        }
        vm[a] = vonMises(snap.stress[i]);
        p[a] = -snap.stress[i].trace() / 3.0;
        detF[a] = snap.F[i].determinant();
        ids[a] = static_cast<int>(a);
        r[a] = 0.5 * std::cbrt(snap.volume[i] * detF[a]);
    });
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->SetCells(VTK_VERTEX, cells);
    vtkPointData* pd = grid->GetPointData();
    for (vtkDataArray* arr :
         std::initializer_list<vtkDataArray*>{displacement, mises, pressure, J, id, radius})
        pd->AddArray(arr);
    snap.forEachField([&](const SnapshotField& field, const auto& array) {
        if (field.vtuName != nullptr) pd->AddArray(fieldArray(field.vtuName, array));
    });
    writeXml<vtkXMLUnstructuredGridWriter>(path, grid.GetPointer());
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
