// SPDX-License-Identifier: MIT
// Running a reader of untrusted input in a child process: large third-party parsers (gmsh's
// .msh and .geo readers, HDF5's file format code) can crash, or corrupt memory, on damaged
// files. runInChild forks; the child runs `work`, which writes its result into a ByteWriter,
// and exits; the parent reads the bytes back through a pipe.
//
// Contract: the result bytes, or the child's typed error rethrown in the parent with its type
// (InputError, MeshError, IoError, NumericalError as Error, any other exception as Error) and
// message; a child killed by a signal (SIGSEGV, SIGABRT, the out-of-memory killer) or one that
// ends without an answer calls `crashed(reason)` ("signal 11, Segmentation fault"), which
// throws the caller's error (else Error "<source>: <what> crashed (reason)" is thrown). A fork
// copies only the caller's thread: the work must not use threads (OpenMP included) nor locks
// that the caller's other threads may hold. The byte stream holds plain values, strings and
// vectors of trivially copyable elements (and Vec3, Mat3), native layout: parent and child are
// the same program.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace gsph {

template <class T>
constexpr bool kRawBytes =
    std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>;

class ByteWriter {
  public:
    template <class T>
    void value(const T& v) {
        static_assert(kRawBytes<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void text(const std::string& s) {
        value<std::uint64_t>(s.size());
        bytes_.append(s);
    }
    template <class T>
    void array(const std::vector<T>& v) {
        static_assert(kRawBytes<T>);
        value<std::uint64_t>(v.size());
        bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    void texts(const std::vector<std::string>& v) {
        value<std::uint64_t>(v.size());
        for (const std::string& s : v) text(s);
    }
    const std::string& bytes() const { return bytes_; }

  private:
    std::string bytes_;
};

class ByteReader {
  public:
    /// `source` names the input in the error a truncated stream gives.
    ByteReader(const std::string& bytes, std::string source)
        : bytes_(bytes), source_(std::move(source)) {}
    template <class T>
    T value() {
        static_assert(kRawBytes<T>);
        T v;
        take(&v, sizeof v);
        return v;
    }
    std::string text() {
        std::string s(count(1), '\0');
        take(s.data(), s.size());
        return s;
    }
    template <class T>
    std::vector<T> array() {
        static_assert(kRawBytes<T>);
        std::vector<T> v(count(sizeof(T)));
        take(v.data(), v.size() * sizeof(T));
        return v;
    }
    const std::string& source() const { return source_; }
    std::vector<std::string> texts() {
        std::vector<std::string> v(count(sizeof(std::uint64_t)));  // each at least its length
        for (std::string& s : v) s = text();
        return v;
    }

  private:
    std::size_t count(std::size_t elementSize) {
        const auto n = value<std::uint64_t>();
        if (n > (bytes_.size() - at_) / elementSize) truncated();
        return static_cast<std::size_t>(n);
    }
    void take(void* to, std::size_t n) {
        if (n > bytes_.size() - at_) truncated();
        if (n > 0) std::memcpy(to, bytes_.data() + at_, n);
        at_ += n;
    }
    [[noreturn]] void truncated() const {
        throw Error(source_ + ": the reading process sent a truncated answer");
    }
    const std::string& bytes_;
    std::string source_;
    std::size_t at_ = 0;
};

/// Time a sound file of the size of `path` needs at most to be read in a child: 60 s, and 1 s
/// per 20 MB (a particle file of 10e6 particles, about 1 GB, reads in 5 s here).
unsigned fileReadDeadline(const std::filesystem::path& path);

/// Runs `work` in a child process (see the header comment); returns what it wrote. `what`
/// names the work in messages ("gmsh", "the particle-file reader").
/// `timeoutSeconds` > 0: the child is killed by SIGALRM after that long (a parser that hangs).
std::string runInChild(const std::string& source, const std::string& what,
                       const std::function<void(ByteWriter&)>& work,
                       const std::function<void(const std::string& reason)>& crashed = {},
                       unsigned timeoutSeconds = 0);

}  // namespace gsph
