// DK001's policy for LS-DYNA keyword names (issue 37, grammar/keywords/keyword_names.hpp): the spellings
// LS-DYNA reads as a laid-out keyword, the names known without a layout, the option grammar, and the
// did-you-mean that replaces no word wholesale.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "grammar/keywords/keyword_names.hpp"
#include "grammar/keywords/schema.hpp"

namespace test_keyword_names_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

std::string schema_of(std::string_view name) {
    const auto m = keywords::find_keyword(name);
    if (!m || !m->unknown_options.empty()) return "";
    return std::string(m->schema->name);
}

}  // namespace

TEST_CASE("keyword names: legacy spellings and options in another order read as the laid-out keyword") {
    CHECK(schema_of("*SET_SHELL") == "*SET_SHELL_LIST");
    CHECK(schema_of("*SET_SHELL_TITLE") == "*SET_SHELL_LIST");
    CHECK(schema_of("*BOUNDARY_PRESCRIBED_MOTION_NODES") == "*BOUNDARY_PRESCRIBED_MOTION_NODE");
    CHECK(schema_of("*BOUNDARY_PRESCRIBED_MOTION_NODES_ID") == "*BOUNDARY_PRESCRIBED_MOTION_NODE");
    CHECK(schema_of("*SET_NODE_COLLECT").starts_with("*SET_NODE_LIST"));
    const auto tied = keywords::find_keyword("*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_ID_BEAM_OFFSET_MPP");
    REQUIRE(tied);
    CHECK(tied->unknown_options.empty());
    CHECK(tied->schema->name == "*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_BEAM_OFFSET");
    CHECK(tied->has("ID"));
    CHECK(tied->has("MPP"));
    // A name that is its own keyword is not respelled into another.
    CHECK(schema_of("*SET_SHELL_GENERAL") == "*SET_SHELL_GENERAL");
    CHECK(schema_of("*SET_SHELLS") == "");
}

TEST_CASE("keyword names: the second source and names LS-DYNA writes itself are known without a layout") {
    const auto names = keywords::generated::keyword971_names();
    CHECK(names.size() > 700);
    CHECK(std::is_sorted(names.begin(), names.end()));
    CHECK(std::adjacent_find(names.begin(), names.end()) == names.end());
    // Family prefixes that the CFG files only build names from are left out.
    for (std::string_view prefix : {"*CONTACT", "*MAT", "*AIRBAG", "*CONTACT_2D"})
        CHECK_FALSE(keywords::is_keyword971_name(prefix));
    CHECK(keywords::known_by_name("*CONTROL_MPP_IO_NOFAIL"));
    CHECK(keywords::known_by_name("*CONTACT_SPOTWELD_WITH_TORSION_PENALTY_MPP_ID"));
    CHECK(keywords::known_by_name("*RVE_INFO"));
    CHECK(keywords::known_by_name("*TERMINATION_NODE"));  // the manual's, without a layout
    CHECK_FALSE(keywords::known_by_name("*CONTROL_SHP"));
}

TEST_CASE("keyword names: a known keyword with options of the grammar that no table gives it") {
    const auto joint = keywords::known_with_options("*CONSTRAINED_JOINT_REVOLUTE_ID");
    REQUIRE(joint);
    CHECK(joint->base == "*CONSTRAINED_JOINT_REVOLUTE");
    CHECK(joint->options == std::vector<std::string>{"ID"});
    // The longest known keyword first: MORTAR belongs to the name, TITLE is the option.
    const auto mortar = keywords::known_with_options("*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR_TITLE");
    REQUIRE(mortar);
    CHECK(mortar->base == "*CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR");
    CHECK(mortar->options == std::vector<std::string>{"TITLE"});
    const auto two = keywords::known_with_options("*CONSTRAINED_JOINT_REVOLUTE_LOCAL_ID");
    REQUIRE(two);
    CHECK(two->options == std::vector<std::string>{"LOCAL", "ID"});
    // Not the grammar's options, or no known keyword before them: unknown.
    CHECK_FALSE(keywords::known_with_options("*CONTROL_SPH_INCOMPRESSIBLY"));
    CHECK_FALSE(keywords::known_with_options("*CONTROL_SHP_ID"));
    CHECK_FALSE(keywords::known_with_options("*SECTION_SPH_TITEL"));
    CHECK_FALSE(keywords::known_with_options("*ID"));
}

TEST_CASE("keyword names: a did-you-mean replaces no word of the name wholesale") {
    CHECK_FALSE(keywords::suggest_keyword("*INITIAL_SPH"));              // not *INITIAL_CPG: two of SPH's three letters
    CHECK(keywords::suggest_keyword("*CONTROL_SHP") == "*CONTROL_SPH");  // a swap: half an edit
    CHECK(keywords::suggest_keyword("*SECTON_SPH") == "*SECTION_SPH");
    CHECK(keywords::suggest_keyword("*ELEMENT_SPHH") == "*ELEMENT_SPH");
}
}  // namespace test_keyword_names_cpp
