// SPDX-License-Identifier: MIT
// A small RAII layer over the serial HDF5 C API, for the library's files (particle file, snapshots,
// checkpoints). Not a general HDF5 binding: just what those files need.
//
// Contract: every HDF5 identifier is owned by one object and closed exactly once; every failing
// HDF5 call becomes an IoError naming the file, the object and HDF5's own reason; HDF5's
// automatic error printing is switched off while a File is open (the library never prints).
// Objects are named by absolute paths ("/particles/X"); missing parent groups are created.
// Files are reproducible: no object time stamps are stored, so the same data gives the same
// bytes.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gsph::h5 {

/// Owns one HDF5 identifier; closes it with the matching H5?close on destruction.
class Id {
  public:
    using Closer = herr_t (*)(hid_t);
    Id() = default;
    Id(hid_t id, Closer close) : id_(id), close_(close) {}
    ~Id() { reset(); }
    Id(Id&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
    Id& operator=(Id&& other) noexcept;
    Id(const Id&) = delete;
    Id& operator=(const Id&) = delete;

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    void reset();
    /// Gives up ownership: the caller closes the identifier.
    hid_t release() {
        const hid_t id = id_;
        id_ = -1;
        return id;
    }

  private:
    hid_t id_ = -1;
    Closer close_ = nullptr;
};

/// Switches HDF5's automatic error printing off for its lifetime and restores it after.
class QuietErrors {
  public:
    QuietErrors();
    ~QuietErrors();
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

  private:
    H5E_auto2_t oldFunc_ = nullptr;
    void* oldData_ = nullptr;
};

/// One open HDF5 file. Element types supported by write/read: double, std::int64_t,
/// std::int32_t, std::int8_t, std::uint8_t. Arrays are row-major, dims outermost first (N×3 = {N,
/// 3}).
class File {
  public:
    enum class Mode { Create, ReadOnly };

    /// Create builds the file in memory (HDF5's core driver, no backing store): nothing touches
    /// the disk until close() writes the whole image with checked writes, so a full disk is an
    /// IoError there and never a half-written file inside HDF5. A created file that is not
    /// closed (an exception) leaves nothing on disk. Throws IoError naming the file on failure.
    File(const std::filesystem::path& path, Mode mode);

    /// Create mode: writes the file's image to its path (created or truncated; every write
    /// checked) and closes it. ReadOnly: closes it. Throws IoError naming the file on failure.
    /// The destructor of a file not closed discards it. Errors name `reportAs` if given (the
    /// target of an atomic write rather than its temporary name).
    void close(const std::filesystem::path& reportAs = {});

    const std::string& name() const { return name_; }

    /// True if the object (group or dataset) at `path` exists.
    bool exists(const std::string& path) const;
    /// Names of the members of a group, in HDF5's name order.
    std::vector<std::string> members(const std::string& group) const;

    void createGroup(const std::string& path);

    template <class T>
    void write(const std::string& path, const T* data, const std::vector<std::size_t>& dims);
    /// Reads a whole dataset; `dims` receives its shape. Throws IoError if the dataset is missing
    /// or its element class (float or integer) does not match T.
    template <class T>
    std::vector<T> read(const std::string& path, std::vector<std::size_t>& dims) const;

    void writeStrings(const std::string& path, const std::vector<std::string>& values);
    std::vector<std::string> readStrings(const std::string& path) const;

    void setAttribute(const std::string& object, const std::string& name, const std::string& value);
    void setAttribute(const std::string& object, const std::string& name, std::int64_t value);
    bool hasAttribute(const std::string& object, const std::string& name) const;
    std::string stringAttribute(const std::string& object, const std::string& name) const;
    std::int64_t integerAttribute(const std::string& object, const std::string& name) const;

  private:
    [[noreturn]] void fail(const std::string& object, const std::string& what) const;
    Id openObject(const std::string& path) const;
    void ensureParents(const std::string& path);

    QuietErrors quiet_;
    std::string name_;
    Mode mode_;
    Id file_;
};

}  // namespace gsph::h5
