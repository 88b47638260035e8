// SPDX-License-Identifier: MIT
// The far ends' fields of the gathered runs of the CSR blocks (the force's,
// forces/internal_force.cpp, and the θ-gradients', kinematics/deformation_gradient.cpp) as one
// row per particle. A run takes 8 pairs of one particle at a time, and their far ends b are
// anywhere; the pair terms read 40 field components of each (x, v, c, ρ, α, s, F, K, N and the
// reference position X), the θ-gradients 6 (x, v). Fetched from the SoA fields, that is one
// gather per component and 8 pairs; from rows, 8 row loads per 8 components and a transposition
// in registers (core/lanes.hpp loadColumns), the same values, several times faster on this
// project's machine (docs/performance.md).
//
// Contract: the rows of the listed particles (CsrPairWeights::gathered: every particle a CSR
// block's run may read) hold their fields at the slots below once refreshed: X once, when the
// runs are staged (reference data); x and v (kSlotX … kSlotV + 2) after the drift, for the
// θ-gradients and then the force; the other slots before the force. A reader reads only those
// rows, only after the refreshes of the same step.
// The other particles' rows are never written (their pages stay unmapped: a lattice whose CSR
// particles are few pays for their rows only). A row is kRowLength doubles, 64-byte aligned, so
// that a strip of up to 8 components is one cache line (x and v: the first). Allocation-free
// once sized.
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "core/types.hpp"

namespace gsph {

/// The slot of each field component in a row: x, v (3 each), c, ρ, α, s, F, K, N (row-major,
/// 9 each), X (3). Slots from kRowFields on name fields the rows do not hold (h and V, read from
/// the SoA fields only).
enum PairFieldSlot : int {
    kSlotX = 0,
    kSlotV = 3,
    kSlotSoundSpeed = 6,
    kSlotDensity = 7,
    kSlotViscositySwitch = 8,
    kSlotHourglassScale = 9,
    kSlotF = 10,
    kSlotK = 19,
    kSlotN = 28,
    kSlotReferenceX = 37,
    kRowFields = 40,
    kSlotSmoothingLength = 40,
    kSlotVolume = 41,
    kPairSlots = 42
};

/// Doubles per row: kRowFields, whole 64-byte lines (and a multiple of every strip width).
inline constexpr std::size_t kRowLength = 40;

/// The slots refreshed after the drift: x and v, [kSlotX, kMotionSlots).
inline constexpr int kMotionSlots = kSlotSoundSpeed;

class PairFieldRows {
  public:
    /// Copies column[k][a] into row a, slot first + k, for every a of `particles` (in parallel);
    /// sizes the rows for n particles the first time (or when n grows).
    void refresh(int first, std::span<const double* const> column, std::span<const Index> particles,
                 std::size_t n);
    /// Row a starts at data() + a · kRowLength.
    const double* data() const { return rows_; }

  private:
    std::unique_ptr<double[]> storage_;
    std::size_t capacity_ = 0;  ///< doubles in storage_
    double* rows_ = nullptr;    ///< storage_ from its first 64-byte boundary
};

}  // namespace gsph
