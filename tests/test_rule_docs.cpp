// `sphdeck rule` / `sphdeck rules`, docs/rules.md (generated from the registry), and the pages
// docs/rules/CODE.md the documentation is read from.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "lint/rule_docs.hpp"
#include "lint/rule_pages.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_rule_docs_cpp {  // each test file's names stay its own in a unity batch

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
    for (const char* section : {"What it does\n", "Why it matters\n", "How to fix\n", "Example\n",
                                "Triggers the rule:\n", "Fixed:\n", "#sph030"}) {
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
        CHECK(contains(md,
                       "<a id=\"" + anchor + "\"></a>\n\n## " + std::string(rule.code) + " " + std::string(rule.name)));
        CHECK(contains(md, "| [" + std::string(rule.code) + "](#" + anchor + ") |"));
        CHECK(lint::rule_url(rule).ends_with("docs/rules.md#" + anchor));
    }
    const std::string body = lint::rule_markdown_body(*lint::find_rule("REF003"));
    CHECK(contains(body, "\\*PART"));         // '*' would otherwise start emphasis
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

TEST_CASE("rules: every registry row has a documentation page and every page a row") {
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        const lint::RuleDocPage* page = lint::find_rule_doc_page(rule.code);
        if (page == nullptr) {
            FAIL_CHECK("no page: write docs/rules/" << rule.code << ".md");
            continue;
        }
        CHECK(page->name == rule.name);
        CHECK(!rule.doc.what.empty());
        CHECK(!rule.doc.why.empty());
        CHECK(!rule.doc.fix.empty());
        CHECK(!rule.doc.before.empty());
        CHECK(!rule.doc.after.empty());
    }
    for (const lint::RuleDocPage& page : lint::rule_doc_pages()) {
        INFO(page.file);
        CHECK_MESSAGE(lint::find_rule(page.code) != nullptr, "no registry row in lint/registry_rows.cpp");
        for (const std::string& problem : page.problems) FAIL_CHECK(problem);
    }
    CHECK(lint::rule_doc_pages().size() == lint::all_rules().size());
}

TEST_CASE("rules: a page reads back as plain text") {
    const lint::RuleDocPage page = lint::parse_rule_doc_page("docs/rules/XX001.md",
                                                             "# XX001 some-rule\r\n"
                                                             "\n"
                                                             "## What it does\n"
                                                             "\n"
                                                             "Reports \\*PART cards\n"
                                                             "wrapped over `a\\*b` lines.\n"
                                                             "\n"
                                                             "## Why it matters\n"
                                                             "Because.\n"
                                                             "## How to fix\n"
                                                             "Fix it.\n"
                                                             "## Before\n"
                                                             "\n"
                                                             "```text\n"
                                                             "## an OpenRadioss comment, not a section\n"
                                                             "  /SPHGLO\n"
                                                             "```\n"
                                                             "\n"
                                                             "## After\n"
                                                             "```text\n"
                                                             "/SPHGLO\n"
                                                             "```\n");
    for (const std::string& problem : page.problems) FAIL_CHECK(problem);
    CHECK(page.code == "XX001");
    CHECK(page.name == "some-rule");
    CHECK(page.what == "Reports *PART cards wrapped over `a\\*b` lines.");  // escapes kept inside code
    CHECK(page.why == "Because.");
    CHECK(page.fix == "Fix it.");
    CHECK(page.before == "## an OpenRadioss comment, not a section\n  /SPHGLO\n");
    CHECK(page.after == "/SPHGLO\n");
}

TEST_CASE("rules: a page that breaks the fixed shape is reported with its line") {
    auto problems = [](std::string_view text) {
        std::string all;
        for (const std::string& p : lint::parse_rule_doc_page("docs/rules/XX001.md", text).problems) all += p + "\n";
        return all;
    };
    const std::string tail = "## How to fix\nFix.\n## Before\n```text\nA\n```\n## After\n```text\nB\n```\n";
    CHECK(problems("# XX001 r\n## What it does\nW.\n## Why it matters\nY.\n" + tail).empty());
    CHECK(contains(problems("# XX002 r\n## What it does\nW.\n## Why it matters\nY.\n" + tail),
                   "docs/rules/XX001.md:1: the title's code 'XX002' is not the file's 'XX001'"));
    CHECK(contains(problems("# XX001 r\n## What it does\nW.\n" + tail), ":4: '## How to fix' out of place"));
    CHECK(contains(problems("# XX001 r\n## What it does\nW.\n\nMore.\n## Why it matters\nY.\n" + tail),
                   ":5: one paragraph only"));
    CHECK(contains(problems("# XX001 r\n## What it does\n## Why it matters\nY.\n" + tail), ":2: the section is empty"));
    CHECK(contains(problems("# XX001 r\n## What it does\nW.\n## Why it matters\nY.\n## How to fix\nF.\n"
                            "## Before\nA\n## After\n```text\nB\n"),
                   ":9: expected a ```text block"));
    CHECK(contains(problems("# XX001 r\n## What it does\nW.\n## Why it matters\nY.\n## How to fix\nF.\n"
                            "## Before\n```text\nA\n```\n## After\n```text\nB\n"),
                   ":12: the ```text block is not closed"));
    CHECK(contains(problems("## What it does\nW.\n"), ":1: the page must start with '# CODE name'"));
    CHECK(contains(problems("## What it does\nW.\n"), "no '## After' section"));
}
}  // namespace test_rule_docs_cpp
