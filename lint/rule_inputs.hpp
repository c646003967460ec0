// What each rule family reads (issue 45 item 2): the editor's re-check after an edit reruns only the
// families whose inputs the edit changed and keeps the others' findings from the last check
// (engine/rule_reuse.hpp). A family's findings are a function of what it reads here and of the rule
// options; whatever else it might read must be added here, or its reuse goes wrong (the random-edit
// test in tests/test_incremental.cpp compares every re-check with a full check).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace sphdeck::lint {

// The rule families of lint/rules.hpp, in the order run_rules runs them.
enum class RuleFamily : std::uint8_t {
    References,
    ControlSph,
    SectionSph,
    SphParticles,
    SphMaterials,
    Isph,
    Densities,
    SphDimension,
    Preview,
    Radioss,
};
inline constexpr std::size_t rule_family_count = 10;
inline constexpr std::array<RuleFamily, rule_family_count> all_rule_families = {
    RuleFamily::References,   RuleFamily::ControlSph, RuleFamily::SectionSph, RuleFamily::SphParticles,
    RuleFamily::SphMaterials, RuleFamily::Isph,       RuleFamily::Densities,  RuleFamily::SphDimension,
    RuleFamily::Preview,      RuleFamily::Radioss};

std::string_view name_of(RuleFamily family);  // "check_references"

// The parts of a deck a family's findings depend on. The reader's own findings (DK010 and the like),
// the block structure and the keyword arguments are read by some families too, but an edit the
// re-check splices never changes them (grammar/deck_splice.hpp), so they are not listed.
struct DeckInputs {
    bool node_ids = false;        // the ids of *NODE (and which line holds each)
    bool node_positions = false;  // the coordinates of *NODE (and the text of its lines)
    bool particles = false;       // *ELEMENT_SPH: node, part, mass or volume of each particle, its line
    bool keywords = false;        // every other block: its decoded values and card lines, but its titles
    bool titles = false;          // title cards (*PART's heading, the TITLE card of _TITLE keywords)
    bool preview = false;         // the geometry preview (RuleContext::preview)
};

const DeckInputs& inputs_of(RuleFamily family);

// Whether an edit that changed `changed` changes what `family` reads.
bool reads_any(RuleFamily family, const DeckInputs& changed);

}  // namespace sphdeck::lint
