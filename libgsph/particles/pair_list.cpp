// SPDX-License-Identifier: MIT
#include "particles/pair_list.hpp"

namespace gsph {

std::size_t PairList::bytes() const {
    return offset.capacity() * sizeof(Index) + neighbor.capacity() * sizeof(Index) +
           kernelId.capacity() * sizeof(Index) + table.capacity() * sizeof(KernelEntry);
}

}  // namespace gsph
