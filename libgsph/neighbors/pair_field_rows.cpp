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
    if (storage_.size() < n * kRowLength + line) {
        storage_.assign(n * kRowLength + line, 0.0);
        const auto address = reinterpret_cast<std::uintptr_t>(storage_.data());
        rows_ = storage_.data() + (line - address / sizeof(double) % line) % line;
    }
    parallelFor(static_cast<std::ptrdiff_t>(particles.size()), [&](std::ptrdiff_t i) {
        const auto a = static_cast<std::size_t>(particles[static_cast<std::size_t>(i)]);
        double* row = rows_ + a * kRowLength;
        for (std::size_t k = 0; k < column.size(); ++k)
            row[static_cast<std::size_t>(first) + k] = column[k][a];
    });
}

}  // namespace gsph
