// SPDX-License-Identifier: MIT
#include "io/checkpoint.hpp"

#include <string>
#include <type_traits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/snapshot.hpp"

namespace gsph {
namespace {

const std::string kStateGroup = "/state/";
const std::string kScalarGroup = "/state/scalars/";

template <class T>
struct Unsupported : std::false_type {};

// Columns of one element of a State array in the file (Vec3: 3, Mat3: 9, scalars: 1).
template <class T>
constexpr std::size_t columnsOf() {
    if constexpr (std::is_same_v<T, Vec3>) {
        return 3;
    } else if constexpr (std::is_same_v<T, Mat3>) {
        return 9;
    } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::uint8_t>) {
        return 1;
    } else {
        static_assert(Unsupported<T>::value, "checkpoint: add this State array type here");
        return 0;
    }
}

template <class T>
std::vector<std::size_t> shapeOf(const std::vector<T>& array) {
    constexpr std::size_t cols = columnsOf<T>();
    if (cols == 1) return {array.size()};
    return {array.size(), cols};
}

template <class T>
void writeArray(h5::File& f, const std::string& path, const std::vector<T>& array) {
    if constexpr (std::is_same_v<T, Vec3>) {
        f.write(path, array.empty() ? nullptr : array.data()->data(), shapeOf(array));
    } else if constexpr (std::is_same_v<T, Mat3>) {
        const std::vector<double> rows = rowMajor(array);
        f.write(path, rows.data(), shapeOf(array));
    } else {
        f.write(path, array.data(), shapeOf(array));
    }
}

template <class T>
void readArray(const h5::File& f, const std::string& path, std::vector<T>& array) {
    using Element = std::conditional_t<std::is_same_v<T, std::uint8_t>, std::uint8_t, double>;
    std::vector<std::size_t> dims;
    const std::vector<Element> data = f.read<Element>(path, dims);
    constexpr std::size_t cols = columnsOf<T>();
    const bool shapeOk = cols == 1 ? dims.size() == 1 : dims.size() == 2 && dims[1] == cols;
    if (!shapeOk)
        throw IoError(f.name() + ": " + path + " is not an array of " + std::to_string(cols) +
                      " column(s)");
    if constexpr (std::is_same_v<T, Vec3>) {
        array.resize(dims[0]);
        for (std::size_t a = 0; a < dims[0]; ++a)
            array[a] = Vec3(data[3 * a], data[3 * a + 1], data[3 * a + 2]);
    } else if constexpr (std::is_same_v<T, Mat3>) {
        array = fromRowMajor(data);
    } else {
        array = data;
    }
}

template <class T>
void writeScalar(h5::File& f, const std::string& path, const T& value) {
    if constexpr (std::is_same_v<T, double>) {
        f.write(path, &value, {1});
    } else {
        static_assert(std::is_same_v<T, long>, "checkpoint: add this State scalar type here");
        const std::int64_t v = value;
        f.write(path, &v, {1});
    }
}

template <class T>
void readScalar(const h5::File& f, const std::string& path, T& value) {
    std::vector<std::size_t> dims;
    if constexpr (std::is_same_v<T, double>) {
        const std::vector<double> v = f.read<double>(path, dims);
        if (v.size() != 1) throw IoError(f.name() + ": " + path + " is not one number");
        value = v[0];
    } else {
        static_assert(std::is_same_v<T, long>, "checkpoint: add this State scalar type here");
        const std::vector<std::int64_t> v = f.read<std::int64_t>(path, dims);
        if (v.size() != 1) throw IoError(f.name() + ": " + path + " is not one number");
        value = static_cast<long>(v[0]);
    }
}

void writeRunRecord(h5::File& f, const RunRecord& run) {
    std::vector<std::string> roles, files, hashes;
    for (const CheckpointInput& in : run.inputs) {
        roles.push_back(in.role);
        files.push_back(in.file);
        hashes.push_back(in.sha256);
    }
    f.writeStrings("/run/inputs/role", roles);
    f.writeStrings("/run/inputs/file", files);
    f.writeStrings("/run/inputs/sha256", hashes);
    f.createGroup("/run/counters");
    for (const auto& [name, value] : run.counters) f.write("/run/counters/" + name, &value, {1});
    f.createGroup("/run/texts");
    for (const auto& [name, text] : run.texts) f.writeStrings("/run/texts/" + name, {text});
}

RunRecord readRunRecord(const h5::File& f) {
    RunRecord run;
    const std::vector<std::string> roles = f.readStrings("/run/inputs/role");
    const std::vector<std::string> files = f.readStrings("/run/inputs/file");
    const std::vector<std::string> hashes = f.readStrings("/run/inputs/sha256");
    if (files.size() != roles.size() || hashes.size() != roles.size())
        throw IoError(f.name() + ": /run/inputs has lists of different lengths");
    for (std::size_t i = 0; i < roles.size(); ++i)
        run.inputs.push_back({roles[i], files[i], hashes[i]});
    std::vector<std::size_t> dims;
    for (const std::string& name : f.members("/run/counters")) {
        const std::vector<std::int64_t> v = f.read<std::int64_t>("/run/counters/" + name, dims);
        if (v.size() != 1)
            throw IoError(f.name() + ": /run/counters/" + name + " is not one number");
        run.counters[name] = v[0];
    }
    for (const std::string& name : f.members("/run/texts")) {
        const std::vector<std::string> v = f.readStrings("/run/texts/" + name);
        if (v.size() != 1) throw IoError(f.name() + ": /run/texts/" + name + " is not one string");
        run.texts[name] = v[0];
    }
    return run;
}

}  // namespace

void writeCheckpoint(const std::filesystem::path& path, const State& state, const RunRecord& run,
                     const Provenance& provenance) {
    writeAtomically(
        path,
        [&](const std::filesystem::path& temp) {
            h5::File f(temp, h5::File::Mode::Create);
            writeFormatVersion(f, kCheckpointFormat, kCheckpointFormatMajor,
                               kCheckpointFormatMinor);
            writeProvenance(f, provenance);
            state.forEachArray([&](const Field& field, const auto& array) {
                writeArray(f, kStateGroup + field.name, array);
                f.setAttribute(kStateGroup + field.name, "units", std::string(field.unit));
            });
            state.forEachScalar([&](const char* name, const auto& value) {
                writeScalar(f, kScalarGroup + name, value);
            });
            writeRunRecord(f, run);
            f.close(path);
        },
        // The previous checkpoint is replaced only by one that reads back whole.
        [](const std::filesystem::path& temp) { readCheckpoint(temp); });
}

Checkpoint readCheckpoint(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw IoError(path.string() + ": no such checkpoint file");
    h5::File f(path, h5::File::Mode::ReadOnly);
    checkFormatVersion(f, kCheckpointFormat, kCheckpointFormatMajor);
    Checkpoint c;
    c.provenance = readProvenance(f);
    c.state.forEachArray([&](const Field& field, auto& array) {
        const std::string dataset = kStateGroup + field.name;
        if (field.checkpointSinceMinor > 0 && !f.exists(dataset)) {  // a file older than it
            using T = typename std::decay_t<decltype(array)>::value_type;
            if constexpr (std::is_same_v<T, double>)
                if (field.extent == Extent::Particle) array.assign(c.state.x.size(), 0.0);
            return;
        }
        // A 3.0 checkpoint names some arrays otherwise (Field::checkpoint30Name).
        readArray(f,
                  field.checkpoint30Name && !f.exists(dataset)
                      ? kStateGroup + field.checkpoint30Name
                      : dataset,
                  array);
    });
    c.state.forEachScalar([&](const char* name, auto& value) {
        const std::string dataset = kScalarGroup + name;
        if (State::scalarSinceMinor(name) > 0 && !f.exists(dataset)) return;  // an older file
        readScalar(f, dataset, value);
    });
    c.run = readRunRecord(f);
    return c;
}

void checkStateShape(const State& loaded, const State& expected, const std::string& file) {
    State::forEachArrayOf(
        loaded, expected, [&](const Field& field, const auto& have, const auto& want) {
            if (have.size() != want.size())
                throw InputError(file + ": state array '" + std::string(field.name) + "' has " +
                                 std::to_string(have.size()) + " entries, the run has " +
                                 std::to_string(want.size()) +
                                 " (another particle file or kappa?)");
        });
}

}  // namespace gsph
