// The MCP server's tools (mcp/tool_*.cpp) on shipped decks and small texts: what each returns, and
// the failures a tool reports as a result with isError.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "mcp_session.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_mcp_tools_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::test;

namespace {
const std::string mistakes = "decks/demo/sph_mistakes_2d.k";
const std::string lower_case_keyword = "*KEYWORD\n*control_termination\n$#  endtim\n       1.0\n*END\n";

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string text_of(const json& answer) { return answer["result"]["content"][0]["text"].get<std::string>(); }
}  // namespace

TEST_CASE("mcp check_deck: the findings of `sphdeck check --format json`, field for field") {
    // Shipped decks with findings and without, LS-DYNA and OpenRadioss, with includes, with fixes.
    for (const std::string& deck :
         {mistakes, std::string("decks/demo/dam_break_2d.k"), std::string("decks/demo/water_tank/water_tank.k"),
          std::string("decks/demo/water_tank/include/materials.k"),  // in context
          std::string("decks/sol2sph/bumper_0000.rad"),
          std::string("decks/tests/dk/DK003_fires_realign.k")}) {  // fixes
        CAPTURE(deck);
        const json result = mcp_result("check_deck", {{"path", deck}});
        // The CLI run elsewhere: its file names are absolute, the server's relative to the source folder.
        TempDir dir;
        const std::string source = std::string(SPHDECK_SOURCE_DIR) + "/";
        const Run run = run_sphdeck(dir, "check --format json '" + source + deck + "'");
        const json cli = json::parse(run.out);
        json expected = cli["diagnostics"];
        const auto relative = [&](json& file) {
            if (file.is_string() && file.get<std::string>().rfind(source, 0) == 0)
                file = file.get<std::string>().substr(source.size());
        };
        for (json& d : expected) {
            relative(d["file"]);
            for (json& n : d["notes"]) relative(n["file"]);
            for (json& f : d["fixes"])
                for (json& e : f["edits"]) relative(e["file"]);
            for (json& c : d["include_chain"]) relative(c["file"]);
        }
        CHECK(result["diagnostics"] == expected);
        CHECK(result["summary"]["errors"] == cli["summary"]["errors"]);
        CHECK(result["summary"]["warnings"] == cli["summary"]["warnings"]);
        CHECK(result["summary"]["files"] == cli["summary"]["files"]);
    }
}

TEST_CASE("mcp check_deck: text in place of a path, select and ignore") {
    const json all = mcp_result("check_deck", {{"text", lower_case_keyword}, {"name", "t.k"}});
    REQUIRE(!all["diagnostics"].empty());
    CHECK(all["diagnostics"][0]["file"] == "t.k");
    bool dk021 = false;
    for (const json& d : all["diagnostics"]) dk021 = dk021 || d["code"] == "DK021";
    CHECK(dk021);
    const json ignored = mcp_result("check_deck", {{"text", lower_case_keyword}, {"ignore", {"DK021"}}});
    for (const json& d : ignored["diagnostics"]) CHECK(d["code"] != "DK021");
    const json selected = mcp_result("check_deck", {{"text", lower_case_keyword}, {"select", {"DK021"}}});
    REQUIRE(selected["diagnostics"].size() == 1);
    CHECK(selected["diagnostics"][0]["fixes"][0]["safe"] == true);
    CHECK(mcp_call("check_deck", {{"text", lower_case_keyword}, {"select", {"XYZ999"}}})["error"]["code"] == -32602);
}

TEST_CASE("mcp check_deck: neither or both of path and text, a bad name, a missing deck") {
    CHECK(mcp_call("check_deck", json::object())["error"]["code"] == -32602);
    CHECK(mcp_call("check_deck", {{"path", mistakes}, {"text", "*KEYWORD\n"}})["error"]["code"] == -32602);
    CHECK(mcp_call("check_deck", {{"text", "*KEYWORD\n"}, {"name", "../x.k"}})["error"]["code"] == -32602);
    const json missing = mcp_call("check_deck", {{"path", "decks/no_such_deck.k"}});
    CHECK(missing["result"]["isError"] == true);
    CHECK(text_of(missing).find("no_such_deck.k") != std::string::npos);
}

TEST_CASE("mcp check_deck: a deck that includes a file outside the roots returns none of it") {
    TempDir outside;  // in the temporary folder, not below the source folder (the root)
    const std::string secret = outside.write("secret.k", "*KEYWORD\n*CONTROL_TERMINATION\n      1.0\n*END\n");
    const json answer = mcp_call("check_deck", {{"text", "*KEYWORD\n*INCLUDE\n" + secret + "\n*END\n"}});
    CHECK(answer["result"]["isError"] == true);
    CHECK(text_of(answer).find("outside the roots") != std::string::npos);
}

TEST_CASE("mcp fix_deck: safe fixes as a diff and the fixed text; nothing written") {
    const json result = mcp_result("fix_deck", {{"text", lower_case_keyword}});
    CHECK(result["fixed"].get<int>() >= 1);
    CHECK(result["diff"].get<std::string>().find("+*CONTROL_TERMINATION") != std::string::npos);
    CHECK(result["text"].get<std::string>().find("*CONTROL_TERMINATION\n") != std::string::npos);
    CHECK(result["written"] == false);
    for (const json& d : result["remaining"]) CHECK(d["code"] != "DK021");
    // A shipped deck is left alone: its findings carry no safe fix.
    const json demo = mcp_result("fix_deck", {{"path", mistakes}});
    CHECK(demo["diff"] == "");
    CHECK(mcp_call("fix_deck", {{"text", lower_case_keyword}, {"write", true}})["error"]["code"] == -32602);
}

TEST_CASE("mcp fix_deck: write: true mends the file in place") {
    TempDir dir;
    const std::string path = dir.write("deck.k", lower_case_keyword);
    // Run from the folder of the deck: it is the root.
    const json result = mcp_result("fix_deck", {{"path", "deck.k"}, {"write", true}}, dir.path());
    CHECK(result["written"] == true);
    CHECK(read_file(path).find("*CONTROL_TERMINATION\n") != std::string::npos);
}

TEST_CASE("mcp format_deck: the canonical layout as text and diff") {
    const json result = mcp_result("format_deck", {{"text", "*KEYWORD\n*CONTROL_TERMINATION\n1.0\n*END\n"}});
    CHECK(result["changed"] == true);
    CHECK(result["text"] == "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n*END\n");
    CHECK(result["diff"].get<std::string>().find("+       1.0") != std::string::npos);
    const json shipped = mcp_result("format_deck", {{"path", "decks/run/water_column_2d.k"}});
    CHECK(shipped["changed"] == false);  // the shipped decks are formatted (ctest shipped-decks-formatted)
}

TEST_CASE("mcp explain_rule: the rule's page; an unknown rule is a tool error with a suggestion") {
    const json answer = mcp_call("explain_rule", {{"rule", "SPH030"}});
    CHECK(answer["result"]["structuredContent"]["code"] == "SPH030");
    CHECK(text_of(answer).find("SPH030") == 0);
    const json unknown = mcp_call("explain_rule", {{"rule", "SPH03"}});
    CHECK(unknown["result"]["isError"] == true);
    CHECK(text_of(unknown).find("did you mean") != std::string::npos);
}

TEST_CASE("mcp keyword_layout: cards and fields with columns; an unknown keyword is a tool error") {
    const json result = mcp_result("keyword_layout", {{"name", "control_sph"}});
    CHECK(result["keyword"] == "*CONTROL_SPH");
    const json& first = result["cards"][0]["fields"][0];
    CHECK(first["name"] == "NCBS");
    CHECK(first["columns"] == json::array({1, 10}));
    const json wide = mcp_result("keyword_layout", {{"name", "*CONTROL_SPH"}, {"format", "long"}});
    CHECK(wide["cards"][0]["fields"][0]["columns"] == json::array({1, 20}));
    CHECK(mcp_call("keyword_layout", {{"name", "*CONTROL_SPHH"}})["result"]["isError"] == true);
}

TEST_CASE("mcp smoothing_preview: per-part h0, spacing and neighbours of a shipped deck") {
    const json result = mcp_result("smoothing_preview", {{"path", "decks/run/water_column_2d.k"}});
    CHECK(result["dimension"] == 2);
    REQUIRE(!result["parts"].empty());
    const json& part = result["parts"][0];
    CHECK(part["particles"].get<int>() > 0);
    CHECK(part["h0"].get<double>() > 0);
    CHECK(part["spacing"].get<double>() > 0);
    CHECK(part["neighbours"]["median"].get<double>() > 0);
    const json none = mcp_call("smoothing_preview", {{"text", lower_case_keyword}});
    CHECK(none["result"]["isError"] == true);
    CHECK(mcp_call("smoothing_preview", {{"path", mistakes}, {"ini", 7}})["error"]["code"] == -32602);
}

TEST_CASE("mcp diff_decks: a deck against itself and against another") {
    const json same = mcp_result("diff_decks", {{"before", mistakes}, {"after", mistakes}});
    CHECK(same["equal"] == true);
    const json other = mcp_result("diff_decks", {{"before", mistakes}, {"after", "decks/run/water_column_2d.k"}});
    CHECK(other["equal"] == false);
    CHECK(!other["keywords"].empty());
    CHECK(mcp_call("diff_decks", {{"before", mistakes}, {"after", "/etc/hostname"}})["error"]["code"] == -32602);
}
}  // namespace test_mcp_tools_cpp
