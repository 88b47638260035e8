// SPDX-License-Identifier: MIT
// Typed errors of the library (style habit 11). The library never prints or exits: it throws
// one of these, and each tool's main turns it into a one-line message and a non-zero exit.
#pragma once

#include <stdexcept>
#include <string>

namespace gsph {

/// Base of every error the library throws.
class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Bad user input (a file, a key, a value); the message names the file and the fault.
class InputError : public Error {
  public:
    using Error::Error;
};

/// Throws InputError "what, got VALUE" unless `ok`: the check of a model's constant.
inline void requireConstant(bool ok, const std::string& what, double value) {
    if (!ok) throw InputError(what + ", got " + std::to_string(value));
}

/// A mesh that cannot become particles (not hex, not structured, inverted, empty).
class MeshError : public Error {
  public:
    using Error::Error;
};

/// A numerical breakdown during a run: NaN, inverted particle, singular metric.
class NumericalError : public Error {
  public:
    NumericalError(const std::string& what, long particle = -1, double time = 0.0)
        : Error(what), particle_(particle), time_(time) {}
    long particle() const { return particle_; }
    double time() const { return time_; }

  private:
    long particle_;
    double time_;
};

/// Reading or writing a file failed (disk full, permissions, corrupt file).
class IoError : public Error {
  public:
    using Error::Error;
};

/// An output file could not be written whole (disk full, quota, file-size limit, permissions,
/// a failing sync or read-back): the file it was to replace is untouched (io/atomic_file.hpp).
class WriteError : public IoError {
  public:
    using IoError::IoError;
};

}  // namespace gsph
