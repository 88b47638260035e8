// SPDX-License-Identifier: MIT
// An exactly rounded sum of doubles, whatever the order of its terms: the terms are added
// without rounding into one fixed-point integer that spans every double (a long accumulator,
// Kulisch's), and only value() rounds, once, to the nearest double (ties to even). So a sum split
// over threads or processes in any way, its parts summed and merged in any order, gives the same
// bits: the reductions of a run split over processes (distributed/domain.hpp) do not depend on the
// process count.
//
// The integer is kept in base 2^32 in signed 64-bit limbs, limb i weighing 2^(32 i − 1074) (the
// least double, 2^−1074, is its unit), so that a term adds to three limbs without carries; the
// carries are settled every 2^28 terms and before a merge or value(). Infinities and NaNs are
// counted apart and give what IEEE addition gives (+∞ + −∞ = NaN).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <span>

namespace gsph {

class ExactSum {
  public:
    /// 2046 binary positions of the doubles (2^−1074 … 2^971 · 2^53) plus carries up to 2^1100.
    static constexpr int kLimbs = 68;
    /// The limbs and the counts of NaN, +∞ and −∞ terms: what travels between processes, summed
    /// element-wise as integers (after normalize()).
    static constexpr int kWords = kLimbs + 3;

    void add(double x) {
        const std::uint64_t bits = bitsOf(x);
        if ((bits << 1) == 0) return;  // ±0: common (particles off a wall), adds nothing
        const auto biased = static_cast<unsigned>((bits >> 52) & 0x7ffU);
        if (biased == 0x7ffU) return addSpecial(bits);
        std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
        if (biased != 0) mantissa |= std::uint64_t{1} << 52;
        // x = ±mantissa · 2^(shift − 1074), shift = max(biased, 1) − 1 (subnormals share e = 1).
        const unsigned shift = (biased == 0 ? 1U : biased) - 1U;
        const unsigned limb = shift >> 5, offset = shift & 31U;
        const std::uint64_t low = (mantissa & 0xffffffffU) << offset;  // < 2^63
        const std::uint64_t high = (mantissa >> 32) << offset;         // < 2^52, weighs 2^32
        const auto l0 = static_cast<std::int64_t>(low & 0xffffffffU);
        const auto l1 = static_cast<std::int64_t>((low >> 32) + (high & 0xffffffffU));
        const auto l2 = static_cast<std::int64_t>(high >> 32);
        if (bits >> 63) {
            limbs_[limb] -= l0, limbs_[limb + 1] -= l1, limbs_[limb + 2] -= l2;
        } else {
            limbs_[limb] += l0, limbs_[limb + 1] += l1, limbs_[limb + 2] += l2;
        }
        // A limb gains < 2^33 a term: settle the carries long before 2^63.
        if (++pending_ == kSettleEvery) normalize();
    }

    /// Adds another sum's terms (exact).
    void add(const ExactSum& other);

    /// The sum rounded once to the nearest double (ties to even); ±∞ beyond the doubles' range.
    double value() const;

    /// Settles the carries: every limb but the last in [0, 2^32), the last holds the sign.
    void normalize();

    /// The limbs and the special counts as kWords integers (normalized first), and back: for a
    /// sum over processes, which adds these words element-wise (exact, in any order).
    void toWords(std::span<std::int64_t, kWords> words);
    void fromWords(std::span<const std::int64_t, kWords> words);

  private:
    static constexpr int kSettleEvery = 1 << 28;
    static std::uint64_t bitsOf(double x) { return std::bit_cast<std::uint64_t>(x); }
    void addSpecial(std::uint64_t bits);

    std::array<std::int64_t, kLimbs> limbs_{};
    std::int64_t nan_ = 0, positiveInfinity_ = 0, negativeInfinity_ = 0;
    int pending_ = 0;
};

}  // namespace gsph
