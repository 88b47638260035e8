// SPDX-License-Identifier: MIT
// Typed reading of one TOML table with "FILE:LINE: what" errors (InputError): the one reader of
// the case file (case_config.*), the material tables and files (material_config.*) and the
// material-point path files (material_point_cli.*). Keys are checked against the allowed set
// first, so a misspelt key is reported as unknown, never as the "missing" key of its correct
// spelling.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace gsph::solver {

/// Parses a TOML file; a syntax error becomes InputError "FILE:LINE: what".
inline toml::table parseTomlFile(const std::string& file) {
    try {
        return toml::parse_file(file);
    } catch (const toml::parse_error& e) {
        throw InputError(file + ":" + std::to_string(e.source().begin.line) + ": " +
                         std::string(e.description()));
    }
}

class TomlKeys {
  public:
    enum class Sign { Any, Positive, NonNegative };

    TomlKeys(std::string file, const toml::table& table, std::string where)
        : file_(std::move(file)), table_(table), where_(std::move(where)) {}
    /// A table that may hold only the `allowed` keys (checked at once).
    TomlKeys(std::string file, const toml::table& table, std::string where,
             const std::vector<std::string>& allowed)
        : TomlKeys(std::move(file), table, std::move(where)) {
        rejectUnknown(allowed);
    }

    const std::string& file() const { return file_; }
    int line() const { return static_cast<int>(table_.source().begin.line); }
    bool has(const std::string& key) const { return table_.get(key) != nullptr; }

    /// Throws "FILE:LINE: what", LINE of `key` (of the table when key is empty or absent).
    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        const toml::node* n = key.empty() ? nullptr : table_.get(key);
        const int at = n ? static_cast<int>(n->source().begin.line) : line();
        throw InputError(file_ + ":" + std::to_string(at) + ": " + what);
    }

    /// Every key must be in `allowed`; `hint(key)` may explain where an unknown key belongs.
    void rejectUnknown(const std::vector<std::string>& allowed,
                       const std::function<std::string(const std::string&)>& hint = {}) const {
        for (const auto& [k, node] : table_) {
            const std::string key(k.str());
            bool known = false;
            for (const std::string& a : allowed) known = known || a == key;
            if (known) continue;
            const std::string extra = hint ? hint(key) : std::string();
            fail(key,
                 "unknown key '" + key + "' in " + where_ + (extra.empty() ? "" : " ") + extra);
        }
    }

    double number(const std::string& key, Sign sign) const {
        if (!has(key)) fail("", "missing key '" + key + "' in " + where_);
        return checked(key, sign);
    }
    double number(const std::string& key, double fallback, Sign sign) const {
        return has(key) ? checked(key, sign) : fallback;
    }

    long integer(const std::string& key, long fallback, long minimum) const {
        const toml::node* n = table_.get(key);
        if (!n) return fallback;
        const std::optional<std::int64_t> v =
            n->is_integer() ? n->value<std::int64_t>() : std::optional<std::int64_t>();
        if (!v) fail(key, "'" + key + "' in " + where_ + " must be an integer");
        if (*v < minimum)
            fail(key, "'" + key + "' in " + where_ + " must be ≥ " + std::to_string(minimum));
        return static_cast<long>(*v);
    }

    /// A non-empty string; an integer is taken as its digits (a body named by its id).
    std::string text(const std::string& key, const std::string& fallback) const {
        const toml::node* n = table_.get(key);
        if (!n) return fallback;
        // is_integer first: toml++'s value<int64_t>() of a float such as 5e66 converts it to
        // int64 before the range check (undefined behaviour).
        if (n->is_integer()) return std::to_string(*n->value<std::int64_t>());
        const std::optional<std::string> v = n->value<std::string>();
        if (!v || v->empty())
            fail(key, "'" + key + "' in " + where_ + " must be a non-empty string");
        return *v;
    }
    std::string text(const std::string& key) const {
        if (!has(key)) fail("", "missing key '" + key + "' in " + where_);
        return text(key, std::string());
    }

    /// One of `choices` (a string, as text()); `fallback` when the key is absent.
    std::string choice(const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& choices) const {
        if (!has(key)) return fallback;
        const std::string v = text(key, fallback);
        for (const std::string& c : choices)
            if (v == c) return v;
        std::string list;
        for (std::size_t i = 0; i < choices.size(); ++i)
            list += (i == 0                    ? ""
                     : i + 1 == choices.size() ? " or "
                                               : ", ") +
                    ("\"" + choices[i] + "\"");
        fail(key, "'" + key + "' in " + where_ + " must be " + list + ", got '" + v + "'");
    }

    bool flag(const std::string& key, bool fallback) const {
        const toml::node* n = table_.get(key);
        if (!n) return fallback;
        const std::optional<bool> v = n->value<bool>();
        if (!v) fail(key, "'" + key + "' in " + where_ + " must be true or false");
        return *v;
    }

    /// A list of distinct axis names "x", "y", "z" (at least one), as a mask; empty when the key
    /// is absent or not a list.
    std::optional<std::array<bool, 3>> axes(const std::string& key) const {
        const toml::node* n = table_.get(key);
        const toml::array* arr = n ? n->as_array() : nullptr;
        if (!arr) return std::nullopt;
        const std::string what =
            "'" + key + "' in " + where_ + " must be a list of distinct axes \"x\", \"y\", \"z\"";
        if (arr->empty()) fail(key, what);
        std::array<bool, 3> mask = {false, false, false};
        for (const toml::node& e : *arr) {
            const std::optional<std::string> v = e.value<std::string>();
            const std::size_t axis = !v || v->size() != 1 ? 3 : std::string("xyz").find((*v)[0]);
            if (axis > 2 || mask[axis]) fail(key, what);
            mask[axis] = true;
        }
        return mask;
    }

    /// A list of exactly `size` numbers.
    std::vector<double> numbers(const std::string& key, std::size_t size) const {
        const toml::node* n = table_.get(key);
        const toml::array* arr = n ? n->as_array() : nullptr;
        const std::string what = "'" + key + "' in " + where_ + " must be a list of " +
                                 std::to_string(size) + " numbers";
        if (!arr || arr->size() != size) fail(key, what);
        std::vector<double> out;
        for (const toml::node& e : *arr) {
            const std::optional<double> v = e.value<double>();
            if (!v || !std::isfinite(*v)) fail(key, what);
            out.push_back(*v);
        }
        return out;
    }

    Vec3 vector(const std::string& key) const {
        const std::vector<double> v = numbers(key, 3);
        return Vec3(v[0], v[1], v[2]);
    }

    /// A number y (the constant curve [[0, y]]) or a list of [x, y] pairs, x increasing.
    std::vector<std::pair<double, double>> curve(const std::string& key) const {
        const toml::node* n = table_.get(key);
        const std::string what = "'" + key + "' in " + where_;
        if (n && !n->is_array()) return {{0.0, number(key, Sign::Any)}};
        const toml::array* arr = n ? n->as_array() : nullptr;
        if (!arr || arr->empty())
            fail(key, what + " must be a number or a list of [time, value] pairs");
        std::vector<std::pair<double, double>> out;
        for (const toml::node& e : *arr) {
            const toml::array* pair = e.as_array();
            std::optional<double> x, y;
            if (pair && pair->size() == 2) {
                x = (*pair)[0].value<double>();
                y = (*pair)[1].value<double>();
            }
            if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
                fail(key, what + " must hold [time, value] pairs of numbers");
            if (!out.empty() && !(*x > out.back().first))
                fail(key, what + ": the times must increase");
            out.emplace_back(*x, *y);
        }
        return out;
    }

  private:
    double checked(const std::string& key, Sign sign) const {
        const std::optional<double> v = table_.get(key)->value<double>();
        if (!v || !std::isfinite(*v)) fail(key, "'" + key + "' in " + where_ + " must be a number");
        if (sign == Sign::Positive && !(*v > 0.0))
            fail(key, "'" + key + "' in " + where_ + " must be > 0");
        if (sign == Sign::NonNegative && *v < 0.0)
            fail(key, "'" + key + "' in " + where_ + " must be ≥ 0");
        return *v;
    }

    std::string file_;
    const toml::table& table_;
    std::string where_;
};

}  // namespace gsph::solver
