// Shared pieces of the RAD rule family (rules_radioss*.cpp): particle positions, the reference
// smoothing length the starter uses for "on the plane", SOL2SPH parts and element sizes.
// Internal to the family; lint/rules.hpp declares only its entry point, check_radioss.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "lint/rule_context.hpp"

namespace sphdeck::lint::radioss {

inline constexpr std::size_t max_listed = 5;  // ids named in one message

// Particles sharing one finding: how many, and the first few (model indices).
struct Group {
    std::size_t count = 0;
    std::vector<std::size_t> first;
    void add(std::size_t i) {
        if (count++ < max_listed) first.push_back(i);
    }
    std::string ids(const model::Particles& p) const;
};

// Position of every particle's node; nullopt when the node is missing (REF001).
struct Positions {
    std::vector<std::array<double, 3>> at;
    std::vector<std::uint8_t> located;
};
Positions particle_positions(const model::Model& m);

// The starter's reference length for a part's particles (sph-algorithms.md §8.5): the property
// h, or (√2·mp/ρ)^(1/3) when h is 0; 0 when neither is known.
double reference_h(const model::Model& m, long long part);

// The /PROP/SPH of a part, or nullptr.
const model::RadiossSphProperty* sph_property_of(const model::Model& m, long long part);
// The material law of a part (-1 when unknown), and the material.
const model::RadiossMaterial* material_of(const model::Model& m, long long part);

// Parts whose property is a SOL2SPH solid property (Ndir ≠ 0).
std::vector<const model::Part*> parts_using(const model::Model& m, long long property);

// Mean edge length of each element of `parts` (bricks and tetras), for pitch estimates.
std::vector<double> element_sizes(const model::Model& m, const std::vector<long long>& parts);

double median(std::vector<double> v);

// The columns of a /SPHCEL field of particle `i` ("Type", "MASS").
grammar::Span cell_field_span(const RuleContext& c, std::size_t particle, std::string_view field);

// Rules by group (rules_radioss*.cpp).
void check_symmetry(RuleContext& c);        // RAD002-RAD008
void check_sol2sph(RuleContext& c);         // RAD010-RAD016, RAD021
void check_properties(RuleContext& c);      // RAD020, RAD022-RAD024, RAD026-RAD029, DK018 for /SPHGLO
void check_sph_references(RuleContext& c);  // REF001, REF002: /SPH/INOUT and /INISPHCEL ids
// REF002-REF004, REF008, REF009: ids named by generated cards (model::RadiossIdUse).
void check_generated_references(RuleContext& c);
// RAD040: the starter's own value checks, law by law (lint/starter_checks.hpp).
void check_starter_values(RuleContext& c);
// RAD042: /TH selections naming ids the entity kind of their keyword does not define.
void check_time_history_selections(RuleContext& c);

}  // namespace sphdeck::lint::radioss
