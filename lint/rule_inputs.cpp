#include "lint/rule_inputs.hpp"

namespace sphdeck::lint {
namespace {

// Read from the rule bodies (lint/rules_*.cpp and the RuleContext look-ups they call). Every family
// reads the other keywords' values: narrowing that to keyword families is left for when it pays (an
// edit outside the bulk blocks that changes a value reruns them all, cheaply but for the particle loops).
// No family reads a title: Part::heading and the TITLE/HEADING fields are shown, never checked.
// clang-format off
constexpr std::array<DeckInputs, rule_family_count> kInputs = {{
    // References: node ids (REF001, duplicates), never coordinates; particles, sets, parts, links.
    {.node_ids = true, .node_positions = false, .particles = true, .keywords = true},
    // ControlSph: BOXID's box over the particles' positions (SPH071), particle counts.
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true},
    // SectionSph: the parts the particles name.
    {.node_ids = false, .node_positions = false, .particles = true, .keywords = true},
    // SphParticles: masses, 2D planes and axes (coordinates).
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true},
    // SphMaterials: boxes and sets over the particles' positions.
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true},
    // Isph: keyword blocks only.
    {.node_ids = false, .node_positions = false, .particles = false, .keywords = true},
    // Densities: materials, parts, sections.
    {.node_ids = false, .node_positions = false, .particles = false, .keywords = true},
    // SphDimension: the particles' extent.
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true},
    // Preview: the preview and what it is made of.
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true, .preview = true},
    // Radioss: Radioss decks (never spliced); everything, to be safe.
    {.node_ids = true, .node_positions = true, .particles = true, .keywords = true, .titles = true, .preview = true},
}};
// clang-format on

}  // namespace

std::string_view name_of(RuleFamily family) {
    switch (family) {
        case RuleFamily::References: return "check_references";
        case RuleFamily::ControlSph: return "check_control_sph";
        case RuleFamily::SectionSph: return "check_section_sph";
        case RuleFamily::SphParticles: return "check_sph_particles";
        case RuleFamily::SphMaterials: return "check_sph_materials";
        case RuleFamily::Isph: return "check_isph";
        case RuleFamily::Densities: return "check_densities";
        case RuleFamily::SphDimension: return "check_sph_dimension";
        case RuleFamily::Preview: return "check_preview";
        case RuleFamily::Radioss: return "check_radioss";
    }
    return "?";
}

const DeckInputs& inputs_of(RuleFamily family) { return kInputs[static_cast<std::size_t>(family)]; }

bool reads_any(RuleFamily family, const DeckInputs& changed) {
    const DeckInputs& reads = inputs_of(family);
    return (reads.node_ids && changed.node_ids) || (reads.node_positions && changed.node_positions) ||
           (reads.particles && changed.particles) || (reads.keywords && changed.keywords) ||
           (reads.titles && changed.titles) || (reads.preview && changed.preview);
}

}  // namespace sphdeck::lint
