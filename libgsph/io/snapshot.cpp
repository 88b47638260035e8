// SPDX-License-Identifier: MIT
#include "io/snapshot.hpp"

#include <cstdint>
#include <string>

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

void writeSnapshot(const std::filesystem::path& path, const Reference& ref, const State& state,
                   const Provenance& provenance) {
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        h5::File f(temp, h5::File::Mode::Create);
        writeFormatVersion(f, kSnapshotFormat, kSnapshotFormatMajor, kSnapshotFormatMinor);
        writeProvenance(f, provenance);
        const std::size_t n = state.x.size();
        const double time = state.time;
        const double step = static_cast<double>(state.step);
        f.write("/time", &time, {1});
        f.write("/step", &step, {1});
        f.write("/particles/X", ref.X.data()->data(), {n, 3});
        f.write("/particles/x", state.x.data()->data(), {n, 3});
        f.write("/particles/v", state.v.data()->data(), {n, 3});
        const std::vector<double> stress = rowMajor(state.cauchy);
        const std::vector<double> F = rowMajor(state.F);
        f.write("/particles/stress", stress.data(), {n, 9});
        f.write("/particles/F", F.data(), {n, 9});
        f.write("/particles/volume", ref.quadVolume.data(), {n});
        f.write("/particles/body", ref.body.data(), {n});
        f.write("/particles/space", ref.space.data(), {n});
        f.write("/particles/plastic_strain", state.plasticStrain.data(), {n});
        f.write("/particles/temperature", state.temperature.data(), {n});
        f.write("/particles/damage", state.damage.data(), {n});
        std::vector<std::int8_t> transient(n, 0);
        for (const OversetEntry& e : ref.overset)
            transient[static_cast<std::size_t>(e.particle)] = 1;
        f.write("/particles/transient", transient.data(), {n});
        const std::vector<double> bondDamage = brokenBondFraction(ref.pairs, state.bondIntact);
        f.write("/particles/bond_damage", bondDamage.data(), {n});
        const std::vector<std::array<Index, 2>> broken = brokenBonds(ref.pairs, state.bondIntact);
        f.write("/bonds/broken", broken.empty() ? nullptr : broken.data()->data(),
                {broken.size(), 2});
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
    s.time = f.read<double>("/time", dims).at(0);
    s.step = static_cast<long>(f.read<double>("/step", dims).at(0));
    s.body = f.read<std::int32_t>("/particles/body", dims);
    const std::size_t n = s.body.size();
    s.space = f.read<std::int32_t>("/particles/space", dims);
    if (s.space.size() != n)
        throw IoError(path.string() + ": /particles/space has the wrong length");
    s.X = readVectors(f, "/particles/X", n);
    s.x = readVectors(f, "/particles/x", n);
    s.v = readVectors(f, "/particles/v", n);
    s.stress = fromRowMajor(readRows(f, "/particles/stress", n, 9));
    s.F = fromRowMajor(readRows(f, "/particles/F", n, 9));
    s.volume = f.read<double>("/particles/volume", dims);
    if (s.volume.size() != n)
        throw IoError(path.string() + ": /particles/volume has the wrong length");
    s.plasticStrain = readScalars(f, "/particles/plastic_strain", n);
    s.temperature = readScalars(f, "/particles/temperature", n);
    s.damage = readScalars(f, "/particles/damage", n);
    s.transient.assign(n, 0);
    if (f.exists("/particles/transient")) {  // since 0.3
        const std::vector<std::int8_t> t = f.read<std::int8_t>("/particles/transient", dims);
        if (t.size() != n)
            throw IoError(path.string() + ": /particles/transient has the wrong length");
        for (std::size_t a = 0; a < n; ++a) s.transient[a] = t[a] != 0 ? 1 : 0;
    }
    s.bondDamage.assign(n, 0.0);
    if (f.exists("/particles/bond_damage"))  // since 0.4
        s.bondDamage = readScalars(f, "/particles/bond_damage", n);
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
            w.value(s.time);
            w.value(s.step);
            w.array(s.X);
            w.array(s.x);
            w.array(s.v);
            w.array(s.stress);
            w.array(s.F);
            w.array(s.volume);
            w.array(s.body);
            w.array(s.space);
            w.array(s.plasticStrain);
            w.array(s.temperature);
            w.array(s.damage);
            w.array(s.transient);
            w.array(s.bondDamage);
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
    s.time = r.value<double>();
    s.step = r.value<long>();
    s.X = r.array<Vec3>();
    s.x = r.array<Vec3>();
    s.v = r.array<Vec3>();
    s.stress = r.array<Mat3>();
    s.F = r.array<Mat3>();
    s.volume = r.array<double>();
    s.body = r.array<Index>();
    s.space = r.array<Index>();
    s.plasticStrain = r.array<double>();
    s.temperature = r.array<double>();
    s.damage = r.array<double>();
    s.transient = r.array<std::uint8_t>();
    s.bondDamage = r.array<double>();
    s.brokenBonds = r.array<std::array<Index, 2>>();
    s.provenance = readProvenance(r);
    return s;
}

}  // namespace gsph
