// The machine-readable formats of `sphdeck check` (JSON, SARIF, GitHub annotations), its streams
// and its exit codes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "diag/render_github.hpp"
#include "diag/render_json.hpp"
#include "diag/render_sarif.hpp"
#include "engine/check.hpp"
#include "lint/registry.hpp"
#include "lint/rule_catalog.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_output_formats_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using nlohmann::json;

namespace {

// DK003 on line 4, columns 1-10 of the only card.
const std::string kBadReal = "*KEYWORD\n*CONTROL_TERMINATION\n$#  endtim\nabc\n*END\n";

json json_of(const engine::CheckResult& r, const diag::RunSummary& summary = {}) {
    auto report = diag::make_json_report(lint::rule_catalog());
    report->add(r.deck.sources, r.diagnostics);
    return json::parse(report->finish(summary));
}

// A synthetic finding's fixes: a safe realignment (a replacement and an insertion on line 4) and an
// unsafe did-you-mean on line 2.
diag::Diagnostic with_fix(diag::Diagnostic d) {
    d.fixes.push_back({"move the value back into its field",
                       true,
                       {{grammar::Span{0, 4, 1, 4}, "1.0"}, {grammar::Span{0, 4, 11, 11}, "   "}}});
    d.fixes.push_back({"did you mean *CONTROL_TERMINATION?", false, {{grammar::Span{0, 2, 2, 8}, "CONTROL"}}});
    return d;
}

}  // namespace

TEST_CASE("output: json and sarif carry a finding's fixes") {
    engine::CheckResult r = engine::check_buffer(kBadReal, "main.k");
    REQUIRE(r.diagnostics.size() == 1);
    r.diagnostics[0] = with_fix(r.diagnostics[0]);
    const json doc = json_of(r);
    const json& fixes = doc["diagnostics"][0]["fixes"];
    REQUIRE(fixes.size() == 2);
    CHECK(fixes[0]["description"] == "move the value back into its field");
    CHECK(fixes[0]["safe"] == true);
    CHECK(fixes[0]["edits"][0] ==
          json({{"file", "main.k"}, {"line", 4}, {"column", 1}, {"end_column", 4}, {"replacement", "1.0"}}));
    CHECK(fixes[0]["edits"][1]["column"] == 11);
    CHECK(fixes[0]["edits"][1]["end_column"] == 11);  // an insertion
    CHECK(fixes[1]["safe"] == false);
    CHECK(fixes[1]["edits"][0]["replacement"] == "CONTROL");

    auto report = diag::make_sarif_report(lint::rule_catalog());
    report->add(r.deck.sources, r.diagnostics);
    const json log = json::parse(report->finish({}));
    const json& sarif = log["runs"][0]["results"][0]["fixes"];
    REQUIRE(sarif.size() == 2);
    CHECK(sarif[0]["description"]["text"] == "move the value back into its field");
    const json& change = sarif[0]["artifactChanges"][0];
    CHECK(change["artifactLocation"]["uri"] == "main.k");
    REQUIRE(change["replacements"].size() == 2);
    CHECK(change["replacements"][0]["deletedRegion"] == json({{"startLine", 4}, {"startColumn", 1}, {"endColumn", 4}}));
    CHECK(change["replacements"][0]["insertedContent"]["text"] == "1.0");
    CHECK(change["replacements"][1]["deletedRegion"]["endColumn"] == 11);

    engine::CheckResult plain = engine::check_buffer(kBadReal, "main.k");
    CHECK(json_of(plain)["diagnostics"][0]["fixes"] == json::array());  // always present in JSON
}

TEST_CASE("output: json carries code, name, location, notes and summary") {
    engine::CheckResult r = engine::check_buffer(kBadReal, "main.k");
    r.diagnostics.push_back({"DK018", diag::Severity::Warning, "deck-wide", grammar::Span{}, {{grammar::Span{}, "n"}}});
    diag::RunSummary summary;
    summary.files = 1;
    summary.counts.errors = 1;
    summary.seconds = 0.5;
    const json doc = json_of(r, summary);
    CHECK(doc["version"] == SPHDECK_VERSION);
    REQUIRE(doc["diagnostics"].size() == 2);
    const json& d = doc["diagnostics"][0];
    CHECK(d["code"] == "DK003");
    CHECK(d["name"] == "bad-real");
    CHECK(d["severity"] == "error");
    CHECK(d["file"] == "main.k");
    CHECK(d["line"] == 4);
    CHECK(d["column"] == 1);
    CHECK(d["end_column"] == 11);
    CHECK(d["notes"].is_array());
    CHECK(d["include_chain"] == json::array());
    CHECK(d["url"].get<std::string>().ends_with("docs/rules.md#dk003"));

    const json& wide = doc["diagnostics"][1];  // no location: file null, zeros
    CHECK(wide["file"].is_null());
    CHECK(wide["line"] == 0);
    CHECK(wide["notes"][0]["file"].is_null());
    CHECK(wide["notes"][0]["message"] == "n");

    const json& s = doc["summary"];
    for (const char* key : {"files", "keywords", "cards", "particles", "errors", "warnings", "infos", "seconds"})
        CHECK(s.contains(key));
    CHECK(s["files"] == 1);
    CHECK(s["seconds"] == 0.5);
}

TEST_CASE("output: json names the include chain, main deck first") {
    test::TempDir dir;
    dir.write("parts.k", "*CONTROL_TERMINATION\nabc\n");
    const std::string main = dir.write("main.k", "*KEYWORD\n*INCLUDE\nparts.k\n*END\n");
    const json doc = json_of(engine::check_file(main));
    const json* found = nullptr;
    for (const json& d : doc["diagnostics"])
        if (d["code"] == "DK003") found = &d;
    REQUIRE(found != nullptr);
    CHECK((*found)["file"].get<std::string>().ends_with("parts.k"));
    REQUIRE((*found)["include_chain"].size() == 1);
    CHECK((*found)["include_chain"][0]["file"] == main);
    CHECK((*found)["include_chain"][0]["line"] == 3);  // the line naming parts.k
}

TEST_CASE("output: json survives bytes that are not UTF-8") {
    engine::CheckResult r = engine::check_buffer(kBadReal, "main.k");
    r.diagnostics[0].message = "bad \xff byte";
    CHECK(json_of(r)["diagnostics"][0]["message"] == "bad \xEF\xBF\xBD byte");
}

TEST_CASE("output: sarif lists every rule and maps results") {
    engine::CheckResult r = engine::check_buffer(kBadReal, "main.k");
    r.diagnostics[0].notes.push_back({grammar::Span{0, 2, 1, 21}, "keyword here"});
    auto report = diag::make_sarif_report(lint::rule_catalog());
    report->add(r.deck.sources, r.diagnostics);
    const json log = json::parse(report->finish({}));
    CHECK(log["version"] == "2.1.0");
    const json& run = log["runs"][0];
    const json& driver = run["tool"]["driver"];
    CHECK(driver["name"] == "sphdeck");
    CHECK(driver["version"] == SPHDECK_VERSION);
    REQUIRE(driver["rules"].size() == lint::all_rules().size());
    const json& result = run["results"][0];
    CHECK(result["ruleId"] == "DK003");
    const json& rule = driver["rules"][result["ruleIndex"].get<std::size_t>()];
    CHECK(rule["id"] == "DK003");
    CHECK(rule["defaultConfiguration"]["level"] == "error");
    CHECK(rule["helpUri"].get<std::string>().ends_with("#dk003"));
    CHECK(rule["help"]["markdown"].get<std::string>().find("### How to fix") != std::string::npos);
    const json& location = result["locations"][0]["physicalLocation"];
    CHECK(location["artifactLocation"]["uri"] == "main.k");
    CHECK(location["artifactLocation"]["uriBaseId"] == "%SRCROOT%");
    CHECK(location["region"] == json({{"startLine", 4}, {"startColumn", 1}, {"endColumn", 11}}));
    CHECK(result["relatedLocations"][0]["message"]["text"] == "keyword here");
    for (const json& rule_entry : driver["rules"]) {
        std::string level = rule_entry["defaultConfiguration"]["level"];
        CHECK((level == "error" || level == "warning" || level == "note"));
    }
}

TEST_CASE("output: sarif uris are relative below the working directory, else file URIs") {
    grammar::SourceFile below;
    below.path = (std::filesystem::current_path() / "decks" / "a b.k").string();
    bool relative = false;
    CHECK(diag::sarif_uri(below, relative) == "decks/a%20b.k");
    CHECK(relative);
    grammar::SourceFile elsewhere;
    elsewhere.path = (std::filesystem::current_path().root_path() / "x%y" / "c.k").string();
    if (std::filesystem::current_path() != std::filesystem::current_path().root_path()) {
        CHECK(diag::sarif_uri(elsewhere, relative) == "file:///x%25y/c.k");
        CHECK_FALSE(relative);
    }
}

TEST_CASE("output: sarif validates against the SARIF 2.1.0 schema") {
    const std::string schema = SPHDECK_SOURCE_DIR "/../shared/schemas/sarif-schema-2.1.0.json";
    if (!std::filesystem::exists(schema) || std::system("python3 -c 'import jsonschema' > /dev/null 2>&1") != 0) {
        MESSAGE("python3-jsonschema or " << schema << " missing: skipped");
        return;
    }
    test::TempDir dir;
    dir.write("inc/part.k", "*CONTROL_TERMINATION\nabc\n*FOO\n");
    const std::string main = dir.write("main.k", "units\n*KEYWORD\n*INCLUDE\ninc/part.k\n*INCLUDE\nmissing.k\n*END\n");
    engine::CheckResult r = engine::check_file(main);
    r.diagnostics.push_back({"XX999", diag::Severity::Info, "unregistered", grammar::Span{}, {}});
    r.diagnostics.push_back(with_fix({"DK003", diag::Severity::Error, "fixable", grammar::Span{0, 2, 1, 6}, {}}));
    auto report = diag::make_sarif_report(lint::rule_catalog());
    report->add(r.deck.sources, r.diagnostics);
    const std::string log = dir.write("out.sarif", report->finish({}));
    auto validates = [&](const std::string& path, const char* redirect) {
        const std::string command =
            "python3 -c 'import json, sys, jsonschema; "
            "jsonschema.Draft4Validator(json.load(open(sys.argv[1]))).validate(json.load(open(sys.argv[2])))' '" +
            schema + "' '" + path + "'" + redirect;
        return std::system(command.c_str()) == 0;
    };
    CHECK(validates(log, ""));
    // A log without `tool` must fail: the check really validates.
    json broken = json::parse(report->finish({}));
    broken["runs"][0].erase("tool");
    CHECK_FALSE(validates(dir.write("bad.sarif", broken.dump()), " 2> /dev/null"));
}

TEST_CASE("output: github annotations escape data and properties") {
    CHECK(diag::github_escape_data("50% a:b,c\r\nnext") == "50%25 a:b,c%0D%0Anext");
    CHECK(diag::github_escape_property("50% a:b,c\r\n") == "50%25 a%3Ab%2Cc%0D%0A");
    grammar::SourceMap map;
    grammar::SourceFile f;
    f.path = f.display_name = "dir,x/a:b.k";
    f.text = std::string("*KEYWORD\nabc\n");
    const auto id = map.add(std::move(f));
    diag::Diagnostic d{"DK003",
                       diag::Severity::Warning,
                       "100% wrong\nreally",
                       grammar::Span{id, 2, 1, 4},
                       {{grammar::Span{id, 1, 1, 9}, "see"}}};
    CHECK(diag::render_github(d, map) ==
          "::warning file=dir%2Cx/a%3Ab.k,line=2,col=1,endColumn=4,title=DK003::100%25 wrong%0Areally%0Anote: "
          "dir,x/a:b.k:1:1: see\n");
    d.severity = diag::Severity::Info;
    d.span = grammar::Span{};
    d.notes.clear();
    CHECK(diag::render_github(d, map) == "::notice title=DK003::100%25 wrong%0Areally\n");
    d.severity = diag::Severity::Error;
    CHECK(diag::render_github(d, map).starts_with("::error "));
}

TEST_CASE("output: streams and exit codes of the binary") {
    test::TempDir dir;
    dir.write("clean.k", "*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*END\n");
    dir.write("bad.k", kBadReal);
    dir.write("warn.k", "units: mm\n*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*END\n");  // DK027 only
    const std::string only = " --no-config --select DK003,DK027 ";
    CHECK(test::run_sphdeck(dir, "check" + only + "clean.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "check" + only + "bad.k").exit_code == 1);
    CHECK(test::run_sphdeck(dir, "check" + only + "warn.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "check" + only + "--fail-on warning warn.k").exit_code == 1);
    CHECK(test::run_sphdeck(dir, "check" + only + "--fail-on never bad.k").exit_code == 0);
    CHECK(test::run_sphdeck(dir, "check" + only + "missing.k").exit_code == 2);
    CHECK(test::run_sphdeck(dir, "check" + only + "--fail-on sometimes bad.k").exit_code == 2);
    CHECK(test::run_sphdeck(dir, "check --select SPH999 bad.k").exit_code == 2);
    CHECK(test::run_sphdeck(dir, "check -I inc --select DK003 bad.k --ignore DK027").exit_code == 1);  // lists end

    // Machine formats keep stdout parseable; the summary line goes to stderr.
    for (const char* format : {"json", "sarif"}) {
        const test::Run r = test::run_sphdeck(dir, "check" + only + "--format " + format + " bad.k clean.k");
        INFO(r.out, r.err);
        CHECK(r.exit_code == 1);
        CHECK(json::accept(r.out));
        CHECK(r.err.starts_with("checked 2 file(s)"));
    }
    const test::Run github = test::run_sphdeck(dir, "check" + only + "--format github bad.k");
    CHECK(github.out.starts_with("::error file=bad.k,line=4,col=1,endColumn=11,title=DK003::"));
    CHECK(github.err.starts_with("checked 1 file(s)"));
    const test::Run full = test::run_sphdeck(dir, "check" + only + "bad.k");
    CHECK(full.out.find("checked 1 file(s)") != std::string::npos);
}

TEST_CASE("output: every format carries every finding; text folds, every summary counts all") {
    test::TempDir dir;
    std::string deck = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= 30; ++i) deck += std::to_string(i) + ",abc,0.0,0.0\n";  // DK003 on 30 lines of one block
    deck += "*END\n";
    dir.write("flood.k", deck);
    const std::string only = " --no-config --select DK003 ";
    const test::Run js = test::run_sphdeck(dir, "check" + only + "--format json flood.k");
    INFO(js.err);
    const json doc = json::parse(js.out);
    CHECK(doc["diagnostics"].size() == 30);
    CHECK(doc["summary"]["errors"] == 30);
    CHECK(js.err.find("30 error(s)") != std::string::npos);
    const json sarif = json::parse(test::run_sphdeck(dir, "check" + only + "--format sarif flood.k").out);
    CHECK(sarif["runs"][0]["results"].size() == 30);
    const test::Run gh = test::run_sphdeck(dir, "check" + only + "--format github flood.k");
    CHECK(std::count(gh.out.begin(), gh.out.end(), '\n') == 30);

    // Text: five findings, then one line for the other 25 of the block; the summary counts all 30.
    const test::Run concise = test::run_sphdeck(dir, "check" + only + "--format concise flood.k");
    INFO(concise.out);
    std::size_t shown = 0;
    for (std::size_t at = concise.out.find("[DK003]"); at != std::string::npos;
         at = concise.out.find("[DK003]", at + 1))
        ++shown;
    CHECK(shown == 6);  // five findings and the fold line, which keeps the concise pattern
    CHECK(concise.out.find("flood.k:8:3: note: 25 more DK003 finding(s) on the lines of this *NODE block: lines 8, 9, "
                           "10, 11, 12, ... (--max-per-code 0 shows all) [DK003]") != std::string::npos);
    const std::regex concise_line(R"(^[^:]+:\d+:\d+: (error|warning|info|note): .* \[[A-Z]+[0-9]+\]$)");
    std::istringstream concise_lines(concise.out);
    for (std::string line; std::getline(concise_lines, line);)
        CHECK_MESSAGE(std::regex_match(line, concise_line), line);
    // A code folded across the deck (--max-per-code) points at its first finding not shown.
    const test::Run capped = test::run_sphdeck(dir, "check" + only + "--format concise --max-per-code 2 flood.k");
    std::istringstream capped_lines(capped.out);
    for (std::string line; std::getline(capped_lines, line);) CHECK_MESSAGE(std::regex_match(line, concise_line), line);
    CHECK(capped.out.find(": note: 28 more DK003 finding(s) not shown (--max-per-code 0 shows all) [DK003]") !=
          std::string::npos);
    CHECK(concise.err.find("30 error(s)") != std::string::npos);
    const test::Run all = test::run_sphdeck(dir, "check" + only + "--format concise --max-per-code 0 flood.k");
    CHECK(std::count(all.out.begin(), all.out.end(), '\n') == 30);
    const test::Run full = test::run_sphdeck(dir, "check" + only + "flood.k");
    CHECK(full.out.find("30 error(s)") != std::string::npos);
    CHECK(full.out.find("25 more DK003 finding(s)") != std::string::npos);
}
}  // namespace test_output_formats_cpp
