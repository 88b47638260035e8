// SPDX-License-Identifier: MIT
// The set of strength models, held by value per body and dispatched once per body with
// std::visit (never per particle). Adding a model = adding it to this variant.
#pragma once

#include <variant>

#include "materials/hypoelastic.hpp"

namespace gsph {

using Material = std::variant<HypoElastic>;

inline const ElasticConstants& elasticConstants(const Material& m) {
    return std::visit([](const auto& model) -> const ElasticConstants& { return model.elastic(); },
                      m);
}

}  // namespace gsph
