// Which fields define or name which kind of id (grammar/keywords/id_kinds.hpp): one declaration that the
// REF rules and the editor's id look-ups both read, so a definition the rules accept is one the editor finds.
#include <doctest/doctest.h>

#include "engine/check.hpp"
#include "engine/id_lookup.hpp"
#include "grammar/keywords/id_kinds.hpp"
#include "test_support.hpp"

namespace test_id_kinds_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using test::count_code;

TEST_CASE("id kinds: the field holding a block's own id, by family") {
    const keywords::IdDefinition* part = keywords::defining_field("*PART_INERTIA", "PID");
    REQUIRE(part);
    CHECK(part->kind == "PART");
    CHECK(keywords::defining_field("*PART", "SECID") == nullptr);           // names a section, defines none
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

TEST_CASE("id kinds: pydyna's integers read as reals are ids (*DEFINE_TABLE TBID), for the editor as for the rules") {
    const keywords::FieldSpec tbid{.name = "TBID", .type = keywords::FieldType::Real, .pydyna_integer = true};
    REQUIRE(keywords::id_role("*DEFINE_TABLE", tbid));
    CHECK(keywords::id_role("*DEFINE_TABLE", tbid)->kind == "DEFINE_CURVE");
    CHECK(keywords::id_role("*DEFINE_TABLE", tbid)->defines);
    const keywords::FieldSpec real{.name = "TBID", .type = keywords::FieldType::Real};
    CHECK_FALSE(keywords::id_role("*DEFINE_TABLE", real));  // a real the manual types F is no id
    const std::string deck =
        "*KEYWORD\n*LOAD_NODE_POINT\n        80         3        12       1.0\n*NODE\n      80\n"
        "*DEFINE_TABLE\n        12\n               1.0                13\n"
        "*DEFINE_CURVE\n        13\n       0.0       1.0\n";
    const engine::CheckResult r = engine::check_buffer(deck, "d.k");
    CHECK(count_code(r.diagnostics, "REF009") == 0);
    const std::vector<engine::IdUse> found = engine::find_definitions(r, "DEFINE_CURVE", "12");
    REQUIRE(found.size() == 1);
    CHECK(found[0].block->keyword == "*DEFINE_TABLE");
    CHECK(found[0].span.line == 7);
}

TEST_CASE("id kinds: *PART_SENSOR, *PART_MODES and *PART_MOVE name parts, they define none") {
    CHECK(keywords::defining_field("*PART_SENSOR", "PID") == nullptr);
    CHECK(keywords::defining_field("*PART_MODES", "PID") == nullptr);
    CHECK(keywords::defining_field("*PART_MOVE", "PID") == nullptr);
    CHECK(keywords::defining_field("*PART_INERTIA", "PID") != nullptr);
    CHECK_FALSE(keywords::defines_kind("*PART_SENSOR", "PART"));
    const keywords::FieldSpec pid{.name = "PID", .type = keywords::FieldType::Real, .pydyna_integer = true};
    REQUIRE(keywords::id_role("*PART_MOVE", pid));
    CHECK(keywords::id_role("*PART_MOVE", pid)->kind == "PART");
    CHECK_FALSE(keywords::id_role("*PART_MOVE", pid)->defines);
    // Two lines of *PART_SENSOR: the second is no *PART data card, so it makes no part 2 whose "section 10"
    // (the sensor SIDA) REF003 would report; the editor goes from the PID to the *PART that defines it.
    const std::string deck =
        "*KEYWORD\n*PART\nwater\n         1         1         1\n*SECTION_SPH\n         1\n"
        "*MAT_NULL\n         1     1.0E3\n*PART_SENSOR\n         1        10         1\n"
        "         2        10         1\n*END\n";
    const engine::CheckResult r = engine::check_buffer(deck, "d.k");
    CHECK(r.model.parts.size() == 1);
    CHECK(count_code(r.diagnostics, "REF003") == 0);
    std::size_t named = 0;
    for (const engine::IdUse& use : engine::collect_ids(r))
        if (use.block && use.block->keyword == "*PART_SENSOR" && use.kind == "PART") {
            CHECK_FALSE(use.defines);
            ++named;
        }
    CHECK(named >= 1);
    const std::vector<engine::IdUse> part = engine::find_definitions(r, "PART", "1");
    REQUIRE(part.size() == 1);
    CHECK(part[0].block->keyword == "*PART");
    // A part only *PART_SENSOR names: REF002 reports it and the editor finds no definition.
    const std::string other = "*KEYWORD\n*PART_SENSOR\n         2        10         1\n*END\n";
    const engine::CheckResult o = engine::check_buffer(other, "d.k");
    CHECK(count_code(o.diagnostics, "REF002") == 1);
    CHECK(engine::find_definitions(o, "PART", "2").empty());
}
}  // namespace test_id_kinds_cpp
