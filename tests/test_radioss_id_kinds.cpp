// Which OpenRadioss headers and cells define or name which kind of id (grammar/radioss/id_kinds.hpp): one
// declaration that the REF rules of generated cards and the editor's go-to-definition and references both
// read, so an id the rules accept as defined is one the editor goes to, and one they reject it cannot find.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "grammar/radioss/id_kinds.hpp"
#include "lsp/features.hpp"

namespace test_radioss_id_kinds_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace rad = grammar::radioss;

namespace {

// Functions and tables share one space (/FUNCT, /TABLE, /FUNCT_SMOOTH); /MOVE_FUNCT names a function;
// a skew id may be a /FRAME's; a /SET stands for any group. The cells: /IMPTEMP curveid (CFG type
// FUNCT), rad_sensor_id (SENSOR), entityid (SETS of /SETS/GRNOD); /IMPACC inputsystem (SYSTEM); /AMS
// GRPART_ID and /PART subset_ID by their names.
const std::string kDeck = R"(#RADIOSS STARTER
/BEGIN
ids
      2026         0
                  kg                  mm                  ms
                  kg                  mm                  ms
/NODE
         1                 0.0                 0.0                 0.0
/GRNOD/NODE/6
nodes
         1
/FUNCT/12
curve
                 0.0                 1.0
                 1.0                 1.0
/MOVE_FUNCT/12
moved
                 2.0                 1.0                 0.0                 0.0
/TABLE/1/13
table
         1
/FUNCT_SMOOTH/14
smooth
                 1.0                 1.0                 0.0                 0.0
                 0.0                 1.0
                 1.0                 1.0
/SENSOR/TIME/5
clock
                 0.0
/FRAME/FIX/3
frame
                 0.0                 0.0                 0.0
                 0.0                 1.0                 0.0
                 0.0                 0.0                 1.0
/GRPART/PART/8
parts
         1
/SUBSET/7
subset
         1
/IMPTEMP/1
temperature
        13         5         6
                 1.0                 1.0                 0.0               1e+30
/IMPTEMP/2
temperature
        14         5         6
                 1.0                 1.0                 0.0               1e+30
/IMPACC/3
acceleration
        12         X         3         5         6
                 1.0                 1.0                 0.0               1e+30
/AMS
         8
/PART/1
part
         1         1         7
/END
)";

lsp::CheckedDeck check(const std::string& text) {
    lsp::CheckedDeck deck;
    deck.main = "ids_0000.rad";
    deck.result = engine::check_buffer(text, "ids_0000.rad", {}, std::nullopt);
    return deck;
}

// The 0-based line of the first line starting with `start` after line `from`.
std::uint32_t line_of(const std::string& text, std::string_view start, std::uint32_t from = 0) {
    std::uint32_t line = 0;
    for (std::size_t at = 0; at < text.size(); at = text.find('\n', at) + 1, ++line) {
        if (line >= from && text.compare(at, start.size(), start) == 0) return line;
        if (text.find('\n', at) == std::string::npos) break;
    }
    FAIL("no line starts with " << start);
    return 0;
}

// The line (0-based) go-to-definition answers at a position, -1 for none or several.
int definition_line(const lsp::CheckedDeck& deck, std::uint32_t line, std::uint32_t character) {
    const nlohmann::json found = lsp::definition(deck, 0, {line, character});
    if (!found.is_object()) return -1;
    return found["range"]["start"]["line"].get<int>();
}

std::vector<int> reference_lines(const lsp::CheckedDeck& deck, std::uint32_t line, std::uint32_t character) {
    std::vector<int> out;
    for (const auto& location : lsp::references(deck, 0, {line, character}, true))
        out.push_back(location["range"]["start"]["line"].get<int>());
    std::sort(out.begin(), out.end());
    return out;
}

std::size_t count_code(const lsp::CheckedDeck& deck, std::string_view code) {
    std::size_t n = 0;
    for (const auto& d : deck.result.diagnostics) n += d.code == code;
    return n;
}

}  // namespace

TEST_CASE("radioss id kinds: headers define or name ids, /TABLE after its dimension") {
    const auto table = rad::header_id("/TABLE/1/13");
    REQUIRE(table);
    REQUIRE(table->role);
    CHECK(table->role->kind == "FUNCT");
    CHECK(table->role->defines);
    CHECK(table->id == 13);
    CHECK(std::string_view("/TABLE/1/13").substr(table->begin, table->end - table->begin) == "13");
    const auto moved = rad::header_id("/MOVE_FUNCT/12");
    REQUIRE(moved);
    CHECK(moved->role->kind == "FUNCT");
    CHECK_FALSE(moved->role->defines);  // it scales function 12 (hm_read_move_funct.F)
    CHECK(rad::header_role("FUNCT_SMOOTH")->kind == "FUNCT");
    CHECK(rad::header_role("SENSOR")->defines);
    CHECK(rad::header_role("EOS")->kind == "MAT");
    CHECK_FALSE(rad::header_role("EOS")->defines);
    CHECK_FALSE(rad::header_role("INTER"));
    CHECK(rad::header_id("/GRNOD/NODE/6")->id == 6);
    CHECK_FALSE(rad::header_id("/ANIM/VECT/VEL"));
}

TEST_CASE("radioss id kinds: the kind a cell names, by its CFG link or its name") {
    CHECK(rad::kind_named_by({.name = "curveid", .link = 'F'}) == "FUNCT");
    CHECK(rad::kind_named_by({.name = "rad_sensor_id", .link = 'S'}) == "SENSOR");
    CHECK(rad::kind_named_by({.name = "inputsystem", .link = 'Y'}) == "SKEW");
    CHECK(rad::kind_named_by({.name = "fct_IDP"}) == "FUNCT");
    CHECK(rad::kind_named_by({.name = "Sens_ID1"}) == "SENSOR");
    CHECK(rad::kind_named_by({.name = "tab_IDfld"}) == "FUNCT");
    CHECK(rad::kind_named_by({.name = "grsh4n_ID"}) == "GRSHEL");
    CHECK(rad::kind_named_by({.name = "subset_ID"}) == "SUBSET");
    CHECK(rad::kind_named_by({.name = "MAT_IDEL"}).empty());  // an element deletion flag
    CHECK(rad::kind_named_by({.name = "brick_ID"}).empty());
    CHECK(rad::kind_named_by({.name = "fct_ID", .cell = rad::Cell::Real}).empty());
    CHECK(rad::ids_meet("SKEW", "FRAME"));
    CHECK(rad::ids_meet("SET", "GRPART"));
    CHECK(rad::ids_meet("LINE", "SET"));
    CHECK_FALSE(rad::ids_meet("GRNOD", "SURF"));
    CHECK_FALSE(rad::ids_meet("SUBSET", "SET"));
    CHECK(rad::defined_by("FUNCT") == "/FUNCT or /TABLE");
}

TEST_CASE("radioss id kinds: go to the definition of a table, sensor, frame, smoothed function, part group, subset") {
    const auto deck = check(kDeck);
    const std::uint32_t temp = line_of(kDeck, "        13");
    CHECK(definition_line(deck, temp, 8) == static_cast<int>(line_of(kDeck, "/TABLE/1/13")));
    CHECK(definition_line(deck, temp, 18) == static_cast<int>(line_of(kDeck, "/SENSOR/TIME/5")));
    CHECK(definition_line(deck, temp, 28) == static_cast<int>(line_of(kDeck, "/GRNOD/NODE/6")));
    CHECK(definition_line(deck, line_of(kDeck, "        14"), 8) ==
          static_cast<int>(line_of(kDeck, "/FUNCT_SMOOTH/14")));
    const std::uint32_t acc = line_of(kDeck, "        12         X");
    CHECK(definition_line(deck, acc, 8) == static_cast<int>(line_of(kDeck, "/FUNCT/12")));
    CHECK(definition_line(deck, acc, 28) == static_cast<int>(line_of(kDeck, "/FRAME/FIX/3")));  // a skew id
    CHECK(definition_line(deck, line_of(kDeck, "/MOVE_FUNCT/12"), 12) == static_cast<int>(line_of(kDeck, "/FUNCT/12")));
    CHECK(definition_line(deck, line_of(kDeck, "         8"), 9) == static_cast<int>(line_of(kDeck, "/GRPART/PART/8")));
    CHECK(definition_line(deck, line_of(kDeck, "         1         1         7"), 29) ==
          static_cast<int>(line_of(kDeck, "/SUBSET/7")));
}

TEST_CASE("radioss id kinds: references to a function, a table and a sensor") {
    const auto deck = check(kDeck);
    const int funct = static_cast<int>(line_of(kDeck, "/FUNCT/12"));
    const int moved = static_cast<int>(line_of(kDeck, "/MOVE_FUNCT/12"));
    const int acc = static_cast<int>(line_of(kDeck, "        12         X"));
    CHECK(reference_lines(deck, static_cast<std::uint32_t>(funct), 8) == std::vector<int>{funct, moved, acc});
    const int table = static_cast<int>(line_of(kDeck, "/TABLE/1/13"));
    const int temp = static_cast<int>(line_of(kDeck, "        13"));
    CHECK(reference_lines(deck, static_cast<std::uint32_t>(table), 10) == std::vector<int>{table, temp});
    const int sensor = static_cast<int>(line_of(kDeck, "/SENSOR/TIME/5"));
    CHECK(reference_lines(deck, static_cast<std::uint32_t>(sensor), 13) ==
          std::vector<int>{sensor, temp, static_cast<int>(line_of(kDeck, "        14")), acc});
}

TEST_CASE("radioss id kinds: the REF rules accept what the editor finds, and no id /MOVE_FUNCT or a dimension gives") {
    CHECK(count_code(check(kDeck), "REF009") == 0);
    CHECK(count_code(check(kDeck), "REF008") == 0);
    // /MOVE_FUNCT/20 moves a function 20 the deck lacks; /TABLE/1/13's 1 is its dimension, not a function.
    std::string deck = kDeck;
    deck.replace(deck.find("/MOVE_FUNCT/12"), 14, "/MOVE_FUNCT/20");
    deck.replace(deck.find("        12         X"), 10, "        20");
    deck.replace(deck.find("        14         5"), 10, "         1");
    const auto checked = check(deck);
    CHECK(count_code(checked, "REF009") == 2);
    for (const auto& d : checked.result.diagnostics)
        if (d.code == "REF009") CHECK(d.message.find("names no /FUNCT or /TABLE of the deck") != std::string::npos);
    CHECK(definition_line(checked, line_of(deck, "/MOVE_FUNCT/20"), 12) == -1);
}
}  // namespace test_radioss_id_kinds_cpp
