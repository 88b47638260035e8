// SPDX-License-Identifier: MIT
// 3×3 matrices whose entries are strips (core/lanes.hpp: one particle per lane) or plain doubles:
// the per-particle update (F, L, the Jaumann stress update, the force factors) written once, run
// across the lanes of a block's particles or for one particle.
//
// Contract: every operation does the same floating-point operations in the same order for every
// entry type, so a strip of any width gives each lane the bits that double gives that particle
// (the library is built with -ffp-contract=off). Sums of three terms are taken left to right;
// the inverse divides once (the determinant from the first column's cofactors).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "core/lanes.hpp"
#include "core/types.hpp"

namespace gsph {

/// A 3×3 matrix of T (double or a strip type), entry (r, c) at m[r][c].
template <class T>
struct StripMat3 {
    T m[3][3];

    // Every function on strips is always inlined: called out of line from a kernel built for a
    // wider SIMD target, a strip passed or returned by value is an ABI mismatch (wrong values in
    // an unoptimized build).
    [[gnu::always_inline]] T& operator()(int r, int c) { return m[r][c]; }
    [[gnu::always_inline]] const T& operator()(int r, int c) const { return m[r][c]; }

    [[gnu::always_inline]] static StripMat3 identity() {
        StripMat3 i;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) i.m[r][c] = T{} + (r == c ? 1.0 : 0.0);
        return i;
    }
    [[gnu::always_inline]] T trace() const { return m[0][0] + m[1][1] + m[2][2]; }
    [[gnu::always_inline]] StripMat3 transpose() const {
        StripMat3 t;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) t.m[r][c] = m[c][r];
        return t;
    }
};

template <class T>
[[gnu::always_inline]] inline StripMat3<T> operator+(const StripMat3<T>& a, const StripMat3<T>& b) {
    StripMat3<T> s;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) s.m[r][c] = a.m[r][c] + b.m[r][c];
    return s;
}
template <class T>
[[gnu::always_inline]] inline StripMat3<T> operator-(const StripMat3<T>& a, const StripMat3<T>& b) {
    StripMat3<T> s;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) s.m[r][c] = a.m[r][c] - b.m[r][c];
    return s;
}
/// s a, entry by entry (s a double or a strip).
template <class T, class S>
[[gnu::always_inline]] inline StripMat3<T> operator*(const S& s, const StripMat3<T>& a) {
    StripMat3<T> p;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) p.m[r][c] = s * a.m[r][c];
    return p;
}
template <class T>
[[gnu::always_inline]] inline StripMat3<T> operator*(const StripMat3<T>& a, const StripMat3<T>& b) {
    StripMat3<T> p;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            p.m[r][c] = a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c] + a.m[r][2] * b.m[2][c];
    return p;
}

/// The cofactor of entry (i, j): a(i1, j1) a(i2, j2) − a(i1, j2) a(i2, j1), i1 = (i + 1) % 3 …
template <class T>
[[gnu::always_inline]] inline T cofactorEntry(const StripMat3<T>& a, int i, int j) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    return a.m[i1][j1] * a.m[i2][j2] - a.m[i1][j2] * a.m[i2][j1];
}

/// a^{-1}: the cofactors of the first column, the determinant from them, one division, every
/// cofactor times its reciprocal.
template <class T>
[[gnu::always_inline]] inline StripMat3<T> inverse(const StripMat3<T>& a) {
    const T c0 = cofactorEntry(a, 0, 0), c1 = cofactorEntry(a, 1, 0), c2 = cofactorEntry(a, 2, 0);
    const T det = a.m[0][0] * c0 + a.m[1][0] * c1 + a.m[2][0] * c2;
    const T invdet = 1.0 / det;
    StripMat3<T> inv;
    inv.m[0][0] = c0 * invdet;
    inv.m[0][1] = c1 * invdet;
    inv.m[0][2] = c2 * invdet;
    for (int i = 1; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inv.m[i][j] = cofactorEntry(a, j, i) * invdet;
    return inv;
}

/// a₀ₚ (a₁q a₂r − a₁r a₂q): a term of det a (a function, not a lambda: always inlined).
template <class T>
[[gnu::always_inline]] inline T determinantTerm(const StripMat3<T>& a, int p, int q, int r) {
    return a.m[0][p] * (a.m[1][q] * a.m[2][r] - a.m[1][r] * a.m[2][q]);
}

/// det a, expanded along the first row.
template <class T>
[[gnu::always_inline]] inline T determinant(const StripMat3<T>& a) {
    return determinantTerm(a, 0, 1, 2) - determinantTerm(a, 1, 0, 2) + determinantTerm(a, 2, 0, 1);
}

/// cof F = J F^{-T}: columns F₁×F₂, F₂×F₀, F₀×F₁ (F_i: columns of F; Nanson, the force factors).
template <class T>
[[gnu::always_inline]] inline StripMat3<T> cofactor(const StripMat3<T>& f) {
    StripMat3<T> c;
    for (int k = 0; k < 3; ++k) {
        const int p = (k + 1) % 3, q = (k + 2) % 3;  // columns p × q
        c.m[0][k] = f.m[1][p] * f.m[2][q] - f.m[2][p] * f.m[1][q];
        c.m[1][k] = f.m[2][p] * f.m[0][q] - f.m[0][p] * f.m[2][q];
        c.m[2][k] = f.m[0][p] * f.m[1][q] - f.m[1][p] * f.m[0][q];
    }
    return c;
}

/// |x| lane by lane (the sign bit cleared, as std::fabs).
[[gnu::always_inline]] inline double absOf(double x) {
    return std::fabs(x);
}
template <class L>
requires(!std::is_arithmetic_v<L>) [[gnu::always_inline]] inline L absOf(const L& x) {
    typedef std::int64_t Bits __attribute__((vector_size(sizeof(L))));
    Bits b;
    std::memcpy(&b, &x, sizeof b);
    b &= ~(Bits{} + (std::int64_t(1) << 63));
    L r;
    std::memcpy(&r, &b, sizeof r);
    return r;
}
/// The larger of a and b lane by lane (b where a < b, as std::max).
[[gnu::always_inline]] inline double maxOf(double a, double b) {
    return a < b ? b : a;
}
template <class L>
requires(!std::is_arithmetic_v<L>) [[gnu::always_inline]] inline L maxOf(const L& a, const L& b) {
    return a < b ? b : a;
}
/// √x lane by lane (correctly rounded in every lane).
[[gnu::always_inline]] inline double sqrtOf(double x) {
    return std::sqrt(x);
}
template <class L>
requires(!std::is_arithmetic_v<L>) [[gnu::always_inline]] inline L sqrtOf(const L& x) {
    L r;
    for (int j = 0; j < kLanesOf<L>; ++j) r[j] = std::sqrt(x[j]);
    return r;
}

/// Entry (r, c) of every lane's Eigen matrix: lane j from m[j] (an array of kLanesOf<T> matrices,
/// or one for double).
template <class T>
[[gnu::always_inline]] inline StripMat3<T> lanesOf(const Mat3* const* m) {
    StripMat3<T> s;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            if constexpr (std::is_arithmetic_v<T>)
                s.m[r][c] = (*m[0])(r, c);
            else
                for (int j = 0; j < kLanesOf<T>; ++j) s.m[r][c][j] = (*m[j])(r, c);
        }
    return s;
}

/// Lane j of a strip (the value itself for double).
template <class T>
[[gnu::always_inline]] inline double laneOf(const T& v, int j) {
    if constexpr (std::is_arithmetic_v<T>)
        return v;
    else
        return v[j];
}

/// Lane j of a strip matrix as an Eigen matrix.
template <class T>
[[gnu::always_inline]] inline Mat3 laneOf(const StripMat3<T>& s, int j) {
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = laneOf(s.m[r][c], j);
    return m;
}

/// An Eigen matrix as a StripMat3<double>, and back.
inline StripMat3<double> stripOf(const Mat3& m) {
    StripMat3<double> s;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) s.m[r][c] = m(r, c);
    return s;
}
inline Mat3 eigenOf(const StripMat3<double>& s) {
    return laneOf(s, 0);
}

}  // namespace gsph
