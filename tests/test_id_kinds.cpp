// Which fields define or name which kind of id (grammar/keywords/id_kinds.hpp): one declaration that the
// REF rules and the editor's id look-ups both read, so a definition the rules accept is one the editor finds.
#include <doctest/doctest.h>

#include "engine/check.hpp"
#include "engine/id_lookup.hpp"
#include "grammar/keywords/id_kinds.hpp"
#include "test_support.hpp"

using namespace sphdeck;
using test::count_code;

TEST_CASE("id kinds: the field holding a block's own id, by family") {
    const keywords::IdDefinition* part = keywords::defining_field("*PART_INERTIA", "PID");
    REQUIRE(part);
    CHECK(part->kind == "PART");
    CHECK(keywords::defining_field("*PART", "SECID") == nullptr);  // names a section, defines none
    CHECK(keywords::defining_field("*MAT_ADD_EROSION", "MID") == nullptr);  // adds to a material
    CHECK(keywords::defining_field("*MAT_ELASTIC", "MID")->kind == "MAT");
    CHECK(keywords::defining_field("*SET_PART_LIST", "SID")->kind == "SET_PART");
    CHECK(keywords::defining_field("*SET_PARTX", "SID") == nullptr);  // not *SET_PART with an option
    CHECK(keywords::defining_field("*DEFINE_FUNCTION", "FID")->kind == "DEFINE_CURVE");
}

TEST_CASE("id kinds: curves, tables and functions share one id space") {
    CHECK(keywords::id_space("DEFINE_CURVE_OR_TABLE") == "DEFINE_CURVE");
    CHECK(keywords::id_space("SET_NODE") == "SET_NODE");
    for (const char* keyword : {"*DEFINE_CURVE_TITLE", "*DEFINE_TABLE_2D", "*DEFINE_FUNCTION_TABULATED"}) {
        CHECK(keywords::defines_kind(keyword, "DEFINE_CURVE"));
        CHECK(keywords::defines_kind(keyword, "DEFINE_CURVE_OR_TABLE"));
    }
    CHECK_FALSE(keywords::defines_kind("*DEFINE_BOX", "DEFINE_CURVE"));
}

TEST_CASE("id kinds: the kind a field's name gives where the layout links none") {
    CHECK(keywords::kind_named_by("*SET_PART_LIST", "PID3") == "PART");
    CHECK(keywords::kind_named_by("*PART", "SECID") == "SECTION");
    CHECK(keywords::kind_named_by("*ELEMENT_SPH", "PID") == "PART");
    CHECK(keywords::kind_named_by("*ELEMENT_SPH", "NEND").empty());  // ends a range of nodes
    CHECK(keywords::kind_named_by("*CONTROL_SPH", "NCBS").empty());
}

TEST_CASE("id kinds: a curve the REF rules accept as defined is one the editor goes to") {
    const std::string deck =
        "*KEYWORD\n*LOAD_NODE_POINT\n        80         3        12       1.0\n*NODE\n      80\n"
        "*DEFINE_CURVE_TITLE\nload\n        12\n       0.0       1.0\n";
    const engine::CheckResult r = engine::check_buffer(deck, "d.k");
    CHECK(count_code(r.diagnostics, "REF009") == 0);
    const std::vector<engine::IdUse> found = engine::find_definitions(r, "DEFINE_CURVE", "12");
    REQUIRE(found.size() == 1);
    CHECK(found[0].block->keyword == "*DEFINE_CURVE_TITLE");
    CHECK(found[0].span.line == 8);  // after the title line
    CHECK(found[0].title == "load");
}
