// The rule registry: one sorted table that covers the whole catalogue, with complete documentation.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "lint/registry.hpp"

namespace test_registry_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using lint::RuleInfo;

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_lower_alnum(char c) { return (c >= 'a' && c <= 'z') || is_digit(c); }

bool is_code(std::string_view code) {
    for (std::string_view prefix : {"DK", "REF", "SPH", "RAD"}) {
        if (!code.starts_with(prefix) || code.size() != prefix.size() + 3) continue;
        std::string_view digits = code.substr(prefix.size());
        return std::all_of(digits.begin(), digits.end(), is_digit);
    }
    return false;
}

bool is_kebab(std::string_view name) {
    if (name.empty() || name.front() == '-' || name.back() == '-') return false;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name[i] == '-') {
            if (name[i - 1] == '-') return false;
        } else if (!is_lower_alnum(name[i])) {
            return false;
        }
    }
    return true;
}

std::string trim(std::string_view s) {
    std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
    return b == std::string_view::npos ? std::string() : std::string(s.substr(b, e - b + 1));
}

std::vector<std::string> cells(const std::string& row) {
    std::vector<std::string> out;
    std::stringstream in(row);
    std::string cell;
    while (std::getline(in, cell, '|')) out.push_back(trim(cell));
    return out;
}

std::vector<std::string_view> lines_of(std::string_view text) {
    std::vector<std::string_view> out;
    while (!text.empty()) {
        std::size_t nl = text.find('\n');
        out.push_back(text.substr(0, nl));
        if (nl == std::string_view::npos) break;
        text.remove_prefix(nl + 1);
    }
    return out;
}

bool is_keyword_line(std::string_view line) {
    line.remove_prefix(std::min(line.find_first_not_of(' '), line.size()));  // DK020 shows an indented one
    return line.starts_with('*') || line.starts_with('/');
}
bool is_ruler_line(std::string_view line) { return line.starts_with("$#") || line.starts_with('#'); }

bool contains(const std::vector<std::string_view>& v, std::string_view s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

TEST_CASE("registry: codes unique and sorted") {
    auto rules = lint::all_rules();
    REQUIRE(!rules.empty());
    for (std::size_t i = 1; i < rules.size(); ++i) {
        INFO(rules[i - 1].code, " then ", rules[i].code);
        CHECK(rules[i - 1].code < rules[i].code);  // strictly increasing: sorted, no code twice
    }
}

TEST_CASE("registry: every code is a family prefix and three digits") {
    for (const RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        CHECK(is_code(rule.code));
    }
}

TEST_CASE("registry: every catalogue rule is present with its name, severity and source") {
    const std::string path = SPHDECK_SOURCE_DIR "/../shared/spec/lint-rules.md";
    std::ifstream file(path);
    if (!file) {
        MESSAGE("rule catalogue not found at " << path << ": skipped");
        return;
    }
    std::size_t rows = 0;
    for (std::string line; std::getline(file, line);) {
        if (!(line.starts_with("| DK") || line.starts_with("| REF") || line.starts_with("| SPH") ||
              line.starts_with("| RAD")))
            continue;
        auto cell = cells(line);  // "", code, name, sev, condition[, source]
        REQUIRE(cell.size() >= 5);
        ++rows;
        INFO(cell[1]);
        const RuleInfo* rule = lint::find_rule(cell[1]);
        REQUIRE(rule != nullptr);
        CHECK(rule->code == cell[1]);
        CHECK(rule->name == cell[2]);
        const std::string& sev = cell[3];
        // Deliberate departures from the catalogue, each with the issue that decided it.
        const bool departs = cell[1] == "DK001";  // issue 25: an unknown LS-DYNA keyword is an error
        if (sev.find("DFLAG") == std::string::npos && !departs) {
            auto expected = sev.find("error") != std::string::npos  ? diag::Severity::Error
                            : sev.find("warn") != std::string::npos ? diag::Severity::Warning
                                                                    : diag::Severity::Info;
            CHECK(rule->severity == expected);
        }
        if (cell.size() >= 6 && !cell[5].empty()) CHECK(rule->source == cell[5]);
    }
    CHECK(rows >= 90);
}

TEST_CASE("registry: the extra reader rules are registered") {
    struct Extra {
        std::string_view code, name;
        diag::Severity severity;
    };
    for (const Extra& extra :
         {Extra{"DK019", "include-format-ignored", diag::Severity::Warning},
          Extra{"DK020", "keyword-not-in-column-1", diag::Severity::Warning},
          Extra{"DK021", "keyword-case", diag::Severity::Info}, Extra{"DK022", "encrypted-block", diag::Severity::Info},
          Extra{"DK023", "nend-wide-column", diag::Severity::Warning},
          Extra{"DK024", "parameter-case", diag::Severity::Warning},
          Extra{"DK025", "include-path-long", diag::Severity::Error},
          Extra{"DK026", "unused-suppression", diag::Severity::Info}}) {
        INFO(extra.code);
        const RuleInfo* rule = lint::find_rule(extra.code);
        REQUIRE(rule != nullptr);
        CHECK(rule->name == extra.name);
        CHECK(rule->severity == extra.severity);
        CHECK(rule->source == "reader");
    }
}

TEST_CASE("registry: names kebab-case and unique") {
    std::set<std::string_view> names;
    for (const RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code, " ", rule.name);
        CHECK(is_kebab(rule.name));
        CHECK(names.insert(rule.name).second);
    }
}

TEST_CASE("registry: every rule is documented") {
    for (const RuleInfo& rule : lint::all_rules()) {
        INFO(rule.code);
        CHECK(!rule.summary.empty());
        CHECK(rule.summary.find('\n') == std::string_view::npos);
        CHECK(rule.since == "0.1.0");
        CHECK(!rule.source.empty());
        CHECK(!rule.doc.what.empty());
        CHECK(!rule.doc.why.empty());
        CHECK(rule.doc.why.find('(') != std::string_view::npos);  // cites where the rule comes from
        CHECK(!rule.doc.fix.empty());
        CHECK(!rule.doc.before.empty());
        CHECK(!rule.doc.after.empty());
        CHECK(rule.doc.before != rule.doc.after);
        for (std::string_view example : {rule.doc.before, rule.doc.after}) {
            auto lines = lines_of(example);
            CHECK(example.ends_with('\n'));
            CHECK(std::any_of(lines.begin(), lines.end(), is_keyword_line));
            CHECK(std::any_of(lines.begin(), lines.end(), is_ruler_line));
            for (std::string_view line : lines) CHECK(line.size() <= 100);
        }
    }
}

TEST_CASE("registry: find_rule by code, lower-case code and name") {
    const RuleInfo* by_code = lint::find_rule("SPH030");
    REQUIRE(by_code != nullptr);
    CHECK(by_code->name == "iavis-solid-in-2d");
    CHECK(by_code->severity == diag::Severity::Error);
    CHECK(lint::find_rule("sph030") == by_code);
    CHECK(lint::find_rule("Sph030") == by_code);
    CHECK(lint::find_rule("iavis-solid-in-2d") == by_code);
    CHECK(lint::find_rule("rad001")->name == "missing-starter-header");
    CHECK(lint::find_rule("SPH999") == nullptr);
    CHECK(lint::find_rule("") == nullptr);
    CHECK(lint::find_rule("IAVIS-SOLID-IN-2D") == nullptr);  // names are matched exactly
}

TEST_CASE("registry: similar_rules suggests close codes and names") {
    auto codes = lint::similar_rules("SPH03");
    REQUIRE(codes.size() == 3);
    CHECK(codes[0] == "SPH030");
    CHECK(codes[1] == "SPH031");
    CHECK(codes[2] == "SPH032");

    CHECK(contains(lint::similar_rules("sph03"), "SPH030"));
    CHECK(lint::similar_rules("SPH03", 1).size() == 1);
    CHECK(contains(lint::similar_rules("SPH3O"), "SPH030"));  // letter O for zero
    CHECK(contains(lint::similar_rules("iavis-solid-2d"), "iavis-solid-in-2d"));
    CHECK(contains(lint::similar_rules("cslh-rnage"), "cslh-range"));
    CHECK(lint::similar_rules("completely-unrelated-words").empty());
    CHECK(lint::similar_rules("").empty());
}
}  // namespace test_registry_cpp
