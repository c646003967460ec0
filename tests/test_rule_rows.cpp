// A rule is one registry row that names its check, its page and its decks (lint/registry.hpp, RuleHome):
// the row test holds every row to what it names, so a rule cannot lose its page, its firing deck or its
// silent deck unnoticed (or the row says why a deck cannot be written). The decks themselves run in
// tests/test_decks.cpp, one ctest entry per rule (rule-CODE).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lint/registry.hpp"
#include "lint/rule_docs.hpp"
#include "rule_decks.hpp"

namespace test_rule_rows_cpp {  // each test file's names stay its own in a unity batch

namespace fs = std::filesystem;
using namespace sphdeck;

namespace {

std::vector<std::string> words(std::string_view list) {
    std::vector<std::string> out;
    std::istringstream in{std::string(list)};
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

std::string read_source(const std::string& relative) {
    std::ifstream in(fs::path(SPHDECK_SOURCE_DIR) / relative, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The folder of a deck under decks/tests/ ("sph", "rad"), or "" for one elsewhere (decks/demo/).
std::string test_folder(const fs::path& deck) {
    const fs::path relative = deck.lexically_relative(fs::path(SPHDECK_SOURCE_DIR) / "decks" / "tests");
    if (relative.empty() || *relative.begin() == "..") return {};
    return relative.parent_path().string();
}

// Every deck named after a rule, by code.
std::map<std::string, std::vector<fs::path>> decks_by_rule() {
    std::map<std::string, std::vector<fs::path>> out;
    for (const fs::path& deck : test::all_test_decks()) {
        std::string rule = test::rule_of_deck(deck);
        if (!rule.empty()) out[rule].push_back(deck);
    }
    return out;
}

}  // namespace

TEST_CASE("rule rows: the deck names read as their rule and kind") {
    CHECK(test::rule_of_deck("decks/tests/sph/SPH030_fires.k") == "SPH030");
    CHECK(test::rule_of_deck("decks/tests/dk/DK029_lone_value_silent.k") == "DK029");
    CHECK(test::rule_of_deck("decks/tests/rad/RAD021_fires_0000.rad") == "RAD021");
    CHECK(test::rule_of_deck("decks/tests/preview/mesh_box.k").empty());
    CHECK(test::rule_of_deck("decks/tests/sph/SPH030.k").empty());
    CHECK(test::rule_of_deck("decks/tests/sph/SPH30_fires.k").empty());
    CHECK(test::kind_of_deck("decks/tests/dk/DK029_straddle3_fires.k") == test::DeckKind::Fires);
    CHECK(test::kind_of_deck("decks/tests/sph/SPH092_silent.k") == test::DeckKind::Silent);
    CHECK(test::kind_of_deck("decks/tests/rad/DK007_integer_range.rad") == test::DeckKind::Other);
    CHECK(test::kind_of_deck("decks/tests/preview/mesh_box.k") == test::DeckKind::Other);
    CHECK(!test::is_main_deck("decks/tests/rad/RAD021_fires_0001.rad"));  // read with its starter deck
    CHECK(!test::is_main_deck("decks/tests/dk/include/dk011_s/model.inc"));
}

TEST_CASE("rule rows: each rule's check reports its code") {
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        const auto files = words(rule.home.check);
        CHECK_MESSAGE(!files.empty(), "name the source files of its check in lint/registry_rows.cpp");
        for (const std::string& file : files) {
            INFO(file);
            const std::string text = read_source(file);
            CHECK_MESSAGE(!text.empty(), "no such source file");
            CHECK_MESSAGE(text.find('"' + std::string(rule.code) + '"') != std::string::npos,
                          "the file does not name the code");
        }
    }
}

TEST_CASE("rule rows: each rule has its page") {
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        const std::string page = lint::rule_page_path(rule);
        CHECK(page == "docs/rules/" + std::string(rule.code) + ".md");
        CHECK_MESSAGE(fs::is_regular_file(fs::path(SPHDECK_SOURCE_DIR) / page), "write " << page);
        const lint::RuleDocPage* embedded = lint::find_rule_doc_page(rule.code);
        REQUIRE_MESSAGE(embedded != nullptr, "rebuild: " << page << " is not embedded");
        CHECK(embedded->file == page);
    }
}

TEST_CASE("rule rows: each rule has a firing and a silent deck where its row says, or the reason why not") {
    const auto by_rule = decks_by_rule();
    for (const lint::RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        const auto folders = words(rule.home.decks);
        const std::set<std::string> named(folders.begin(), folders.end());
        CHECK_MESSAGE(!folders.empty(), "name the folders of its decks (under decks/tests/)");
        for (const std::string& folder : folders)
            CHECK_MESSAGE(fs::is_directory(fs::path(SPHDECK_SOURCE_DIR) / "decks" / "tests" / folder),
                          "no folder decks/tests/" << folder);
        std::set<std::string> used;
        std::size_t fires = 0, silents = 0;
        const auto it = by_rule.find(std::string(rule.code));
        for (const fs::path& deck : it == by_rule.end() ? std::vector<fs::path>{} : it->second) {
            INFO(deck.string());
            const std::string folder = test_folder(deck);
            CHECK_MESSAGE(named.count(folder) == 1, "the row does not name its folder '" << folder << "'");
            used.insert(folder);
            fires += test::kind_of_deck(deck) == test::DeckKind::Fires;
            silents += test::kind_of_deck(deck) == test::DeckKind::Silent;
        }
        for (const std::string& folder : folders)
            CHECK_MESSAGE(used.count(folder) == 1,
                          "the row names decks/tests/" << folder << ", which has none of its decks");
        if (rule.home.no_firing_deck.empty())
            CHECK_MESSAGE(fires > 0, "write a deck " << rule.code << "_fires.k that reports it");
        else
            CHECK_MESSAGE(fires == 0, "it has a firing deck now: drop the row's reason");
        if (rule.home.no_silent_deck.empty())
            CHECK_MESSAGE(silents > 0,
                          "write a deck " << rule.code << "_silent.k, a near miss that must not report it");
        else
            CHECK_MESSAGE(silents == 0, "it has a silent deck now: drop the row's reason");
    }
}

TEST_CASE("rule rows: every deck named after a code has a row") {
    // Not a structured binding: clang-14 cannot capture one in INFO's lambda.
    for (const auto& entry : decks_by_rule()) {
        const auto& code = entry.first;
        const auto& decks = entry.second;
        INFO(code << ": " << decks.front().string());
        CHECK_MESSAGE(lint::find_rule(code) != nullptr, "no registry row: rename the deck or add the rule");
    }
}

TEST_CASE("rule rows: every rule has its ctest entry") {
    // CMakeLists.txt reads the codes from lint/registry_rows.cpp; a row it cannot read would run no deck.
    std::vector<std::string> registered;
    for (const lint::RuleInfo& rule : lint::all_rules()) registered.emplace_back(rule.code);
    CHECK(words(test::rule_ctest_codes()) == registered);
}
}  // namespace test_rule_rows_cpp
