// `sphdeck dump --format json`: every field of every card a keyword defines, with the defaults
// of the cards the deck left out; valid JSON on Latin-1 text; OpenRadioss decks block by block.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_dump_command_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using json = nlohmann::ordered_json;  // keeps the order of the output

namespace {

// *CONTROL_SPH with card 1 only: cards 2 and 3 (CONT ... ISYMP, ITHK ... QL) are optional.
const std::string kCard1Only =
    "*KEYWORD\n"
    "*CONTROL_SPH\n"
    "$#    ncbs     boxid        dt      idim    memory      form     start      maxv\n"
    "         1         0   1.0e+20         2       150        15\n"
    "*END\n";

json dump(const test::TempDir& dir, const std::string& deck) {
    test::Run r = test::run_sphdeck(dir, "dump " + deck);
    REQUIRE(r.exit_code == 0);
    return json::parse(r.out);
}

const json& control_sph_fields(const json& doc) {
    for (const json& k : doc["keywords"])
        if (k["name"] == "*CONTROL_SPH") return k["fields"];
    FAIL("no *CONTROL_SPH in the dump");
    static const json none;
    return none;
}

}  // namespace

TEST_CASE("dump: fields of optional cards the deck did not write carry their defaults") {
    test::TempDir dir;
    dir.write("sph.k", kCard1Only);
    const json doc = dump(dir, "sph.k");
    const json& f = control_sph_fields(doc);
    // Written, and blank in a written card: positioned.
    CHECK(f["FORM"]["value"] == 15);
    CHECK(f["FORM"]["explicit"] == true);
    CHECK(f["START"]["explicit"] == false);
    CHECK(f["START"]["line"] == 4);
    // Card 2 and card 3 were not written: defaults, not explicit, no position.
    CHECK(f["INI"]["value"] == 0);
    CHECK(f["INI"]["explicit"] == false);
    CHECK(f["INI"]["line"].is_null());
    CHECK(f["ISYMP"]["value"] == 100);
    CHECK(f["IAVIS"]["value"] == 0);
    CHECK(f["QL"]["value"] == doctest::Approx(0.01));
    CHECK(f["QL"]["explicit"] == false);
    CHECK(f["QL"]["column"].is_null());
}

TEST_CASE("dump: fields keep the schema's order, written or not") {
    test::TempDir dir;
    dir.write("sph.k", kCard1Only);
    const json doc = dump(dir, "sph.k");
    const json& f = control_sph_fields(doc);
    std::vector<std::string> names;
    for (auto it = f.begin(); it != f.end(); ++it) names.push_back(it.key());
    REQUIRE(names.size() >= 19);
    CHECK(names.front() == "NCBS");
    auto position = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
    CHECK(position("MAXV") < position("CONT"));
    CHECK(position("ISYMP") < position("ITHK"));
    CHECK(position("ITHK") < position("QL"));
}

TEST_CASE("dump: a keyword with repeated cards keeps them") {
    test::TempDir dir;
    dir.write("curve.k",
              "*KEYWORD\n*DEFINE_CURVE\n         7\n                 0.0                 1.0\n"
              "                 1.0                 2.0\n*END\n");
    json doc = dump(dir, "curve.k");
    const json& curve = doc["keywords"][0];
    CHECK(curve["fields"]["LCID"]["value"] == 7);
    CHECK(curve["fields"]["SFO"]["value"] == doctest::Approx(1.0));
    CHECK(curve["fields"]["SFO"]["explicit"] == false);
    CHECK(curve["cards"].size() == 3);
}

TEST_CASE("dump: Latin-1 text gives valid JSON") {
    test::TempDir dir;
    dir.write("latin1.k",
              "*KEYWORD\n*TITLE\nd\xE9"
              "cembre: barrage \xE0 2 dimensions\n*END\n");
    json doc = dump(dir, "latin1.k");
    CHECK(doc["keywords"][0]["name"] == "*TITLE");
    const std::string title = doc["keywords"][0]["fields"]["TITLE"]["value"];
    CHECK(title ==
          "d\xEF\xBF\xBD"
          "cembre: barrage \xEF\xBF\xBD 2 dimensions");
}

TEST_CASE("dump: an OpenRadioss deck gives its blocks with the fields as read") {
    test::TempDir dir;
    dir.write("m_0000.rad",
              "#RADIOSS STARTER\n/BEGIN\nrun\n      2026         0\n"
              "                  kg                  mm                  ms\n"
              "                  kg                  mm                  ms\n"
              "/PART/2\nwater\n         2         3\n"
              "/NODE\n      1001                 1.0                 1.0                 1.0\n"
              "      1002                 2.0                 1.0                 1.0\n"
              "/UNKNOWN_THING/4\n1 2 3\n/END\n");
    test::Run r = test::run_sphdeck(dir, "dump m_0000.rad");
    REQUIRE(r.exit_code == 0);
    const json doc = json::parse(r.out);
    CHECK(doc["format"] == "radioss");
    CHECK(doc["version"] == 2026);
    REQUIRE(doc["keywords"].size() == 3);
    const json& part = doc["keywords"][1];
    CHECK(part["name"] == "/PART/2");
    CHECK(part["keyword"] == "/PART");
    CHECK(part["title"] == "water");
    CHECK(part["line"] == 7);
    CHECK(part["fields"]["prop_ID"]["value"] == 2);
    CHECK(part["fields"]["prop_ID"]["explicit"] == true);
    CHECK(part["fields"]["subset_ID"]["value"].is_null());
    CHECK(part["fields"]["subset_ID"]["explicit"] == false);
    CHECK(doc["keywords"][2]["records"] == 2);  // /NODE lines are counted, not listed
    CHECK(doc["nodes"]["count"] == 2);
    CHECK(doc["unknown_keywords"]["/UNKNOWN_THING"] == 1);
}

TEST_CASE("dump: a keyword written without card lines shows its defaults, in deck order") {
    test::TempDir dir;
    dir.write("bare.k", "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*CONTROL_SPH\n*DEFINE_CURVE\n         7\n*END\n");
    json doc = dump(dir, "bare.k");
    REQUIRE(doc["keywords"].size() == 3);
    CHECK(doc["keywords"][0]["name"] == "*CONTROL_TERMINATION");
    CHECK(doc["keywords"][2]["name"] == "*DEFINE_CURVE");
    const json& sph = doc["keywords"][1];
    CHECK(sph["name"] == "*CONTROL_SPH");
    CHECK(sph["line"] == 4);
    CHECK(sph["fields"]["NCBS"]["value"] == 1);
    CHECK(sph["fields"]["NCBS"]["explicit"] == false);
    CHECK(sph["fields"]["NCBS"]["line"].is_null());
    CHECK(sph["fields"]["QL"]["value"] == doctest::Approx(0.01));
}
}  // namespace test_dump_command_cpp
