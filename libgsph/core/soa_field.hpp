// SPDX-License-Identifier: MIT
// Per-particle fixed-size tensors stored as a structure of arrays.
//
// Component (r, c) of every particle is one contiguous array, so a loop over consecutive
// particles (the stencil blocks of neighbors/stencil_blocks.hpp) reads each component with one
// vector load and vectorises across particles. Element access converts to and from the Eigen
// types of core/types.hpp, so code outside the hot loops still reads like the formulas.
// Owns its storage; sized once by resize() (no allocation inside a step).
//
// The components sit cacheSpreadStride(n) apart: a loop reads all of them at the same particle
// index, and when they sat n apart with n a multiple of 512 (32³, 40³, 64³ particles) all of them
// fell into one set of the L1 and L2 caches and evicted each other (the step 0.55–0.65 of its
// speed at other sizes, docs/performance.md).
#pragma once

#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace gsph {

/// The distance, in doubles, at which to lay the components of a per-entry array of n entries
/// (SoaField here, the staged CSR weights): whole 64-byte cache lines, then up to 63 more so that
/// it is ≡ 39 lines (mod 64). An odd number of lines puts the components c·stride into distinct
/// sets of any cache of 64·2^k sets.
inline std::size_t cacheSpreadStride(std::size_t n) {
    constexpr std::size_t line = 8, spread = 39;  // doubles per line; odd, near 64/φ
    const std::size_t lines = (n + line - 1) / line;
    return (lines + (spread + 64 - lines % 64) % 64) * line;
}

template <int Rows, int Cols>
class SoaField {
  public:
    using Value = Eigen::Matrix<double, Rows, Cols>;
    static constexpr int kComponents = Rows * Cols;

    void resize(std::size_t n) {
        n_ = n;
        stride_ = cacheSpreadStride(n);
        data_.assign(stride_ * kComponents, 0.0);
    }
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }

    /// Component (r, c) of all particles, index r·Cols + c (row-major).
    double* component(int rc) { return data_.data() + static_cast<std::size_t>(rc) * stride_; }
    const double* component(int rc) const {
        return data_.data() + static_cast<std::size_t>(rc) * stride_;
    }

    Value operator[](std::size_t a) const {
        Value m;
        for (int r = 0; r < Rows; ++r)
            for (int c = 0; c < Cols; ++c) m(r, c) = data_[(r * Cols + c) * stride_ + a];
        return m;
    }
    void set(std::size_t a, const Value& m) {
        for (int r = 0; r < Rows; ++r)
            for (int c = 0; c < Cols; ++c) data_[(r * Cols + c) * stride_ + a] = m(r, c);
    }

  private:
    std::size_t n_ = 0, stride_ = 0;
    std::vector<double> data_;
};

using Vec3Field = SoaField<3, 1>;
using Mat3Field = SoaField<3, 3>;

}  // namespace gsph
