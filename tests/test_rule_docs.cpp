// `sphdeck rule` / `sphdeck rules` and docs/rules.md, which is generated from the registry.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "lint/rule_pages.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

using namespace sphdeck;

namespace {
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("rules: docs/rules.md is the generated text") {
    std::ifstream in(SPHDECK_SOURCE_DIR "/docs/rules.md", std::ios::binary);
    REQUIRE(in.good());
    std::ostringstream text;
    text << in.rdbuf();
    const bool same = text.str() == lint::render_rules_markdown();
    if (!same) MESSAGE("regenerate it: build/sphdeck rules --format markdown > docs/rules.md");
    CHECK(same);
}

TEST_CASE("rules: the page of one rule has every section") {
    const lint::RuleInfo* rule = lint::find_rule("SPH030");
    REQUIRE(rule != nullptr);
    const std::string page = lint::render_rule_page(*rule);
    CHECK(page.starts_with("SPH030 iavis-solid-in-2d (error)\n"));
    std::size_t last = 0;
    for (const char* section : {"What it does\n", "Why it matters\n", "How to fix\n", "Example\n", "Triggers the rule:\n",
                                "Fixed:\n", "#sph030"}) {
        INFO(section);
        const std::size_t at = page.find(section);
        REQUIRE(at != std::string::npos);
        CHECK(at > last);  // in this order
        last = at;
    }
    CHECK(contains(page, "    *CONTROL_SPH\n"));  // the example cards, indented
    std::istringstream lines(page);
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("    ") && !line.starts_with("http")) CHECK(line.size() <= 80);  // prose is wrapped
    }
}

TEST_CASE("rules: markdown has one anchored section per rule and escapes markup") {
    const std::string md = lint::render_rules_markdown();
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        std::string anchor(rule.code);
        for (char& c : anchor) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        CHECK(contains(md, "<a id=\"" + anchor + "\"></a>\n\n## " + std::string(rule.code) + " " + std::string(rule.name)));
        CHECK(contains(md, "| [" + std::string(rule.code) + "](#" + anchor + ") |"));
        CHECK(lint::rule_url(rule).ends_with("docs/rules.md#" + anchor));
    }
    const std::string body = lint::rule_markdown_body(*lint::find_rule("REF003"));
    CHECK(contains(body, "\\*PART"));  // '*' would otherwise start emphasis
    CHECK(contains(body, "```text\n*PART"));  // but not inside the example
}

TEST_CASE("rules: the table lists every rule with its severity") {
    const std::string table = lint::render_rules_table();
    CHECK(table.starts_with("CODE "));
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        CHECK(contains(table, std::string(rule.code) + " "));
        CHECK(contains(table, std::string(rule.name)));
    }
}

TEST_CASE("rules: the commands find rules by code or name and suggest close ones") {
    test::TempDir dir;
    test::Run r = test::run_sphdeck(dir, "rule iavis-solid-in-2d");
    CHECK(r.exit_code == 0);
    CHECK(r.out.starts_with("SPH030 iavis-solid-in-2d (error)"));
    CHECK(test::run_sphdeck(dir, "rule dk027").out.starts_with("DK027 data-before-keyword (warning)"));
    r = test::run_sphdeck(dir, "rule SPH3O");
    CHECK(r.exit_code == 2);
    CHECK(contains(r.err, "unknown rule 'SPH3O'; did you mean 'SPH030'"));
    r = test::run_sphdeck(dir, "rules --format markdown");
    CHECK(r.exit_code == 0);
    CHECK(r.out == lint::render_rules_markdown());
    CHECK(test::run_sphdeck(dir, "rules").out == lint::render_rules_table());
}
