// SPDX-License-Identifier: MIT
#include "core/exact_sum.hpp"

#include <cmath>
#include <limits>

namespace gsph {
namespace {

constexpr std::int64_t kBase = std::int64_t{1} << 32;

// Bit length of a non-zero 64-bit value.
int bitLength(std::uint64_t v) {
    return 64 - std::countl_zero(v);
}

}  // namespace

void ExactSum::normalize() {
    for (int i = 0; i + 1 < kLimbs; ++i) {
        const std::int64_t carry = limbs_[i] >> 32;  // floor division by 2^32
        limbs_[i] -= carry * kBase;
        limbs_[i + 1] += carry;
    }
    pending_ = 0;
}

void ExactSum::add(const ExactSum& other) {
    ExactSum settled = other;
    settled.normalize();
    normalize();
    for (int i = 0; i < kLimbs; ++i) limbs_[i] += settled.limbs_[i];
    nan_ += settled.nan_;
    positiveInfinity_ += settled.positiveInfinity_;
    negativeInfinity_ += settled.negativeInfinity_;
    pending_ = 1;  // each limb has grown by < 2^32: settle before long
}

void ExactSum::addSpecial(std::uint64_t bits) {
    if ((bits & ((std::uint64_t{1} << 52) - 1)) != 0)
        ++nan_;
    else if (bits >> 63)
        ++negativeInfinity_;
    else
        ++positiveInfinity_;
}

double ExactSum::value() const {
    if (nan_ > 0 || (positiveInfinity_ > 0 && negativeInfinity_ > 0))
        return std::numeric_limits<double>::quiet_NaN();
    if (positiveInfinity_ > 0) return std::numeric_limits<double>::infinity();
    if (negativeInfinity_ > 0) return -std::numeric_limits<double>::infinity();

    ExactSum m = *this;
    m.normalize();
    const bool negative = m.limbs_[kLimbs - 1] < 0;
    if (negative) {  // the magnitude: negate every limb and settle again
        for (std::int64_t& limb : m.limbs_) limb = -limb;
        m.normalize();
    }
    int top = kLimbs - 1;
    while (top >= 0 && m.limbs_[top] == 0) --top;
    if (top < 0) return 0.0;
    const auto limb = [&](int i) { return i >= 0 ? static_cast<std::uint64_t>(m.limbs_[i]) : 0U; };
    double magnitude = 0.0;
    if (top <= 1) {
        // Below 2^−1010: an integer of units 2^−1074 under 2^64; a subnormal result is exact, a
        // normal one is rounded once by the conversion.
        magnitude = std::ldexp(static_cast<double>(limb(1) << 32 | limb(0)), -1074);
    } else {
        // The top 96 bits (the top limb is non-zero, so 65–96 of them significant), and whether
        // anything below them is non-zero.
        const std::uint64_t hi = limb(top), mid = limb(top - 1), lo = limb(top - 2);
        bool sticky = false;
        for (int i = top - 3; i >= 0; --i) sticky = sticky || m.limbs_[i] != 0;
        // value = (hi·2^64 + mid·2^32 + lo) · 2^(32 (top − 2) − 1074)
        const int length = bitLength(hi) + 64;  // bits of hi·2^64 + mid·2^32 + lo
        const int drop = length - 53;           // 12–43 bits below the 53 kept
        // The 96-bit value as two words: upper = hi·2^32 + mid, lower = lo (32 bits).
        const std::uint64_t upper = hi << 32 | mid;
        std::uint64_t mantissa = 0, remainder = 0, half = 0;
        bool below = sticky;  // non-zero bits under the remainder's field
        if (drop >= 32) {
            mantissa = upper >> (drop - 32);
            remainder = upper & ((std::uint64_t{1} << (drop - 32)) - 1);
            half = std::uint64_t{1} << (drop - 33 >= 0 ? drop - 33 : 0);
            if (drop == 32) {  // the remainder is lo alone
                remainder = lo;
                half = std::uint64_t{1} << 31;
            } else {
                below = below || lo != 0;
            }
        } else {
            mantissa = (upper << (32 - drop)) | (lo >> drop);
            remainder = lo & ((std::uint64_t{1} << drop) - 1);
            half = std::uint64_t{1} << (drop - 1);
        }
        const bool roundUp =
            remainder > half || (remainder == half && (below || (mantissa & 1U) != 0));
        if (roundUp) ++mantissa;  // 2^53 stays exact as a double
        magnitude = std::ldexp(static_cast<double>(mantissa), drop + 32 * (top - 2) - 1074);
    }
    return negative ? -magnitude : magnitude;
}

void ExactSum::toWords(std::span<std::int64_t, kWords> words) {
    normalize();
    for (int i = 0; i < kLimbs; ++i) words[static_cast<std::size_t>(i)] = limbs_[i];
    words[kLimbs] = nan_;
    words[kLimbs + 1] = positiveInfinity_;
    words[kLimbs + 2] = negativeInfinity_;
}

void ExactSum::fromWords(std::span<const std::int64_t, kWords> words) {
    for (int i = 0; i < kLimbs; ++i) limbs_[i] = words[static_cast<std::size_t>(i)];
    nan_ = words[kLimbs];
    positiveInfinity_ = words[kLimbs + 1];
    negativeInfinity_ = words[kLimbs + 2];
    pending_ = 0;
    normalize();
}

}  // namespace gsph
