// SPDX-License-Identifier: MIT
// The field registry (particles/fields.hpp) and what derives from it: every state array has one
// field of a unique name; a snapshot holds exactly the state arrays flagged for snapshots; the
// materials' history variables are the State's fields they say; loading and storing a history
// copies exactly a model's variables; docs/formats.md documents every field with its unit.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <variant>

#include "io/snapshot.hpp"
#include "materials/material.hpp"
#include "particles/fields.hpp"
#include "particles/state.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

// A state of n particles (and pairs, walls, body pairs) with a distinct value in every entry.
State distinctState(std::size_t n) {
    State s;
    double next = 0.25;
    s.forEachArray([&](const Field&, auto& array) {
        array.resize(n);
        for (auto& e : array) {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, std::uint8_t>)
                e = static_cast<std::uint8_t>(next += 1.0) % 2;
            else if constexpr (std::is_same_v<T, double>)
                e = next += 1.0;
            else
                for (int k = 0; k < e.size(); ++k) e.data()[k] = next += 1.0;
        }
    });
    return s;
}

// Every field of the registry that a state or a snapshot names, in their visiting order.
std::vector<const Field*> everyField() {
    std::vector<const Field*> out;
    State().forEachArray([&](const Field& f, const auto&) { out.push_back(&f); });
    Snapshot().forEachField([&](const Field& f, const auto&) {
        if (!f.isSavedIn(kCheckpoint)) out.push_back(&f);  // the reference's fields
    });
    return out;
}

TEST(FieldRegistry, EveryFieldHasAUniqueNameAUnitAndConsistentFlags) {
    std::set<std::string> names;
    std::set<std::string> vtuNames;
    for (const Field* f : everyField()) {
        SCOPED_TRACE(f->name);
        EXPECT_TRUE(names.insert(f->name).second) << "two fields are named " << f->name;
        EXPECT_FALSE(std::string(f->unit).empty());
        EXPECT_NE(f->savedIn, 0u) << "saved nowhere";
        // Snapshots and their .vtu arrays are per particle.
        if (f->isSavedIn(kSnapshot)) {
            EXPECT_EQ(f->extent, Extent::Particle);
        }
        if (f->vtuName) {
            EXPECT_TRUE(f->isSavedIn(kSnapshot)) << "a .vtu array is read from snapshots";
            EXPECT_TRUE(vtuNames.insert(f->vtuName).second);
        }
        if (f->snapshotSinceMinor > 0) {
            EXPECT_LE(f->snapshotSinceMinor, kSnapshotFormatMinor);
        }
    }
    // Every state array is in checkpoints (a restart needs all of it).
    State().forEachArray(
        [&](const Field& f, const auto&) { EXPECT_TRUE(f.isSavedIn(kCheckpoint)) << f.name; });
    EXPECT_EQ(names.size(), 23u);  // 17 state arrays + 6 reference fields of snapshots
}

TEST(FieldRegistry, ASnapshotHoldsExactlyTheStateArraysFlaggedForSnapshots) {
    Reference ref;
    const std::size_t n = 5;
    ref.X.assign(n, Vec3::Zero());
    ref.quadVolume.assign(n, 1.0);
    ref.body.assign(n, 0);
    ref.space.assign(n, 0);
    ref.pairs.offset.assign(n + 1, 0);
    const State state = distinctState(n);
    const Snapshot snap = snapshotOf(ref, state);
    int flagged = 0;
    State::forEachArrayOf(snap.state, state,
                          [&](const Field& f, const auto& kept, const auto& original) {
                              SCOPED_TRACE(f.name);
                              if (f.isSavedIn(kSnapshot)) {
                                  ++flagged;
                                  EXPECT_EQ(kept, original);
                              } else {
                                  EXPECT_TRUE(kept.empty());
                              }
                          });
    EXPECT_EQ(flagged, 10);  // x, v, σ, F, ε̄p, T, D, e, plastic work, damage driver
    // And forEachField visits them with the same fields.
    int visited = 0;
    snap.forEachField([&](const Field& f, const auto&) {
        if (f.isSavedIn(kCheckpoint)) ++visited;
    });
    EXPECT_EQ(visited, flagged);
}

// The field State::forEachArray visits with the array `member` of a state.
const Field* fieldOfArray(const State& s, const std::vector<double>* member) {
    const Field* out = nullptr;
    s.forEachArray([&](const Field& f, const auto& array) {
        if (static_cast<const void*>(&array) == member) out = &f;
    });
    return out;
}

TEST(FieldRegistry, MaterialsNameTheirHistoryByTheFieldsOfTheStateArraysTheyKeep) {
    const State s;
    const ElasticConstants& copper = testing::kCopperElastic;
    const Material models[] = {
        HypoElastic(copper),
        JohnsonCook(copper, testing::copperParams(),
                    EquationOfState::linear(copper.density, copper.bulkModulus()))};
    EXPECT_TRUE(historyVariables(models[0]).empty());
    EXPECT_FALSE(tracksHistory(models[0]));
    ASSERT_EQ(historyVariables(models[1]).size(), 5u);
    EXPECT_TRUE(tracksHistory(models[1]));
    std::set<std::string> names;
    for (const HistoryVariable& h : historyVariables(models[1])) {
        EXPECT_EQ(fieldOfArray(s, &(s.*(h.array))), h.field) << h.field->name;
        names.insert(h.field->name);
    }
    EXPECT_EQ(names, (std::set<std::string>{"plastic_strain", "temperature", "damage",
                                            "internal_energy", "damage_driver"}));
}

TEST(FieldRegistry, LoadingAndStoringAHistoryCopiesExactlyTheModelsVariables) {
    const State from = distinctState(3);
    MaterialPoint p;
    loadHistory<JohnsonCook>(from, 2, p);
    EXPECT_EQ(p.plasticStrain, from.plasticStrain[2]);
    EXPECT_EQ(p.temperature, from.temperature[2]);
    EXPECT_EQ(p.damage, from.damage[2]);
    EXPECT_EQ(p.internalEnergy, from.internalEnergy[2]);
    State to = State::atRest(std::vector<Vec3>(3, Vec3::Zero()));
    storeHistory<JohnsonCook>(p, 1, to);
    EXPECT_EQ(to.plasticStrain[1], from.plasticStrain[2]);
    EXPECT_EQ(to.temperature[1], from.temperature[2]);
    EXPECT_EQ(to.damage[1], from.damage[2]);
    EXPECT_EQ(to.internalEnergy[1], from.internalEnergy[2]);
    EXPECT_EQ(to.plasticWork[1], 0.0) << "plastic work is a dissipation, not a history variable";
    // The elastic model has none: the point is left as it was.
    MaterialPoint elastic;
    loadHistory<HypoElastic>(from, 2, elastic);
    EXPECT_EQ(elastic.plasticStrain, 0.0);
    EXPECT_EQ(elastic.temperature, State::kRoomTemperature);
}

// `text` in backquotes, as the documents quote names.
std::string quoted(const std::string& text) {
    std::string out(1, '`');
    out += text;
    out += '`';
    return out;
}

// docs/formats.md documents every field: each checkpoint array as `NAME` and each snapshot
// dataset as `/particles/NAME`, and every unit other than "1" appears in the document.
TEST(FieldRegistry, TheFormatsDocumentNamesEveryField) {
    std::ifstream in(std::string(GSPH_SOURCE_DIR) + "/docs/formats.md");
    ASSERT_TRUE(in) << "docs/formats.md";
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    for (const Field* f : everyField()) {
        SCOPED_TRACE(f->name);
        if (f->isSavedIn(kCheckpoint)) {
            EXPECT_NE(doc.find(quoted(f->name)), std::string::npos);
        }
        if (f->isSavedIn(kSnapshot)) {
            EXPECT_NE(doc.find(quoted(std::string("/particles/") + f->name)), std::string::npos);
        }
        if (std::string(f->unit) != "1") {
            EXPECT_NE(doc.find(f->unit), std::string::npos) << f->unit;
        }
    }
}

}  // namespace
}  // namespace gsph
