// SPDX-License-Identifier: MIT
// Per-particle fixed-size tensors stored as a structure of arrays.
//
// Component (r, c) of every particle is one contiguous array, so a loop over consecutive
// particles (the stencil blocks of neighbors/stencil_blocks.hpp) reads each component with one
// vector load and vectorises across particles. Element access converts to and from the Eigen
// types of core/types.hpp, so code outside the hot loops still reads like the formulas.
// Owns its storage; sized once by resize() (no allocation inside a step).
//
// The components sit kStrideLines apart modulo 64 cache lines: a loop reads all of them at the
// same particle index, and with a stride of a power of two (32³ or 64³ particles) every one
// fell into the same set of the L1 and L2 caches, whose ways they then evicted from each other
// (the elastic step 25 % slower at 32³ and 64³ than at 46³ particles, docs/performance.md).
#pragma once

#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace gsph {

template <int Rows, int Cols>
class SoaField {
  public:
    using Value = Eigen::Matrix<double, Rows, Cols>;
    static constexpr int kComponents = Rows * Cols;

    void resize(std::size_t n) {
        n_ = n;
        // Whole cache lines, then up to 63 more, so that the stride ≡ kStrideLines (mod 64): odd,
        // so components c·stride fall into distinct sets of any cache of up to 64·2^k sets.
        const std::size_t lines = (n + kLine - 1) / kLine;
        stride_ = (lines + (kStrideLines + 64 - lines % 64) % 64) * kLine;
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
    static constexpr std::size_t kLine = 8;          ///< doubles per 64-byte cache line
    static constexpr std::size_t kStrideLines = 39;  ///< odd, near 64/φ: spreads the sets
    std::size_t n_ = 0, stride_ = 0;
    std::vector<double> data_;
};

using Vec3Field = SoaField<3, 1>;
using Mat3Field = SoaField<3, 3>;

}  // namespace gsph
