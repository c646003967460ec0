// "Did you mean" wherever a name is wrong (issue 25 items 1 and 4): keywords, parameters, include
// files, command-line options and rule codes.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <random>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/similar_names.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_suggestions_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const diag::Diagnostic* first_of(const engine::CheckResult& r, std::string_view code) {
    for (const auto& d : r.diagnostics)
        if (d.code == code) return &d;
    return nullptr;
}

engine::CheckResult check_text(const test::TempDir& dir, const std::string& name, const std::string& text) {
    dir.write(name, text);
    return engine::check_file((dir.path() / name).string(), {});
}

}  // namespace

TEST_CASE("suggestions: the typing distance makes a swap cheaper than other edits") {
    CHECK(grammar::typing_distance("SHP", "SPH") == 1);
    CHECK(grammar::typing_distance("SHP", "SHA") == 2);
    CHECK(grammar::typing_distance("PRAT", "PART") == 1);
    CHECK(grammar::typing_distance("endx", "ENDX", true) == 0);
    CHECK(grammar::typing_distance("", "abc") == 6);
}

TEST_CASE("suggestions: one edit distance, a swap costing half an edit, one edit or two") {
    // Rule names (lint/registry.cpp) count a swap as one edit; command names (cli/suggest.cpp) as two.
    CHECK(grammar::edit_distance("chekc", "check", grammar::SwapCost::OneEdit) == 1);
    CHECK(grammar::edit_distance("chekc", "check", grammar::SwapCost::TwoEdits) == 2);
    CHECK(grammar::edit_distance("fromat", "format", grammar::SwapCost::TwoEdits) == 2);
    CHECK(grammar::edit_distance("kitten", "sitting", grammar::SwapCost::TwoEdits) == 3);
    CHECK(grammar::edit_distance("", "lsp", grammar::SwapCost::OneEdit) == 3);
}

TEST_CASE("suggestions: a bounded distance is the distance up to the bound, and only 'beyond' past it") {
    std::mt19937 rng(7);
    const auto random_name = [&] {
        std::string s(rng() % 12, 'A');
        for (char& c : s) c = "ABCS_"[rng() % 5];  // few letters: many close pairs and swaps
        return s;
    };
    for (int i = 0; i < 3000; ++i) {
        const std::string a = random_name(), b = random_name();
        const std::size_t full = grammar::typing_distance(a, b);
        const std::size_t limit = rng() % 10;
        const std::size_t bounded = grammar::typing_distance(a, b, false, limit);
        INFO(a, " ", b, " limit ", limit);
        if (full <= limit)
            CHECK(bounded == full);
        else
            CHECK(bounded == limit + 1);
    }
}

namespace {

// The whole table, as the definition reads: what the banded table of typing_distance must give.
std::size_t whole_table_distance(std::string_view a, std::string_view b, bool fold_case, std::size_t swap) {
    const auto same = [&](char x, char y) {
        return fold_case ? std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y))
                         : x == y;
    };
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = 2 * i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = 2 * j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] =
                std::min({d[i - 1][j] + 2, d[i][j - 1] + 2, d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 2)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]) && !same(a[i - 1], b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + swap);
        }
    return d[a.size()][b.size()];
}

}  // namespace

TEST_CASE("suggestions: the bounded distance equals the whole table's, for every swap cost, case and bound") {
    std::mt19937 rng(11);
    const auto random_name = [&] {
        std::string s(rng() % 14, 'A');
        for (char& c : s) c = "ABCSab_"[rng() % 7];
        return s;
    };
    for (int i = 0; i < 4000; ++i) {
        const std::string a = random_name(), b = rng() % 4 == 0 ? a : random_name();
        const bool fold_case = rng() % 2 == 0;
        const auto swap =
            std::array{grammar::SwapCost::Slip, grammar::SwapCost::OneEdit, grammar::SwapCost::TwoEdits}[rng() % 3];
        const std::size_t limit = rng() % 3 == 0 ? std::size_t{1000} : rng() % 13;
        const std::size_t expected =
            std::min(whole_table_distance(a, b, fold_case, static_cast<std::size_t>(swap)), limit + 1);
        INFO(a, " ", b, " limit ", limit, " swap ", static_cast<int>(swap), " fold ", fold_case);
        CHECK(grammar::typing_distance(a, b, fold_case, limit, swap) == expected);
    }
}

TEST_CASE("suggestions: keywords, with the author's options kept") {
    CHECK(keywords::suggest_keyword("*CONTROL_SHP") == "*CONTROL_SPH");
    CHECK(keywords::suggest_keyword("*SECTON_SPH") == "*SECTION_SPH");
    CHECK(keywords::suggest_keyword("*PRAT") == "*PART");
    CHECK(keywords::suggest_keyword("*CONTROL_TERMINATON") == "*CONTROL_TERMINATION");
    CHECK(keywords::suggest_keyword("*secton_sph_title") == "*SECTION_SPH_TITLE");
    CHECK(keywords::suggest_keyword("*DATABASE_SPHMASFLOW") == "*DATABASE_SPHMASSFLOW");  // a generated layout
    CHECK(keywords::suggest_keyword("*CONTROL_SPH_INCOMPRESSIBLY") == "*CONTROL_SPH_INCOMPRESSIBLE");
    CHECK(keywords::suggest_keyword("*TERMINATION_NODES") == "*TERMINATION_NODE");  // known without a layout
    CHECK_FALSE(keywords::suggest_keyword("*COMPLETELY_DIFFERENT_THING"));
    CHECK(keywords::keyword_replacement("*control_shp", "*CONTROL_SPH") == "*control_sph");
    CHECK(keywords::keyword_replacement("*Control_Shp", "*CONTROL_SPH") == "*CONTROL_SPH");
}

TEST_CASE("suggestions: an unknown keyword is an error at its line with the fix; a real one is not") {
    test::TempDir dir;
    auto r = check_text(dir, "typo.k", "*KEYWORD\n*control_shp\n         1         0     1e+20         2\n*END\n");
    const diag::Diagnostic* d = first_of(r, "DK001");
    REQUIRE(d);
    CHECK(d->severity == diag::Severity::Error);
    CHECK(d->span.line == 2);
    CHECK(d->message.find("LS-DYNA stops") != std::string::npos);
    CHECK(d->message.find("did you mean *CONTROL_SPH?") != std::string::npos);
    REQUIRE(d->fixes.size() == 1);
    CHECK_FALSE(d->fixes[0].safe);
    REQUIRE(d->fixes[0].edits.size() == 1);
    CHECK(d->fixes[0].edits[0].replacement == "*control_sph");
    CHECK(d->fixes[0].edits[0].span.column == 1);
    CHECK(d->fixes[0].edits[0].span.end_column == 13);

    auto real =
        check_text(dir, "real.k", "*KEYWORD\n*TERMINATION_NODE\n         1         3       0.0       1.0\n*END\n");
    const diag::Diagnostic* info = first_of(real, "DK001");
    REQUIRE(info);
    CHECK(info->severity == diag::Severity::Info);
}

TEST_CASE("suggestions: a misspelt *CONTROL_SPH's consequences point back at the typo") {
    test::TempDir dir;
    // IDIM 2 lost with the block: the 2D mass per particle looks wrong for the default 3D.
    const std::string deck =
        "*KEYWORD\n*CONTROL_SHP\n         1         0     1e+20         2\n"
        "*SECTION_SPH\n         1       1.2\n*PART\nwater\n         1         1         1\n"
        "*MAT_NULL\n         1    1000.0\n*EOS_LINEAR_POLYNOMIAL\n         1\n"
        "*NODE\n       1             0.0             0.0             0.0\n"
        "       2           0.015             0.0             0.0\n"
        "*ELEMENT_SPH\n       1       1          0.225\n       2       1          0.225\n*END\n";
    auto r = check_text(dir, "consequence.k", deck);
    for (const auto& d : r.diagnostics) {
        if (!(d.code.starts_with("SPH") || d.code.starts_with("REF"))) continue;
        CAPTURE(d.message);
        const bool points_back = std::any_of(d.notes.begin(), d.notes.end(), [](const diag::Note& n) {
            return n.span.line == 2 && n.message.find("*CONTROL_SPH") != std::string::npos;
        });
        CHECK(points_back);
    }
}

TEST_CASE("suggestions: an undefined parameter names a close defined one, or says the field cut it") {
    test::TempDir dir;
    auto r = check_text(dir, "params.k",
                        "*KEYWORD\n*PARAMETER\nR endt         0.002I pidwater         1\n"
                        "*CONTROL_TERMINATION\n     &endx\n*NODE\n       1             0.0             0.0\n"
                        "*ELEMENT_SPH\n       1&pidwater\n*END\n");
    std::vector<const diag::Diagnostic*> found;
    for (const auto& d : r.diagnostics)
        if (d.code == "DK012") found.push_back(&d);
    REQUIRE(found.size() == 2);
    CHECK(found[0]->message == "undefined parameter 'endx'; did you mean 'endt'?");
    REQUIRE(found[0]->fixes.size() == 1);
    CHECK(found[0]->fixes[0].edits[0].replacement == "endt");
    CHECK(found[0]->fixes[0].edits[0].span.column == 7);  // the name after '&'
    // PID is 8 columns wide: '&pidwater' is read as '&pidwate'.
    CHECK(found[1]->message.find("the name is longer than its field") != std::string::npos);
    CHECK(found[1]->message.find("'&pidwater' does not fit in 8 columns") != std::string::npos);
}

TEST_CASE("suggestions: a missing include lists each path once, its rule, -I and a similar file") {
    test::TempDir dir;
    dir.write("mesh_v3.k", "*NODE\n       1             0.0             0.0             0.0\n");
    auto r = check_text(dir, "main.k", "*KEYWORD\n*INCLUDE\nmesh_v2.k\n*END\n");
    const diag::Diagnostic* d = first_of(r, "DK010");
    REQUIRE(d);
    CHECK(d->message == "include file 'mesh_v2.k' not found; did you mean 'mesh_v3.k'?");
    REQUIRE(d->fixes.size() == 1);
    CHECK(d->fixes[0].edits[0].replacement == "mesh_v3.k");
    std::size_t tried = 0;
    bool hint = false;
    for (const auto& n : d->notes) {
        if (n.message.starts_with("tried ")) {
            ++tried;
            CHECK(n.message.find("including file's folder and main deck's folder") != std::string::npos);
        }
        hint = hint ||
               (n.message.find("-I DIR") != std::string::npos && n.message.find("*INCLUDE_PATH") != std::string::npos);
    }
    CHECK(tried == 1);  // the deck's folder is the including file's: one path, tried once
    CHECK(hint);

    // A deck named relative to the working folder, and an OpenRadioss #include: the same suggestion.
    test::Run run = test::run_sphdeck(dir, "check --format concise main.k");
    CHECK(run.out.find("main.k:3:1: error: include file 'mesh_v2.k' not found; did you mean 'mesh_v3.k'?") !=
          std::string::npos);
    dir.write("run_0000.rad",
              "#RADIOSS STARTER\n/BEGIN\nrun\n      2022         0\n"
              "                  kg                  mm                  ms\n"
              "                  kg                  mm                  ms\n#include mesh_v2.k\n/END\n");
    run = test::run_sphdeck(dir, "check --format concise run_0000.rad");
    CHECK(run.out.find("include file 'mesh_v2.k' not found; did you mean 'mesh_v3.k'?") != std::string::npos);
}

TEST_CASE("suggestions: an unknown command-line option names the closest one, exit 2") {
    test::TempDir dir;
    dir.write("deck.k", "*KEYWORD\n*END\n");
    test::Run r = test::run_sphdeck(dir, "check --formt json deck.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("sphdeck check: unknown option --formt; did you mean --format?") != std::string::npos);
    r = test::run_sphdeck(dir, "smooth --formt=csv deck.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("sphdeck smooth: unknown option --formt; did you mean --format?") != std::string::npos);
    r = test::run_sphdeck(dir, "check --max-per-cod 3 deck.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("did you mean --max-per-code?") != std::string::npos);
    r = test::run_sphdeck(dir, "check -I . deck.k");  // a known short option with its value
    CHECK(r.exit_code == 0);
}

TEST_CASE("suggestions: rule codes that do not exist, wherever they are written") {
    test::TempDir dir;
    dir.write("deck.k", "*KEYWORD\n$ sphdeck: disable=SPH0300\n*END\n");
    test::Run r = test::run_sphdeck(dir, "rule SPH0300");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("unknown rule 'SPH0300'; did you mean 'SPH030'") != std::string::npos);
    r = test::run_sphdeck(dir, "check --ignore DK0001 deck.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("did you mean 'DK001'") != std::string::npos);
    r = test::run_sphdeck(dir, "check --format concise deck.k");
    CHECK(r.out.find("unknown rule 'SPH0300' in suppression; did you mean 'SPH030'") != std::string::npos);
    dir.write("sphdeck.toml", "ignore = [\"SPH0300\"]\n");
    r = test::run_sphdeck(dir, "check deck.k");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("did you mean 'SPH030'") != std::string::npos);
}
}  // namespace test_suggestions_cpp
