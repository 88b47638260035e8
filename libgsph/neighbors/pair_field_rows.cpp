// SPDX-License-Identifier: MIT
#include "neighbors/pair_field_rows.hpp"

#include <cstdint>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

static_assert(kRowLength % 8 == 0 && kRowLength >= kRowFields);

void PairFieldRows::refresh(int first, std::span<const double* const> column,
                            std::span<const Index> particles, std::size_t n) {
    if (first < 0 ||
        static_cast<std::size_t>(first) + column.size() > static_cast<std::size_t>(kRowFields))
        throw Error("PairFieldRows::refresh: slots beyond a row");
    constexpr std::size_t line = 64 / sizeof(double);
    if (capacity_ < n * kRowLength + line) {
        // Left uninitialized: only the listed particles' rows are ever written or read, so the
        // pages of the others (most of them where few particles take the CSR path) stay
        // unmapped instead of costing kRowLength doubles for every particle.
        capacity_ = n * kRowLength + line;
        storage_.reset(new double[capacity_]);
        const auto address = reinterpret_cast<std::uintptr_t>(storage_.get());
        rows_ = storage_.get() + (line - address / sizeof(double) % line) % line;
    }
    parallelFor(static_cast<std::ptrdiff_t>(particles.size()), [&](std::ptrdiff_t i) {
        const auto a = static_cast<std::size_t>(particles[static_cast<std::size_t>(i)]);
        double* row = rows_ + a * kRowLength;
        for (std::size_t k = 0; k < column.size(); ++k)
            row[static_cast<std::size_t>(first) + k] = column[k][a];
    });
}

}  // namespace gsph
