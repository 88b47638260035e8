// SPDX-License-Identifier: MIT
// Per-particle fixed-size tensors stored as a structure of arrays.
//
// Component (r, c) of every particle is one contiguous array, so a loop over consecutive
// particles (the stencil blocks of neighbors/stencil_blocks.hpp) reads each component with one
// vector load and vectorises across particles. Element access converts to and from the Eigen
// types of core/types.hpp, so code outside the hot loops still reads like the formulas.
// Owns its storage; sized once by resize() (no allocation inside a step).
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
        data_.assign(n * kComponents, 0.0);
    }
    std::size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }

    /// Component (r, c) of all particles, index r·Cols + c (row-major).
    double* component(int rc) { return data_.data() + static_cast<std::size_t>(rc) * n_; }
    const double* component(int rc) const {
        return data_.data() + static_cast<std::size_t>(rc) * n_;
    }

    Value operator[](std::size_t a) const {
        Value m;
        for (int r = 0; r < Rows; ++r)
            for (int c = 0; c < Cols; ++c) m(r, c) = data_[(r * Cols + c) * n_ + a];
        return m;
    }
    void set(std::size_t a, const Value& m) {
        for (int r = 0; r < Rows; ++r)
            for (int c = 0; c < Cols; ++c) data_[(r * Cols + c) * n_ + a] = m(r, c);
    }

  private:
    std::size_t n_ = 0;
    std::vector<double> data_;
};

using Vec3Field = SoaField<3, 1>;
using Mat3Field = SoaField<3, 3>;

}  // namespace gsph
