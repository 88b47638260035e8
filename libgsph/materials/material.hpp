// SPDX-License-Identifier: MIT
// The set of material models, held by value per body and dispatched once per body with
// std::visit (never per particle): elastic, and the plastic solids (materials/plastic_solid.hpp)
// of each strength model. Adding a model = adding it to this variant.
#pragma once

#include <span>
#include <variant>

#include "materials/hypoelastic.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/linear_hardening.hpp"

namespace gsph {

using Material = std::variant<HypoElastic, JohnsonCook, LinearHardening>;

inline const ElasticConstants& elasticConstants(const Material& m) {
    return std::visit([](const auto& model) -> const ElasticConstants& { return model.elastic(); },
                      m);
}

/// The history variables of a material's model (its kHistory), each naming its field.
inline std::span<const HistoryVariable> historyVariables(const Material& m) {
    return std::visit(
        [](const auto& model) { return std::span<const HistoryVariable>(model.kHistory); }, m);
}

/// True for models that carry a history between steps (plastic strain, temperature, ...).
inline bool tracksHistory(const Material& m) {
    return !historyVariables(m).empty();
}

/// The damage model of a material (Johnson–Cook damage of a plastic solid), if it has one.
inline const JohnsonCookDamage* damageModel(const Material& m) {
    return std::visit(
        [](const auto& model) -> const JohnsonCookDamage* {
            if constexpr (requires { model.damage(); })
                return model.damage() ? &*model.damage() : nullptr;
            else
                return nullptr;
        },
        m);
}

/// The temperature a body of this material starts at: the model's room temperature (Johnson–
/// Cook Tr), or `fallback` for models without one.
inline double roomTemperature(const Material& m, double fallback) {
    return std::visit(
        [&](const auto& model) {
            if constexpr (requires { model.roomTemperature(); })
                return model.roomTemperature();
            else
                return fallback;
        },
        m);
}

}  // namespace gsph
