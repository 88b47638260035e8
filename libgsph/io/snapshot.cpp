// SPDX-License-Identifier: MIT
#include "io/snapshot.hpp"

#include <cstdint>
#include <string>
#include <type_traits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/child_process.hpp"
#include "io/hdf5_file.hpp"

namespace gsph {
namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(sizeof(Mat3) == 9 * sizeof(double), "Mat3 must be nine packed doubles");

// An N×cols float64 dataset, its shape checked.
std::vector<double> readRows(const h5::File& f, const std::string& path, std::size_t n,
                             std::size_t cols) {
    std::vector<std::size_t> dims;
    std::vector<double> d = f.read<double>(path, dims);
    if (dims.size() != 2 || dims[0] != n || dims[1] != cols)
        throw IoError(f.name() + ": " + path + " is not an N×" + std::to_string(cols) +
                      " array of " + std::to_string(n) + " rows");
    return d;
}

std::vector<Vec3> readVectors(const h5::File& f, const std::string& path, std::size_t n) {
    const std::vector<double> d = readRows(f, path, n, 3);
    std::vector<Vec3> out(n);
    for (std::size_t a = 0; a < n; ++a) out[a] = Vec3(d[3 * a], d[3 * a + 1], d[3 * a + 2]);
    return out;
}

// An N-vector of float64, its length checked.
std::vector<double> readScalars(const h5::File& f, const std::string& path, std::size_t n) {
    std::vector<std::size_t> dims;
    std::vector<double> d = f.read<double>(path, dims);
    if (d.size() != n) throw IoError(f.name() + ": " + path + " has the wrong length");
    return d;
}

// One field's dataset: N×3 vectors, N×9 row-major tensors, N numbers; flags as int8.
void writeField(h5::File& f, const std::string& name, const std::vector<Vec3>& a) {
    f.write(name, a.empty() ? nullptr : a.front().data(), {a.size(), 3});
}
void writeField(h5::File& f, const std::string& name, const std::vector<Mat3>& a);
void writeField(h5::File& f, const std::string& name, const std::vector<double>& a) {
    f.write(name, a.data(), {a.size()});
}
void writeField(h5::File& f, const std::string& name, const std::vector<Index>& a) {
    f.write(name, a.data(), {a.size()});
}
void writeField(h5::File& f, const std::string& name, const std::vector<std::uint8_t>& a) {
    const std::vector<std::int8_t> flags(a.begin(), a.end());
    f.write(name, flags.data(), {flags.size()});
}

// One field's dataset read back, its shape checked against the particle count n.
void readField(const h5::File& f, const std::string& name, std::size_t n, std::vector<Vec3>& a) {
    a = readVectors(f, name, n);
}
void readField(const h5::File& f, const std::string& name, std::size_t n, std::vector<Mat3>& a);
void readField(const h5::File& f, const std::string& name, std::size_t n, std::vector<double>& a) {
    a = readScalars(f, name, n);
}
void readField(const h5::File& f, const std::string& name, std::size_t n, std::vector<Index>& a) {
    std::vector<std::size_t> dims;
    a = f.read<std::int32_t>(name, dims);
    if (a.size() != n) throw IoError(f.name() + ": " + name + " has the wrong length");
}
void readField(const h5::File& f, const std::string& name, std::size_t n,
               std::vector<std::uint8_t>& a) {
    std::vector<std::size_t> dims;
    const std::vector<std::int8_t> flags = f.read<std::int8_t>(name, dims);
    if (flags.size() != n) throw IoError(f.name() + ": " + name + " has the wrong length");
    a.resize(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = flags[i] != 0 ? 1 : 0;
}
}  // namespace

std::vector<double> rowMajor(const std::vector<Mat3>& m) {
    std::vector<double> out(9 * m.size());
    for (std::size_t a = 0; a < m.size(); ++a)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                out[9 * a + 3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)] =
                    m[a](i, j);
    return out;
}

std::vector<Mat3> fromRowMajor(const std::vector<double>& d) {
    std::vector<Mat3> out(d.size() / 9);
    for (std::size_t a = 0; a < out.size(); ++a)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                out[a](i, j) =
                    d[9 * a + 3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)];
    return out;
}

namespace {

void writeField(h5::File& f, const std::string& name, const std::vector<Mat3>& a) {
    const std::vector<double> rows = rowMajor(a);
    f.write(name, rows.data(), {a.size(), 9});
}
void readField(const h5::File& f, const std::string& name, std::size_t n, std::vector<Mat3>& a) {
    a = fromRowMajor(readRows(f, name, n, 9));
}

}  // namespace

std::vector<std::array<Index, 2>> brokenBonds(const PairList& pairs,
                                              const std::vector<std::uint8_t>& bondIntact) {
    std::vector<std::array<Index, 2>> out;
    if (bondIntact.empty()) return out;
    for (Index a = 0; a < pairs.particles(); ++a)
        for (Index k = pairs.begin(a); k < pairs.end(a); ++k) {
            const Index b = pairs.neighbor[static_cast<std::size_t>(k)];
            if (a < b && bondIntact[static_cast<std::size_t>(k)] == 0) out.push_back({a, b});
        }
    return out;
}

std::vector<double> brokenBondFraction(const PairList& pairs,
                                       const std::vector<std::uint8_t>& bondIntact) {
    std::vector<double> out(static_cast<std::size_t>(pairs.particles()), 0.0);
    if (bondIntact.empty()) return out;
    for (Index a = 0; a < pairs.particles(); ++a) {
        Index broken = 0;
        for (Index k = pairs.begin(a); k < pairs.end(a); ++k)
            if (bondIntact[static_cast<std::size_t>(k)] == 0) ++broken;
        const Index bonds = pairs.end(a) - pairs.begin(a);
        if (bonds > 0)
            out[static_cast<std::size_t>(a)] =
                static_cast<double>(broken) / static_cast<double>(bonds);
    }
    return out;
}

Snapshot snapshotOf(const Reference& ref, const State& state) {
    Snapshot s;
    s.state.time = state.time;
    s.state.step = state.step;
    State::forEachArrayOf(s.state, state, [](const Field& field, auto& to, const auto& from) {
        if (field.isSavedIn(kSnapshot)) to = from;
    });
    s.X = ref.X;
    s.axisymmetric = ref.dim.axisymmetric;
    s.dimension = ref.dim.value;
    s.volume = ref.quadVolume;
    s.body = ref.body;
    s.space = ref.space;
    s.transient.assign(state.x.size(), 0);
    for (const OversetEntry& e : ref.overset) s.transient[static_cast<std::size_t>(e.particle)] = 1;
    s.bondDamage = brokenBondFraction(ref.pairs, state.bondIntact);
    s.brokenBonds = brokenBonds(ref.pairs, state.bondIntact);
    return s;
}

void writeSnapshot(const std::filesystem::path& path, const Reference& ref, const State& state,
                   const Provenance& provenance) {
    const Snapshot s = snapshotOf(ref, state);
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        h5::File f(temp, h5::File::Mode::Create);
        writeFormatVersion(f, kSnapshotFormat, kSnapshotFormatMajor, kSnapshotFormatMinor);
        writeProvenance(f, provenance);
        const double time = s.state.time;
        const double step = static_cast<double>(s.state.step);
        f.write("/time", &time, {1});
        f.write("/step", &step, {1});
        const std::int8_t axisymmetric = s.axisymmetric ? 1 : 0;
        f.write("/axisymmetric", &axisymmetric, {1});
        const std::int32_t dimension = s.dimension;
        f.write("/dimension", &dimension, {1});
        s.forEachField([&](const Field& field, const auto& array) {
            const std::string name = std::string("/particles/") + field.name;
            writeField(f, name, array);
            f.setAttribute(name, "units", std::string(field.unit));
        });
        f.write("/bonds/broken", s.brokenBonds.empty() ? nullptr : s.brokenBonds.data()->data(),
                {s.brokenBonds.size(), 2});
        f.close(path);
    });
}

Snapshot readSnapshot(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw IoError(path.string() + ": no such file");
    h5::File f(path, h5::File::Mode::ReadOnly);
    checkFormatVersion(f, kSnapshotFormat, kSnapshotFormatMajor);
    Snapshot s;
    s.provenance = readProvenance(f);
    std::vector<std::size_t> dims;
    s.state.time = f.read<double>("/time", dims).at(0);
    s.state.step = static_cast<long>(f.read<double>("/step", dims).at(0));
    if (f.exists("/axisymmetric"))  // since 0.6
        s.axisymmetric = f.read<std::int8_t>("/axisymmetric", dims).at(0) != 0;
    if (f.exists("/dimension")) s.dimension = f.read<std::int32_t>("/dimension", dims).at(0);
    if (s.dimension != 2 && s.dimension != 3)
        throw IoError(path.string() + ": /dimension is " + std::to_string(s.dimension) +
                      ", neither 2 nor 3");
    // The particle count from the first field (X, N×3); every other field must agree.
    f.read<double>("/particles/X", dims);
    if (dims.size() != 2 || dims[1] != 3)
        throw IoError(path.string() + ": /particles/X is not an N×3 array");
    const std::size_t n = dims[0];
    s.forEachField([&](const Field& field, auto& array) {
        const std::string name = std::string("/particles/") + field.name;
        if (field.snapshotSinceMinor > 0 && !f.exists(name)) {  // a file older than the field
            using T = typename std::decay_t<decltype(array)>::value_type;
            if constexpr (std::is_arithmetic_v<T>)
                array.assign(n, T(0));
            else
                array.assign(n, T::Zero());
            return;
        }
        readField(f, name, n, array);
    });
    const std::vector<Index> broken = f.read<std::int32_t>("/bonds/broken", dims);
    if (dims.size() != 2 || dims[1] != 2)
        throw IoError(path.string() + ": /bonds/broken is not an M×2 array");
    s.brokenBonds.resize(broken.size() / 2);
    for (std::size_t k = 0; k < s.brokenBonds.size(); ++k) {
        s.brokenBonds[k] = {broken[2 * k], broken[2 * k + 1]};
        for (Index a : s.brokenBonds[k])
            if (a < 0 || static_cast<std::size_t>(a) >= n)
                throw IoError(path.string() + ": /bonds/broken names particle " +
                              std::to_string(a) + " outside [0, " + std::to_string(n) + ")");
    }
    return s;
}

Snapshot readSnapshotIsolated(const std::filesystem::path& path, unsigned deadlineSeconds) {
    const std::string source = path.string();
    const std::string bytes = runInChild(
        source, "the snapshot reader",
        [&](ByteWriter& w) {
            const Snapshot s = readSnapshot(path);
            w.value(s.state.time);
            w.value(s.state.step);
            w.value<std::uint8_t>(s.axisymmetric ? 1 : 0);
            w.value<std::int32_t>(s.dimension);
            s.forEachField([&](const Field&, const auto& array) { w.array(array); });
            w.array(s.brokenBonds);
            writeProvenance(w, s.provenance);
        },
        [&](const std::string& reason) {
            throw IoError(source + ": the file crashed or hung HDF5's reader (" + reason +
                          "): it is damaged or not a snapshot");
        },
        deadlineSeconds > 0 ? deadlineSeconds : fileReadDeadline(path));
    ByteReader r(bytes, source);
    Snapshot s;
    s.state.time = r.value<double>();
    s.state.step = r.value<long>();
    s.axisymmetric = r.value<std::uint8_t>() != 0;
    s.dimension = r.value<std::int32_t>();
    s.forEachField([&](const Field&, auto& array) {
        array = r.array<typename std::decay_t<decltype(array)>::value_type>();
    });
    s.brokenBonds = r.array<std::array<Index, 2>>();
    s.provenance = readProvenance(r);
    return s;
}

}  // namespace gsph
