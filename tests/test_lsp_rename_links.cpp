// The editor server's rename, document links, workspace symbols and code lens (issue 45 items 4-5),
// through its JSON-RPC as a client sends them, on a deck whose section lies in an include.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "engine/id_rename.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"
#include "lsp_session.hpp"
#include "tests/lsp_radioss_deck.hpp"

namespace test_lsp_rename_links_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
namespace fs = std::filesystem;

namespace {

// main.k: a part whose section 3 is defined in section.k (an *INCLUDE), two particles of part 1.
const std::string kMain =
    "*KEYWORD\n"
    "*INCLUDE\n"
    "section.k\n"
    "*PART\n"
    "water\n"
    "$#     pid     secid       mid     eosid\n"
    "         1         3         5\n"
    "*MAT_NULL\n"
    "         5    1000.0\n"
    "*NODE\n"
    "       1           0.010           0.030             0.0\n"
    "       2           0.030           0.030             0.0\n"
    "*ELEMENT_SPH\n"
    "       1       1   0.001\n"
    "       2       1   0.001\n"
    "*END\n";
const std::string kSection =
    "*KEYWORD\n"
    "*SECTION_SPH\n"
    "         3       1.2\n"
    "*SECTION_SPH\n"
    "4,1.3\n"
    "*END\n";

struct Files {
    fs::path dir, main, section;
    explicit Files(const std::string& name) : dir(fs::temp_directory_path() / name) {
        fs::remove_all(dir);
        fs::create_directories(dir);
        main = dir / "main.k";
        section = dir / "section.k";
        std::ofstream(main, std::ios::binary) << kMain;
        std::ofstream(section, std::ios::binary) << kSection;
    }
    ~Files() { fs::remove_all(dir); }
};

nlohmann::json at(std::uint32_t line, std::uint32_t character) { return {{"line", line}, {"character", character}}; }

// The server's answers to an open of main.k and then `requests` (ids from 2).
test::Served serve_on(const Files& files, const std::vector<nlohmann::json>& requests) {
    std::vector<nlohmann::json> messages{test::initialize_request(), test::notify("initialized"),
                                         test::did_open(lsp::uri_from_path(files.main), kMain)};
    messages.insert(messages.end(), requests.begin(), requests.end());
    messages.push_back(test::request(99, "shutdown"));
    messages.push_back(test::notify("exit"));
    return test::serve(messages);
}

nlohmann::json rename_request(int id, const Files& files, nlohmann::json position, const std::string& name) {
    return test::request(id, "textDocument/rename",
                         {{"textDocument", {{"uri", lsp::uri_from_path(files.main)}}},
                          {"position", std::move(position)},
                          {"newName", name}});
}

// `text` with LSP TextEdits applied (ASCII text: characters are bytes).
std::string apply(std::string text, nlohmann::json edits) {
    auto offset = [&](const nlohmann::json& p) {
        std::size_t at = 0;
        for (int line = 0; line < p["line"].get<int>(); ++line) at = text.find('\n', at) + 1;
        return at + p["character"].get<std::size_t>();
    };
    std::vector<nlohmann::json> sorted(edits.begin(), edits.end());
    std::sort(sorted.begin(), sorted.end(), [&](const nlohmann::json& a, const nlohmann::json& b) {
        return offset(a["range"]["start"]) > offset(b["range"]["start"]);
    });
    for (const auto& e : sorted) {
        const std::size_t from = offset(e["range"]["start"]), to = offset(e["range"]["end"]);
        text.replace(from, to - from, e["newText"].get<std::string>());
    }
    return text;
}

std::vector<std::string> findings(const engine::CheckResult& result) {
    std::vector<std::string> out;
    for (const auto& d : result.diagnostics) out.push_back(d.code + ":" + std::to_string(d.span.line));
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("lsp rename: a section id across an include, byte-exact, the deck reads the same") {
    const Files files("sphdeck_lsp_rename_include");
    const auto before = engine::check_file(files.main.string());
    const auto served = serve_on(files, {
                                            test::request(2, "textDocument/prepareRename",
                                                          {{"textDocument", {{"uri", lsp::uri_from_path(files.main)}}},
                                                           {"position", at(6, 19)}}),
                                            rename_request(3, files, at(6, 19), "42"),
                                            test::request(4, "textDocument/references",
                                                          {{"textDocument", {{"uri", lsp::uri_from_path(files.main)}}},
                                                           {"position", at(6, 19)},
                                                           {"context", {{"includeDeclaration", true}}}}),
                                        });
    const auto prepared = served.answer(2)["result"];
    CHECK(prepared["placeholder"] == "3");
    CHECK(prepared["range"]["start"] == at(6, 19));
    CHECK(prepared["range"]["end"] == at(6, 20));
    const auto changes = served.answer(3)["result"]["changes"];
    REQUIRE(changes.size() == 2);
    const std::string renamed_main = apply(kMain, changes[lsp::uri_from_path(files.main)]);
    const std::string renamed_section = apply(kSection, changes[lsp::uri_from_path(files.section)]);
    // Only the id fields changed, right-aligned in their 10 columns.
    std::string expected_main = kMain;
    expected_main.replace(expected_main.find("         1         3"), 20, "         1        42");
    CHECK(renamed_main == expected_main);
    std::string expected_section = kSection;
    expected_section.replace(expected_section.find("         3       1.2"), 10, "        42");
    CHECK(renamed_section == expected_section);
    // The references count of the id is unchanged, and the renamed deck reads the same.
    const std::size_t references = served.answer(4)["result"].size();
    CHECK(references == 2);
    std::ofstream(files.main, std::ios::binary) << renamed_main;
    std::ofstream(files.section, std::ios::binary) << renamed_section;
    auto after = engine::check_file(files.main.string());
    CHECK(findings(after) == findings(before));
    CHECK(after.model.parts.size() == before.model.parts.size());
    lsp::CheckedDeck deck{files.main, std::move(after)};
    auto refs = lsp::answer_feature("textDocument/references", deck, 0,
                                    {{"position", at(6, 19)}, {"context", {{"includeDeclaration", true}}}});
    CHECK(refs.result.size() == references);
}

TEST_CASE("lsp rename: a part id in its particles; free format; refusals say why") {
    const Files files("sphdeck_lsp_rename_refused");
    const auto served =
        serve_on(files, {
                            rename_request(2, files, at(6, 9), "7"),  // PID 1: the *PART and both particles
                            rename_request(3, files, at(6, 9),
                                           "123456789"),  // 9 digits: wider than *ELEMENT_SPH's 8-column PID
                            rename_request(4, files, at(6, 19), "4"),   // section 4 exists
                            rename_request(5, files, at(6, 19), "x1"),  // not an id
                            rename_request(6, files, at(5, 3), "5"),    // a comment: nothing to rename
                        });
    const auto changes = served.answer(2)["result"]["changes"][lsp::uri_from_path(files.main)];
    REQUIRE(changes.size() == 3);
    std::string expected = kMain;
    expected.replace(expected.find("         1         3"), 10, "         7");
    expected.replace(expected.find("       1       1   0.001"), 16, "       1       7");
    expected.replace(expected.find("       2       1   0.001"), 16, "       2       7");
    CHECK(apply(kMain, changes) == expected);
    const auto too_wide = served.answer(3);
    REQUIRE(too_wide.contains("error"));
    CHECK(too_wide["error"]["code"] == lsp::error_code::request_failed);
    CHECK(too_wide["error"]["message"].get<std::string>().find("does not fit the 8-column field PID") !=
          std::string::npos);
    const auto exists = served.answer(4);
    REQUIRE(exists.contains("error"));
    CHECK(exists["error"]["message"].get<std::string>().find("SECTION 4 already exists") != std::string::npos);
    CHECK(served.answer(5)["error"]["message"].get<std::string>().find("'x1' is not an id") != std::string::npos);
    CHECK(served.answer(6).contains("error"));

    // Section 4 is written in free format: its id is replaced where it stands.
    lsp::CheckedDeck deck{files.main, engine::check_file(files.main.string())};
    auto renamed =
        lsp::answer_feature("textDocument/rename", deck, 1, {{"position", at(4, 0)}, {"newName", "1234567890"}});
    const auto edits = renamed.result["changes"][lsp::uri_from_path(files.section)];
    REQUIRE(edits.size() == 1);
    CHECK(apply(kSection, edits).find("\n1234567890,1.3\n") != std::string::npos);
    CHECK_THROWS_WITH_AS(lsp::answer_feature("textDocument/rename", deck, 1,
                                             {{"position", at(4, 0)}, {"newName", "12345678901"}}),
                         doctest::Contains("does not fit the 10-column field SECID"), lsp::FeatureError);
}

TEST_CASE("lsp rename: a *PARAMETER name and its &uses; a Radioss property id in headers and fields") {
    const std::string deck_text =
        "*KEYWORD\n*PARAMETER\nR rho        1000.0\n*PART\nwater\n         1         3         5\n"
        "*MAT_NULL\n         5      &rho\n*SECTION_SPH\n         3       1.2\n*END\n";
    lsp::CheckedDeck deck{"main.k", engine::check_buffer(deck_text, "main.k", {}, grammar::DeckFormat::LsDyna)};
    auto renamed = lsp::answer_feature("textDocument/rename", deck, 0, {{"position", at(7, 17)}, {"newName", "dens"}});
    const auto edits = renamed.result["changes"].begin().value();
    REQUIRE(edits.size() == 2);
    const std::string text = apply(deck_text, edits);
    CHECK(text.find("R dens       1000.0") != std::string::npos);
    CHECK(text.find("         5     &dens\n") != std::string::npos);  // still ends at column 20

    // engine::replace_in_field keeps a left-aligned value left, a right-aligned one right.
    auto r = engine::replace_in_field("1         2", 0, 10, 0, 1, "42", false);
    CHECK(r.start == 0);
    CHECK(r.end == 2);
    CHECK(r.text == "42");
    r = engine::replace_in_field("        12", 0, 10, 8, 10, "7", false);
    CHECK(std::string("        12").replace(r.start, r.end - r.start, r.text) == "         7");
}

TEST_CASE("lsp document links, workspace symbols and code lens") {
    const Files files("sphdeck_lsp_links_symbols");
    const std::string main_uri = lsp::uri_from_path(files.main);
    const auto served =
        serve_on(files, {
                            test::request(2, "textDocument/documentLink", {{"textDocument", {{"uri", main_uri}}}}),
                            test::request(3, "workspace/symbol", {{"query", "sec"}}),
                            test::request(4, "workspace/symbol", {{"query", "pt1wat"}}),
                            test::request(5, "textDocument/codeLens", {{"textDocument", {{"uri", main_uri}}}}),
                            test::request(6, "textDocument/codeLens",
                                          {{"textDocument", {{"uri", lsp::uri_from_path(files.section)}}}}),
                        });
    const auto initialize = served.answer(1)["result"]["capabilities"];
    CHECK(initialize["renameProvider"]["prepareProvider"] == true);
    CHECK(initialize.contains("documentLinkProvider"));
    CHECK(initialize.contains("codeLensProvider"));
    CHECK(initialize["workspaceSymbolProvider"] == true);

    const auto links = served.answer(2)["result"];
    REQUIRE(links.size() == 1);
    CHECK(links[0]["target"] == lsp::uri_from_path(files.section));
    CHECK(links[0]["range"]["start"] == at(2, 0));
    CHECK(links[0]["range"]["end"] == at(2, 9));

    const auto sections = served.answer(3)["result"];
    REQUIRE(sections.size() == 2);
    CHECK(sections[0]["name"] == "SECTION 3");
    CHECK(sections[0]["location"]["uri"] == lsp::uri_from_path(files.section));
    const auto part = served.answer(4)["result"];
    REQUIRE(part.size() == 1);
    CHECK(part[0]["name"] == "PART 1 water");
    CHECK(part[0]["location"]["range"]["start"] == at(6, 9));

    std::vector<std::string> titles;
    const auto main_lenses = served.answer(5)["result"];
    for (const auto& lens : main_lenses) titles.push_back(lens["command"]["title"]);
    CHECK(titles == std::vector<std::string>{"used by 0 and 2 particles", "used by 1"});  // PART 1, MAT 5
    titles.clear();
    const auto section_lenses = served.answer(6)["result"];
    for (const auto& lens : section_lenses) titles.push_back(lens["command"]["title"]);
    CHECK(titles == std::vector<std::string>{"used by 1", "used by 0"});  // SECTION 3, 4

    CHECK(lsp::symbol_matches("", "PART 1"));
    CHECK(lsp::symbol_matches("p 1", "PART 1"));
    CHECK_FALSE(lsp::symbol_matches("mat", "PART 1"));
}

TEST_CASE("lsp rename on an OpenRadioss deck: a /PROP id in its header and a /PART's prop_ID; nodes refused") {
    const std::string rad{test::lsp_radioss_deck};
    lsp::CheckedDeck deck{"lsp_0000.rad", engine::check_buffer(rad, "lsp_0000.rad", {}, std::nullopt)};
    REQUIRE(deck.result.model.radioss);
    auto renamed = lsp::answer_feature("textDocument/rename", deck, 0, {{"position", at(9, 9)}, {"newName", "17"}});
    const auto edits = renamed.result["changes"].begin().value();
    REQUIRE(edits.size() == 2);
    const std::string text = apply(rad, edits);
    CHECK(text.find("\n        17         3         0\n") != std::string::npos);
    CHECK(text.find("\n/PROP/SPH/17\n") != std::string::npos);
    CHECK_THROWS_WITH_AS(lsp::answer_feature("textDocument/prepareRename", deck, 0, {{"position", at(27, 8)}}),
                         doctest::Contains("Radioss node"), lsp::FeatureError);
    // Part 2 is named by /SPHCEL/2's header.
    auto lenses = lsp::answer_feature("textDocument/codeLens", deck, 0, nlohmann::json::object()).result;
    REQUIRE(lenses.size() == 3);
    CHECK(lenses[0]["command"]["title"] == "used by 1");
}
}  // namespace test_lsp_rename_links_cpp
