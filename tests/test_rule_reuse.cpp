// Issue 45 item 2: after an edit the re-check splices in, only the rule families whose inputs the edit
// changed run again (lint/rule_inputs.hpp, engine/rule_reuse.hpp); the others' findings are the last
// check's, moved with their lines. Each re-check here is compared with a full check of the same text,
// finding for finding (code, severity, message, places of the finding, its notes and fixes), and the
// families it reused are the ones the edit left alone: a reuse that is wrong fails the comparison, and
// a re-check that reuses nothing fails the expectations.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/check.hpp"
#include "engine/recheck.hpp"
#include "engine/rule_reuse.hpp"
#include "grammar/deck_splice.hpp"
#include "lint/rule_inputs.hpp"
#include "text/text_file.hpp"
#include "workspace_check.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"

namespace test_rule_reuse_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using lint::RuleFamily;

namespace {

std::string node_line(int id, double x, double y, double z) {
    char line[96];
    std::snprintf(line, sizeof line, "%8d%16.8e%16.8e%16.8e\n", id, x, y, z);
    return line;
}

// A 2D deck of n x n particles with findings of several families: a node off the plane (SPH110, the
// particles' positions), a particle whose node is missing (REF001, the particles), a material no part
// uses (REF007, the keywords), a part title.
std::string deck_with_findings(int n) {
    std::string deck =
        "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20         2       150         0\n*SECTION_SPH\n"
        "         1       1.2       0.2       2.0\n*PART\nwater\n         1         1         1         1\n"
        "*MAT_NULL\n         1    1000.0\n*MAT_NULL\n         7    1000.0\n"
        "*EOS_MURNAGHAN\n         1       7.0  357142.9       1.0\n*NODE\n";
    for (int i = 0; i < n * n; ++i) deck += node_line(i + 1, 0.01 * (i % n), 0.01 * (i / n), i == 3 ? 0.5 : 0.0);
    deck += "*ELEMENT_SPH\n";
    char line[96];
    for (int i = 0; i < n * n; ++i) {
        std::snprintf(line, sizeof line, "%8d%8d%16.8e\n", i + 1, 1, 0.1);
        deck += line;
    }
    return deck + "     999       1 1.0e-01\n*END\n";
}

std::string where(const text::Span& s) { return fmt::format("{}:{}:{}-{}", s.file, s.line, s.column, s.end_column); }

// The first difference between two lists of findings, or "" when they are the same.
std::string first_difference(const std::vector<diag::Diagnostic>& got, const std::vector<diag::Diagnostic>& full) {
    if (got.size() != full.size()) return fmt::format("{} findings, a full check {}", got.size(), full.size());
    for (std::size_t i = 0; i < full.size(); ++i) {
        const diag::Diagnostic &a = got[i], &b = full[i];
        std::string one = fmt::format("{} {} {} {}", a.code, int(a.severity), where(a.span), a.message);
        std::string other = fmt::format("{} {} {} {}", b.code, int(b.severity), where(b.span), b.message);
        for (const diag::Note& n : a.notes) one += " | " + where(n.span) + " " + n.message;
        for (const diag::Note& n : b.notes) other += " | " + where(n.span) + " " + n.message;
        for (const diag::Fix& f : a.fixes)
            for (const diag::TextEdit& e : f.edits) one += " / " + where(e.span) + " " + e.replacement;
        for (const diag::Fix& f : b.fixes)
            for (const diag::TextEdit& e : f.edits) other += " / " + where(e.span) + " " + e.replacement;
        if (one != other) return fmt::format("finding {}: {}\n  full check: {}", i, one, other);
    }
    return "";
}

std::vector<RuleFamily> reused_families(const engine::CheckResult& result) {
    std::vector<RuleFamily> out;
    for (RuleFamily f : lint::all_rule_families)
        if (result.rule_findings.reused[static_cast<std::size_t>(f)]) out.push_back(f);
    return out;
}

std::string names(const std::vector<RuleFamily>& families) {
    std::string out;
    for (RuleFamily f : families) out += std::string(out.empty() ? "" : " ") + std::string(lint::name_of(f));
    return out;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
        lines.push_back(text.substr(start, end - start));
    lines.push_back(text.substr(start));
    return lines;
}

std::string text_of(const std::vector<std::string>& lines) {
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? "\n" : "") + lines[i];
    return out;
}

// One random edit of the kinds a re-check may answer with findings it keeps: a title retyped, a
// comment line added or removed, a digit of a *NODE or *ELEMENT_SPH line (position, id, part, mass),
// a digit of another block's data line (a value). `lines` becomes the edited text; the LSP change.
nlohmann::json reuse_edit(std::vector<std::string>& lines, std::mt19937& random) {
    const auto pick = [&](std::size_t n) {
        return static_cast<std::uint32_t>(std::uniform_int_distribution<std::size_t>(0, n - 1)(random));
    };
    std::vector<std::uint32_t> titles, comments, bulk, data;
    std::string keyword;
    bool first_card = false;  // the next data line is its block's first
    for (std::uint32_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        if (!l.empty() && l[0] == '*') {
            keyword = l, first_card = true;
            continue;
        }
        const bool first = first_card && !l.empty() && l[0] != '$';
        if (first) first_card = false;
        if (keyword.empty()) continue;
        if (!l.empty() && l[0] == '$') {
            comments.push_back(i);
        } else if (keyword.rfind("*NODE", 0) == 0 || keyword.rfind("*ELEMENT_SPH", 0) == 0) {
            bulk.push_back(i);
        } else if (keyword.rfind("*PART", 0) == 0 && first) {
            titles.push_back(i);  // the heading: the block's first card
        } else if (keyword != "*KEYWORD" && keyword != "*END") {
            data.push_back(i);
        }
    }
    const auto change = [](std::uint32_t l1, std::uint32_t c1, std::uint32_t l2, std::uint32_t c2,
                           const std::string& text) {
        return nlohmann::json{
            {"range", {{"start", {{"line", l1}, {"character", c1}}}, {"end", {{"line", l2}, {"character", c2}}}}},
            {"text", text}};
    };
    const auto digit_of = [&](const std::vector<std::uint32_t>& among) -> nlohmann::json {
        if (among.empty()) return nullptr;
        const std::uint32_t line = among[pick(among.size())];
        std::string& text = lines[line];
        std::vector<std::uint32_t> digits;
        for (std::uint32_t i = 0; i < text.size(); ++i)
            if (text[i] >= '0' && text[i] <= '9') digits.push_back(i);
        if (digits.empty()) return nullptr;
        const std::uint32_t at = digits[pick(digits.size())];
        text[at] = static_cast<char>('0' + (text[at] - '0' + 1 + pick(9)) % 10);
        return change(line, at, line, at + 1, std::string(1, text[at]));
    };
    switch (pick(6)) {
        case 0: {  // a title retyped
            if (titles.empty()) return nullptr;
            const std::uint32_t line = titles[pick(titles.size())];
            static const std::vector<std::string> words = {"water", "floor 2", "", "12", "tank wall", "x"};
            const std::string word = words[pick(words.size())];
            const auto old_size = static_cast<std::uint32_t>(lines[line].size());
            lines[line] = word;
            return change(line, 0, line, old_size, word);
        }
        case 1: {  // a comment line added inside a block (never before the first keyword)
            std::vector<std::uint32_t> inside = data;
            inside.insert(inside.end(), bulk.begin(), bulk.end());
            inside.insert(inside.end(), titles.begin(), titles.end());
            if (inside.empty()) return nullptr;
            const std::uint32_t line = inside[pick(inside.size())];
            lines.insert(lines.begin() + line, "$ note");
            return change(line, 0, line, 0, "$ note\n");
        }
        case 2: {  // a comment line removed
            if (comments.empty()) return nullptr;
            const std::uint32_t line = comments[pick(comments.size())];
            if (line + 1 >= lines.size()) return nullptr;
            lines.erase(lines.begin() + line);
            return change(line, 0, line + 1, 0, "");
        }
        case 3:
        case 4: return digit_of(bulk);
        default: return digit_of(data);
    }
}

}  // namespace

TEST_CASE("rule reuse: an edit reruns the families that read what it changed, the others' findings move") {
    const std::filesystem::path path = std::filesystem::absolute("rule_reuse_lattice.k");
    std::string text = deck_with_findings(12);
    engine::Documents documents;
    documents.set(path, text);
    engine::CheckOptions options;
    options.rules.keep_preview = true;  // as the editor checks
    engine::CheckResult last = engine::check_deck(path.string(), documents, options);
    REQUIRE(last.rule_findings.kept);
    // The deck's findings come from several families: their reuse is seen in the comparison.
    const auto& by = last.rule_findings.by_family;
    REQUIRE(!by[static_cast<std::size_t>(RuleFamily::References)].empty());
    REQUIRE(!by[static_cast<std::size_t>(RuleFamily::SphParticles)].empty());

    using F = RuleFamily;
    const std::vector<F> keyword_free = {F::Isph, F::Densities};
    const std::vector<F> node_id_free = {F::SectionSph, F::Isph, F::Densities};
    const std::vector<F> position_free = {F::References, F::SectionSph, F::Isph, F::Densities};
    const std::vector<F> titles_free = {F::References, F::ControlSph, F::SectionSph,   F::SphParticles, F::SphMaterials,
                                        F::Isph,       F::Densities,  F::SphDimension, F::Preview};
    std::vector<F> every = titles_free;
    every.push_back(F::Radioss);  // it reads the titles too (Radioss decks, never spliced)
    struct Edit {
        const char* what;
        std::string from, to;
        std::vector<F> reused;
    };
    const std::vector<Edit> edits = {
        {"the part's title", "water\n", "water, renamed\n", titles_free},
        {"a comment line above the findings (the lines below move)", "*MAT_NULL\n", "*MAT_NULL\n$ mid ro\n", every},
        {"the title retyped again", "water, renamed\n", "water, renamed again\n", titles_free},
        {"a node's x (positions, not ids)", node_line(20, 0.01 * 7, 0.01, 0.0), node_line(20, 0.075, 0.01, 0.0),
         position_free},
        {"a node's id", node_line(30, 0.01 * 5, 0.02, 0.0), node_line(1030, 0.01 * 5, 0.02, 0.0), node_id_free},
        {"a particle's mass", "      40       1  1.00000000e-01", "      40       1  2.00000000e-01", keyword_free},
        {"the unused material's density", "         7    1000.0", "         7    1001.0", {}},
        {"the off-plane node put back", node_line(4, 0.03, 0.0, 0.5), node_line(4, 0.03, 0.0, 0.0), position_free},
        {"CSLH", "       1.2", "       1.3", {}},
    };
    for (const Edit& edit : edits) {
        CAPTURE(edit.what);
        const std::size_t at = text.find(edit.from);
        REQUIRE(at != std::string::npos);
        text.replace(at, edit.from.size(), edit.to);
        documents.set(path, text);
        engine::CheckResult again = engine::recheck_deck(path.string(), documents, options, last);
        const engine::CheckResult full = engine::check_deck(path.string(), documents, options);
        CHECK(first_difference(again.diagnostics, full.diagnostics) == "");
        CHECK(names(reused_families(again)) == names(edit.reused));
        // What the next re-check reuses is what a full check found.
        for (F f : lint::all_rule_families) {
            CAPTURE(lint::name_of(f));
            const auto i = static_cast<std::size_t>(f);
            CHECK(first_difference(again.rule_findings.by_family[i], full.rule_findings.by_family[i]) == "");
        }
        last = std::move(again);
    }
}

TEST_CASE("rule reuse: random edits through the editor keep what they may and publish what a full check does") {
    std::vector<std::pair<std::filesystem::path, std::string>> decks;
    decks.emplace_back(std::filesystem::absolute("rule_reuse_random.k"), deck_with_findings(9));
    for (const char* name : {"decks/demo/sph_mistakes_2d.k", "decks/tests/preview/SPH118_fires.k"}) {
        const std::filesystem::path path = std::filesystem::path(SPHDECK_SOURCE_DIR) / name;
        decks.emplace_back(path, text::read_text_file(path.string()));
    }
    std::mt19937 random(4545);
    std::size_t reused = 0, rerun = 0;
    for (const auto& deck : decks) {
        const std::filesystem::path& path = deck.first;
        CAPTURE(path.string());
        const std::string uri = lsp::uri_from_path(path);
        nlohmann::json published;
        lsp::Workspace workspace([&](const nlohmann::json& params) {
            if (params["uri"] == uri) published = params["diagnostics"];
        });
        workspace.open(uri, deck.second, 1);
        workspace.flush();
        std::vector<std::string> lines = lines_of(deck.second);
        for (int edit = 0; edit < 16; ++edit) {
            const nlohmann::json change = reuse_edit(lines, random);
            if (change.is_null()) continue;
            CAPTURE(edit);
            CAPTURE(change.dump());
            REQUIRE(workspace.change(uri, edit + 2, nlohmann::json::array({change})));
            workspace.flush();
            const nlohmann::json full = test::published_by_full_check(path, text_of(lines));
            REQUIRE(published.size() == full.size());
            for (std::size_t i = 0; i < full.size(); ++i) CHECK(published[i] == full[i]);
            REQUIRE(workspace.checked_decks().size() == 1);
            const engine::RuleFindings& kept = workspace.checked_decks()[0]->result.rule_findings;
            for (RuleFamily f : lint::all_rule_families) {
                const auto i = static_cast<std::size_t>(f);
                reused += kept.reached[i] && kept.reused[i];
                rerun += kept.reached[i] && !kept.reused[i];
            }
        }
    }
    MESSAGE(reused, " families reused, ", rerun, " run again");
    CHECK(reused > 120);  // most edits leave most families' inputs alone
    CHECK(rerun > 60);
}

TEST_CASE("rule reuse: findings move with their lines, and those on a line the edit changed are found again") {
    const std::filesystem::path path = std::filesystem::absolute("rule_reuse_places.k");
    const std::string text = deck_with_findings(6);
    engine::Documents documents;
    documents.set(path, text);
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const engine::CheckResult first = engine::check_deck(path.string(), documents, options);
    // SPH110 at the off-plane node's z, REF001 at the particle whose node is missing (after it).
    const auto& off_plane = first.rule_findings.by_family[static_cast<std::size_t>(RuleFamily::SphParticles)];
    const auto& missing = first.rule_findings.by_family[static_cast<std::size_t>(RuleFamily::References)];
    REQUIRE(!off_plane.empty());
    REQUIRE(!missing.empty());
    const std::string node = node_line(4, 0.01 * 3, 0.0, 0.5);
    REQUIRE(text.find(node) != std::string::npos);

    // A comment line above the node: the splice takes the node's line in, unchanged; all move down one.
    std::string commented = text;
    commented.insert(commented.find(node), "$ a comment\n");
    auto spliced = grammar::splice_edit(first.deck, grammar::SourceText(commented));
    REQUIRE(spliced);
    std::vector<diag::Diagnostic> moved = off_plane, moved_missing = missing;
    REQUIRE(engine::follow_edit(moved, first.deck, spliced->deck, spliced->changed));
    REQUIRE(engine::follow_edit(moved_missing, first.deck, spliced->deck, spliced->changed));
    CHECK(moved.front().span.line == off_plane.front().span.line + 1);
    CHECK(moved_missing.front().span.line == missing.front().span.line + 1);

    // The node's line retyped: the findings that point at it are not moved, the others stay.
    std::string retyped = text;
    retyped.replace(retyped.find(node), node.size(), node_line(4, 0.01 * 3, 0.0, 0.6));
    spliced = grammar::splice_edit(first.deck, grammar::SourceText(retyped));
    REQUIRE(spliced);
    moved = off_plane, moved_missing = missing;
    CHECK_FALSE(engine::follow_edit(moved, first.deck, spliced->deck, spliced->changed));
    REQUIRE(engine::follow_edit(moved_missing, first.deck, spliced->deck, spliced->changed));
    CHECK(moved_missing.front().span.line == missing.front().span.line);
}

}  // namespace test_rule_reuse_cpp
