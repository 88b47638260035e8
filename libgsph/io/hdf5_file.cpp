// SPDX-License-Identifier: MIT
#include "io/hdf5_file.hpp"

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace gsph::h5 {

namespace {

herr_t collectMessage(unsigned /*n*/, const H5E_error2_t* err, void* data) {
    auto* messages = static_cast<std::vector<std::string>*>(data);
    if (err->desc != nullptr && err->desc[0] != '\0') messages->emplace_back(err->desc);
    return 0;
}

/// The innermost description on HDF5's error stack (the most specific reason), then clears it.
std::string hdf5Reason() {
    std::vector<std::string> messages;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collectMessage, &messages);
    H5Eclear2(H5E_DEFAULT);
    return messages.empty() ? std::string("HDF5 error") : messages.back();
}

template <class T>
hid_t memoryType() {
    if constexpr (std::is_same_v<T, double>) {
        return H5T_NATIVE_DOUBLE;
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        return H5T_NATIVE_INT32;
    } else if constexpr (std::is_same_v<T, std::int64_t>) {
        return H5T_NATIVE_INT64;
    } else if constexpr (std::is_same_v<T, std::uint8_t>) {
        return H5T_NATIVE_UINT8;
    } else {
        static_assert(std::is_same_v<T, std::int8_t>, "unsupported HDF5 element type");
        return H5T_NATIVE_INT8;
    }
}

/// Little-endian standard types on disk, whatever the machine.
template <class T>
hid_t fileType() {
    if constexpr (std::is_same_v<T, double>) {
        return H5T_IEEE_F64LE;
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        return H5T_STD_I32LE;
    } else if constexpr (std::is_same_v<T, std::int64_t>) {
        return H5T_STD_I64LE;
    } else if constexpr (std::is_same_v<T, std::uint8_t>) {
        return H5T_STD_U8LE;
    } else {
        return H5T_STD_I8LE;
    }
}

template <class T>
H5T_class_t typeClass() {
    return std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
}

Id variableStringType() {
    Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    return type;
}

/// Object creation properties without time stamps (reproducible files).
Id noTimesProperties(hid_t propertyClass) {
    Id plist(H5Pcreate(propertyClass), H5Pclose);
    H5Pset_obj_track_times(plist.get(), 0);
    return plist;
}

std::string parentOf(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == 0 || slash == std::string::npos ? std::string("/") : path.substr(0, slash);
}

/// Reads a string (variable-length or fixed-length) from an attribute or dataset of one element.
template <class ReadFn>
std::string readOneString(hid_t fileStringType, ReadFn&& read) {
    if (H5Tis_variable_str(fileStringType) > 0) {
        Id mem = variableStringType();
        char* value = nullptr;
        if (read(mem.get(), &value) < 0) return {};
        std::string out = value != nullptr ? value : "";
        H5free_memory(value);
        return out;
    }
    const std::size_t size = H5Tget_size(fileStringType);
    Id mem(H5Tcopy(fileStringType), H5Tclose);
    std::string buffer(size + 1, '\0');
    if (read(mem.get(), buffer.data()) < 0) return {};
    return std::string(buffer.c_str());
}

/// The number of elements of a dataset of shape `shape`, checked against the bytes the file
/// stores for it: a corrupt dataspace can claim 2^60 elements, which must be refused before
/// anything is allocated. Products in 64 bits, checked for overflow. (A chunked dataset may
/// legitimately store less, e.g. compressed: only its count is checked.)
std::size_t storedCount(const std::string& file, const std::string& path, hid_t dataset, hid_t type,
                        const std::vector<hsize_t>& shape) {
    const auto corrupt = [&](const std::string& what) {
        return IoError(file + ": dataset " + path + " " + what + " (a corrupt file)");
    };
    std::uint64_t count = 1;
    for (hsize_t d : shape) {
        if (__builtin_mul_overflow(count, std::uint64_t{d}, &count)) {
            throw corrupt("has a shape whose element count overflows");
        }
    }
    std::uint64_t bytes = 0;
    if (__builtin_mul_overflow(count, std::uint64_t{H5Tget_size(type)}, &bytes)) {
        throw corrupt("has a shape whose size in bytes overflows");
    }
    Id plist(H5Dget_create_plist(dataset), H5Pclose);
    const H5D_layout_t layout = plist.valid() ? H5Pget_layout(plist.get()) : H5D_LAYOUT_ERROR;
    if (layout == H5D_CONTIGUOUS || layout == H5D_COMPACT) {
        const std::uint64_t stored = H5Dget_storage_size(dataset);
        if (stored < bytes) {
            throw corrupt("claims " + std::to_string(count) + " elements (" +
                          std::to_string(bytes) + " bytes) but stores " + std::to_string(stored) +
                          " bytes");
        }
    }
    return static_cast<std::size_t>(count);
}

}  // namespace

Id& Id::operator=(Id&& other) noexcept {
    if (this != &other) {
        reset();
        id_ = other.id_;
        close_ = other.close_;
        other.id_ = -1;
    }
    return *this;
}

void Id::reset() {
    if (id_ >= 0 && close_ != nullptr) close_(id_);
    id_ = -1;
}

QuietErrors::QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &oldFunc_, &oldData_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() {
    H5Eset_auto2(H5E_DEFAULT, oldFunc_, oldData_);
}

File::File(const std::filesystem::path& path, Mode mode) : name_(path.string()), mode_(mode) {
    if (mode == Mode::Create) {
        Id fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
        // In memory, grown in steps of 4 MiB, never backed by the file (close() writes it).
        if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), std::size_t{4} << 20, 0) < 0)
            throw IoError(name_ + ": cannot set up the file in memory (" + hdf5Reason() + ")");
        file_ = Id(H5Fcreate(name_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
        if (!file_.valid())
            throw IoError(name_ + ": cannot create the file (" + hdf5Reason() + ")");
        return;
    }
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw IoError(name_ + ": no such file");
    if (H5Fis_hdf5(name_.c_str()) <= 0) {
        H5Eclear2(H5E_DEFAULT);
        throw IoError(name_ + ": not an HDF5 file");
    }
    file_ = Id(H5Fopen(name_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file_.valid()) throw IoError(name_ + ": cannot open the file (" + hdf5Reason() + ")");
}

void File::close(const std::filesystem::path& reportAs) {
    if (!file_.valid()) throw IoError(name_ + ": closed twice");
    if (mode_ == Mode::ReadOnly) {
        const hid_t id = file_.release();  // released before the call: never closed twice
        if (H5Fclose(id) < 0) throw IoError(name_ + ": cannot close (" + hdf5Reason() + ")");
        return;
    }
    if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("/", "cannot flush");
    const ssize_t size = H5Fget_file_image(file_.get(), nullptr, 0);
    if (size < 0) fail("/", "cannot size the image of");
    std::string image(static_cast<std::size_t>(size), '\0');
    if (H5Fget_file_image(file_.get(), image.data(), image.size()) != size)
        fail("/", "cannot copy the image of");
    const hid_t id = file_.release();
    if (H5Fclose(id) < 0) throw IoError(name_ + ": cannot close (" + hdf5Reason() + ")");
    writeBytes(name_, image, reportAs);
}

void File::fail(const std::string& object, const std::string& what) const {
    throw IoError(name_ + ": " + what + " " + object + " (" + hdf5Reason() + ")");
}

bool File::exists(const std::string& path) const {
    if (path == "/") return true;
    std::size_t pos = 0;
    while (pos != std::string::npos) {
        pos = path.find('/', pos + 1);
        const std::string prefix = path.substr(0, pos);
        const htri_t found = H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT);
        if (found <= 0) {
            H5Eclear2(H5E_DEFAULT);
            return false;
        }
    }
    return true;
}

Id File::openObject(const std::string& path) const {
    Id object(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT), H5Oclose);
    if (!object.valid()) fail(path, "cannot open");
    return object;
}

std::vector<std::string> File::members(const std::string& group) const {
    Id g(H5Gopen2(file_.get(), group.c_str(), H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail(group, "cannot open group");
    H5G_info_t info;
    if (H5Gget_info(g.get(), &info) < 0) fail(group, "cannot list group");
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
        const ssize_t length = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                                  nullptr, 0, H5P_DEFAULT);
        if (length < 0) fail(group, "cannot list group");
        std::string name(static_cast<std::size_t>(length) + 1, '\0');
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT);
        name.resize(static_cast<std::size_t>(length));
        names.push_back(std::move(name));
    }
    return names;
}

void File::createGroup(const std::string& path) {
    if (path == "/" || exists(path)) return;
    ensureParents(path);
    Id gcpl = noTimesProperties(H5P_GROUP_CREATE);
    Id g(H5Gcreate2(file_.get(), path.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail(path, "cannot create group");
}

void File::ensureParents(const std::string& path) {
    createGroup(parentOf(path));
}

template <class T>
void File::write(const std::string& path, const T* data, const std::vector<std::size_t>& dims) {
    ensureParents(path);
    const std::vector<hsize_t> shape(dims.begin(), dims.end());
    Id space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
    Id dcpl = noTimesProperties(H5P_DATASET_CREATE);
    Id dataset(H5Dcreate2(file_.get(), path.c_str(), fileType<T>(), space.get(), H5P_DEFAULT,
                          dcpl.get(), H5P_DEFAULT),
               H5Dclose);
    if (!dataset.valid()) fail(path, "cannot create dataset");
    std::size_t count = 1;
    for (std::size_t d : dims) count *= d;
    if (count > 0 &&
        H5Dwrite(dataset.get(), memoryType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
        fail(path, "cannot write dataset");
    }
}

template <class T>
std::vector<T> File::read(const std::string& path, std::vector<std::size_t>& dims) const {
    if (!exists(path)) throw IoError(name_ + ": missing dataset " + path);
    Id dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) fail(path, "cannot open dataset");
    Id type(H5Dget_type(dataset.get()), H5Tclose);
    if (H5Tget_class(type.get()) != typeClass<T>()) {
        throw IoError(name_ + ": dataset " + path + " has the wrong element type (expected " +
                      (std::is_floating_point_v<T> ? "float" : "integer") + ")");
    }
    Id space(H5Dget_space(dataset.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 0) fail(path, "cannot read the shape of");
    std::vector<hsize_t> shape(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
    const std::size_t count = storedCount(name_, path, dataset.get(), type.get(), shape);
    dims.assign(shape.begin(), shape.end());
    std::vector<T> values(count);
    if (count > 0 &&
        H5Dread(dataset.get(), memoryType<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
        fail(path, "cannot read dataset");
    }
    return values;
}

template void File::write<double>(const std::string&, const double*,
                                  const std::vector<std::size_t>&);
template void File::write<std::int32_t>(const std::string&, const std::int32_t*,
                                        const std::vector<std::size_t>&);
template void File::write<std::int8_t>(const std::string&, const std::int8_t*,
                                       const std::vector<std::size_t>&);
template void File::write<std::int64_t>(const std::string&, const std::int64_t*,
                                        const std::vector<std::size_t>&);
template void File::write<std::uint8_t>(const std::string&, const std::uint8_t*,
                                        const std::vector<std::size_t>&);
template std::vector<double> File::read<double>(const std::string&,
                                                std::vector<std::size_t>&) const;
template std::vector<std::int32_t> File::read<std::int32_t>(const std::string&,
                                                            std::vector<std::size_t>&) const;
template std::vector<std::int8_t> File::read<std::int8_t>(const std::string&,
                                                          std::vector<std::size_t>&) const;
template std::vector<std::int64_t> File::read<std::int64_t>(const std::string&,
                                                            std::vector<std::size_t>&) const;
template std::vector<std::uint8_t> File::read<std::uint8_t>(const std::string&,
                                                            std::vector<std::size_t>&) const;

void File::writeStrings(const std::string& path, const std::vector<std::string>& values) {
    ensureParents(path);
    Id type = variableStringType();
    const hsize_t n = values.size();
    Id space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    Id dcpl = noTimesProperties(H5P_DATASET_CREATE);
    Id dataset(H5Dcreate2(file_.get(), path.c_str(), type.get(), space.get(), H5P_DEFAULT,
                          dcpl.get(), H5P_DEFAULT),
               H5Dclose);
    if (!dataset.valid()) fail(path, "cannot create dataset");
    std::vector<const char*> pointers;
    for (const std::string& v : values) pointers.push_back(v.c_str());
    if (n > 0 &&
        H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
        fail(path, "cannot write dataset");
    }
}

std::vector<std::string> File::readStrings(const std::string& path) const {
    if (!exists(path)) throw IoError(name_ + ": missing dataset " + path);
    Id dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) fail(path, "cannot open dataset");
    Id type(H5Dget_type(dataset.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING) {
        throw IoError(name_ + ": dataset " + path + " does not hold strings");
    }
    Id space(H5Dget_space(dataset.get()), H5Sclose);
    if (H5Sget_simple_extent_ndims(space.get()) != 1) {
        throw IoError(name_ + ": dataset " + path + " is not one-dimensional");
    }
    std::vector<hsize_t> shape(1, 0);
    H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
    const hsize_t n = storedCount(name_, path, dataset.get(), type.get(), shape);
    std::vector<std::string> values;
    if (n == 0) return values;
    if (H5Tis_variable_str(type.get()) > 0) {
        Id mem = variableStringType();
        std::vector<char*> pointers(n, nullptr);
        if (H5Dread(dataset.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
            fail(path, "cannot read dataset");
        }
        for (char* p : pointers) values.emplace_back(p != nullptr ? p : "");
        H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, pointers.data());
    } else {
        const std::size_t size = H5Tget_size(type.get());
        std::vector<char> buffer(n * size);
        if (H5Dread(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
            fail(path, "cannot read dataset");
        }
        for (hsize_t i = 0; i < n; ++i) {
            const char* begin = buffer.data() + i * size;
            std::size_t length = 0;
            while (length < size && begin[length] != '\0') ++length;
            values.emplace_back(begin, length);
        }
    }
    return values;
}

void File::setAttribute(const std::string& object, const std::string& name,
                        const std::string& value) {
    Id obj = openObject(object);
    if (H5Aexists(obj.get(), name.c_str()) > 0) H5Adelete(obj.get(), name.c_str());
    Id type = variableStringType();
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id attr(H5Acreate2(obj.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Aclose);
    const char* pointer = value.c_str();
    if (!attr.valid() || H5Awrite(attr.get(), type.get(), &pointer) < 0) {
        fail(object, "cannot write attribute '" + name + "' of");
    }
}

void File::setAttribute(const std::string& object, const std::string& name, std::int64_t value) {
    Id obj = openObject(object);
    if (H5Aexists(obj.get(), name.c_str()) > 0) H5Adelete(obj.get(), name.c_str());
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id attr(
        H5Acreate2(obj.get(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    if (!attr.valid() || H5Awrite(attr.get(), H5T_NATIVE_INT64, &value) < 0) {
        fail(object, "cannot write attribute '" + name + "' of");
    }
}

bool File::hasAttribute(const std::string& object, const std::string& name) const {
    if (!exists(object)) return false;
    Id obj = openObject(object);
    const htri_t found = H5Aexists(obj.get(), name.c_str());
    H5Eclear2(H5E_DEFAULT);
    return found > 0;
}

std::string File::stringAttribute(const std::string& object, const std::string& name) const {
    if (!hasAttribute(object, name)) {
        throw IoError(name_ + ": missing attribute '" + name + "' of " + object);
    }
    Id obj = openObject(object);
    Id attr(H5Aopen(obj.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
    if (!attr.valid()) fail(object, "cannot open attribute '" + name + "' of");
    Id type(H5Aget_type(attr.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING) {
        throw IoError(name_ + ": attribute '" + name + "' of " + object + " is not a string");
    }
    bool ok = true;
    std::string value = readOneString(type.get(), [&](hid_t mem, void* buffer) {
        const herr_t status = H5Aread(attr.get(), mem, buffer);
        ok = status >= 0;
        return status;
    });
    if (!ok) fail(object, "cannot read attribute '" + name + "' of");
    return value;
}

std::int64_t File::integerAttribute(const std::string& object, const std::string& name) const {
    if (!hasAttribute(object, name)) {
        throw IoError(name_ + ": missing attribute '" + name + "' of " + object);
    }
    Id obj = openObject(object);
    Id attr(H5Aopen(obj.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
    Id type(H5Aget_type(attr.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_INTEGER) {
        throw IoError(name_ + ": attribute '" + name + "' of " + object + " is not an integer");
    }
    std::int64_t value = 0;
    if (H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0) {
        fail(object, "cannot read attribute '" + name + "' of");
    }
    return value;
}

}  // namespace gsph::h5
