// edit::format_deck_without_findings, the layout from the reading alone that `format --check` takes on a deck
// laid out already (issue 40): it must give up (nullopt) whenever one line would change or be held back by
// a finding, wherever that line lies in a bulk block (first, last, at a thread's or a page release's chunk
// edge), in every block format (standard, long `+`, I10 `%`, OpenRadioss), and otherwise give format_deck's
// own result. Also the one-pass quick test of the bulk lines (edit::LaidOutTest) against the two it
// stands for (grammar::scan_line and edit::already_laid_out).
#include <doctest/doctest.h>

#include <omp.h>

#include <filesystem>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "edit/format_deck.hpp"
#include "edit/format_line.hpp"
#include "edit/laid_out_test.hpp"
#include "engine/check.hpp"

namespace test_format_without_findings_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// A *NODE block of `n` lines laid out already (8 + 3 x 16 + 8 + 8 columns), line `i` written by `node`.
std::string node_line(std::size_t i) {
    return fmt::format("{:>8}{:>16.8e}{:>16.8e}{:>16.8e}{:>8}{:>8}", i + 1, 0.001 * static_cast<double>(i), -0.5, 2.0,
                       0, 0);
}

std::string deck_with_nodes(std::size_t n, std::size_t odd_at, const std::string& odd_line,
                            const std::string& keyword = "*NODE") {
    std::string text = "*KEYWORD\n*CONTROL_TERMINATION\n       1.0\n" + keyword + "\n";
    text.reserve(n * 80);
    for (std::size_t i = 0; i < n; ++i) {
        if (i == odd_at) {
            text += odd_line + "\n";
            if (odd_line.starts_with("$")) text += node_line(i) + "\n";  // a comment is not a card
        } else {
            text += node_line(i) + "\n";
        }
    }
    return text + "*END\n";
}

// Both results of one deck: format_deck after the check, and the one without findings (nullopt: given up).
struct Both {
    edit::FormatResult full;
    std::optional<edit::FormatResult> fast;
};

Both format_both(const std::string& text, std::optional<grammar::DeckFormat> format = grammar::DeckFormat::LsDyna,
                 const std::string& name = "main.k") {
    const engine::CheckResult r = engine::check_buffer(text, name, {}, format);
    Both out;
    out.full = edit::format_deck(r.deck, r.diagnostics, {0}, {});
    out.fast = edit::format_deck_without_findings(r.deck, {0}, {});
    return out;
}

void check_same(const edit::FormatResult& a, const edit::FormatResult& b) {
    CHECK(a.changes == b.changes);
    CHECK(a.kept == b.kept);
    REQUIRE(a.edits.size() == b.edits.size());
    for (std::size_t i = 0; i < a.edits.size(); ++i) {
        CHECK(a.edits[i].span.line == b.edits[i].span.line);
        CHECK(a.edits[i].replacement == b.edits[i].replacement);
    }
}

// Sets the OpenMP threads for one scope (the bulk lines are cut in one chunk per thread).
class Threads {
public:
    explicit Threads(int n) : saved_(omp_get_max_threads()) { omp_set_num_threads(n); }
    ~Threads() { omp_set_num_threads(saved_); }
    Threads(const Threads&) = delete;
    Threads& operator=(const Threads&) = delete;

private:
    int saved_;
};

}  // namespace

namespace {

// LaidOutTest::length on every line of `lines`, each followed by the next line, "\r\n" or the file's end, against
// what it stands for: scan_line's test for commas and tabs, then already_laid_out.
void check_laid_out_length(const std::vector<std::string>& lines, std::span<const grammar::FixedField> slots,
                           std::span<const edit::CellKind> kinds) {
    const edit::LaidOutTest laid_out(slots, kinds);
    // What follows the line: the next line (long enough for the 16-byte chunks, or not), or the file's end.
    const std::string tail(200, '7');
    for (const std::string& line : lines)
        for (const std::string& after : {std::string("\n*END\n"), std::string("\r\n"), std::string(), std::string("\r"),
                                         "\n" + tail, "\r\n" + tail, "\r" + tail}) {
            CAPTURE(line);
            CAPTURE(after.size());
            const std::string file = line + after;
            const bool comma_or_tab = line.find_first_of(",\t") != std::string::npos;
            // The line as RawDeck::text reads it: to '\n', a last '\r' dropped.
            std::string text = file.substr(0, file.find('\n'));
            if (!text.empty() && text.back() == '\r') text.pop_back();
            const bool expected = !comma_or_tab && edit::already_laid_out(text, slots, kinds);
            const std::optional<std::size_t> length = laid_out.length(file);
            CHECK(length.has_value() == expected);
            if (length) CHECK(*length == text.size());
        }
}

// `base` and the lines made from it by one byte changed or inserted at each column (each byte a laid-out line
// may or may not hold there), and cut short.
std::vector<std::string> lines_around(const std::string& base) {
    std::vector<std::string> lines{base, base.substr(0, 40), base.substr(0, 8), ""};
    for (std::size_t at = 0; at <= base.size(); ++at)
        for (const char c : std::string(" ,\t\rx5$+-")) {
            std::string changed = base;
            if (at < base.size())
                changed[at] = c;
            else
                changed += c;
            lines.push_back(changed);
            std::string inserted = base;
            inserted.insert(at, 1, c);
            lines.push_back(inserted);
        }
    lines.push_back(base + std::string(100, '1'));  // wider than the bit masks
    return lines;
}

}  // namespace

TEST_CASE("format without findings: the one-pass test of a bulk line agrees with scan_line + already_laid_out") {
    using K = edit::CellKind;
    SUBCASE("a *NODE line") {
        const std::vector<grammar::FixedField> slots{{0, 8}, {8, 16}, {24, 16}, {40, 16}, {56, 8}, {64, 8}};
        const std::vector<K> kinds{K::Label, K::Number, K::Number, K::Number, K::Number, K::Number};
        const std::string base = node_line(41);
        std::vector<std::string> lines = lines_around(base);
        lines.push_back("      ab" + base.substr(8));  // a name in the label field
        lines.push_back("     -12" + base.substr(8));  // a signed label
        lines.push_back("       -" + base.substr(8));  // a sign alone
        lines.push_back(base.substr(0, 40) + std::string(16, ' ') + "       0");
        check_laid_out_length(lines, slots, kinds);
    }
    SUBCASE("labels, a text field, a gap and an unused field") {
        const std::vector<grammar::FixedField> slots{{0, 10}, {10, 10}, {25, 10}, {35, 10}, {45, 5}};
        const std::vector<K> kinds{K::Label, K::Text, K::Number, K::Label, K::Unused};
        const std::string base = "        -7               1.5e3       +12";
        std::vector<std::string> lines = lines_around(base);
        lines.push_back("        -7       abc     1.5e3       +12");  // text in the text field
        lines.push_back("        -7               1.5e3       +12    9");
        lines.push_back("        +-               1.5e3      12+3");
        check_laid_out_length(lines, slots, kinds);
    }
    SUBCASE("fields out of order: byte by byte") {
        const std::vector<grammar::FixedField> slots{{10, 10}, {0, 10}};
        const std::vector<K> kinds{K::Number, K::Number};
        check_laid_out_length(lines_around("         1         2"), slots, kinds);
    }
}

TEST_CASE("format without findings: a bulk block laid out already needs no finding, and gives format_deck's result") {
    for (const int threads : {1, 2}) {
        Threads team(threads);
        const Both both = format_both(deck_with_nodes(40000, 40000, ""));
        REQUIRE(both.fast.has_value());
        CHECK(both.fast->edits.empty());
        check_same(both.full, *both.fast);
    }
}

TEST_CASE("format without findings: one line not laid out anywhere in a bulk block: given up") {
    // 40000 lines: two threads cut at 20000, pages are given back every 16384 lines of a chunk.
    const std::size_t n = 40000;
    const std::vector<std::size_t> places{0, 1, 9999, 16383, 16384, 16385, 19999, 20000, 20001, 36383, 36384, n - 1};
    const std::vector<std::string> odd{
        fmt::format("{:<8}{:>16.8e}{:>16.8e}{:>16.8e}", 7, 1.0, 2.0, 3.0),   // an id left-aligned
        node_line(7) + " ",                                                  // a trailing blank
        fmt::format("{:>8},{:>15.8e}{:>16.8e}{:>16.8e}", 7, 1.0, 2.0, 3.0),  // a comma: free format
        node_line(7).substr(0, 60) + "\t0",                                  // a tab
    };
    for (const int threads : {1, 2}) {
        Threads team(threads);
        for (const std::size_t at : places)
            for (const std::string& line : odd) {
                CAPTURE(threads);
                CAPTURE(at);
                CAPTURE(line);
                const Both both = format_both(deck_with_nodes(n, at, line));
                CHECK_FALSE(both.fast.has_value());
                CHECK(both.full.edits.size() + both.full.kept >= 1);  // the full format does see it
            }
    }
}

TEST_CASE("format without findings: a comment line inside a bulk block is no card") {
    Threads team(2);
    for (const std::size_t at : {std::size_t{0}, std::size_t{16384}, std::size_t{20000}, std::size_t{39999}}) {
        CAPTURE(at);
        const Both both = format_both(deck_with_nodes(40000, at, "$ a comment   , with\ta tab, not laid out  "));
        REQUIRE(both.fast.has_value());
        CHECK(both.fast->edits.empty());
        check_same(both.full, *both.fast);
    }
}

TEST_CASE("format without findings: long (+) and I10 (%) bulk blocks in their own widths") {
    std::string long_block = "*KEYWORD\n*NODE +\n", i10 = "*KEYWORD\n*NODE %\n";
    for (int i = 1; i <= 10000; ++i) {
        long_block += fmt::format("{:>20}{:>20.8e}{:>20.8e}{:>20.8e}{:>20}{:>20}\n", i, 0.5, 1.0, 1.5, 0, 0);
        i10 += fmt::format("{:>10}{:>16.8e}{:>16.8e}{:>16.8e}{:>10}{:>10}\n", i, 0.5, 1.0, 1.5, 0, 0);
    }
    for (const std::string& deck : {long_block + "*END\n", i10 + "*END\n"}) {
        const Both laid = format_both(deck);
        REQUIRE(laid.fast.has_value());
        CHECK(laid.fast->edits.empty());
        check_same(laid.full, *laid.fast);
        // The standard widths inside such a block are not its layout: given up, and the full format moves them.
        std::string odd = deck;
        const std::size_t at = odd.find("\n", odd.size() / 2) + 1;
        odd.insert(at, node_line(20000) + "\n");
        const Both moved = format_both(odd);
        CHECK_FALSE(moved.fast.has_value());
        CHECK(moved.full.edits.size() + moved.full.kept >= 1);
    }
}

TEST_CASE("format without findings: a line laid out but held back by a finding (DK004) needs the findings") {
    // `1.0` in the integer NCBS of *CONTROL_SPH: laid out, yet format_deck counts it left as written.
    const std::string deck = "*KEYWORD\n*CONTROL_SPH\n       1.0         0   1.0e+20\n*END\n";
    const Both both = format_both(deck);
    CHECK(both.full.kept == 1);
    CHECK_FALSE(both.fast.has_value());
    // Plain numbers in their own fields: no finding can hold the line back.
    const Both plain = format_both("*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20\n*END\n");
    REQUIRE(plain.fast.has_value());
    check_same(plain.full, *plain.fast);
}

TEST_CASE("format without findings: OpenRadioss cards, laid out or not") {
    std::string deck =
        "#RADIOSS STARTER\n/BEGIN\nrun\n      2026\n                  kg                  mm"
        "                  ms\n                  kg                  mm                  ms\n/NODE\n";
    for (int i = 1; i <= 3000; ++i) deck += fmt::format("{:>10}{:>20.8e}{:>20.8e}{:>20.8e}\n", i, 0.25, 0.5, 0.75);
    const std::string laid = deck + "/END\n";
    const Both both = format_both(laid, std::nullopt, "run_0000.rad");
    REQUIRE(both.fast.has_value());
    CHECK(both.fast->edits.empty());
    check_same(both.full, *both.fast);
    const std::string odd = deck + fmt::format("{:<10}{:>20.8e}{:>20.8e}{:>20.8e}\n", 3001, 0.25, 0.5, 0.75) + "/END\n";
    const Both moved = format_both(odd, std::nullopt, "run_0000.rad");
    CHECK_FALSE(moved.fast.has_value());
    CHECK(moved.full.edits.size() == 1);
}

TEST_CASE("format without findings: a misreading's cause folds other lines' findings into notes: given up") {
    // DK032 (a *PART heading left out) and DK033 (*PART without its '*') hold back three laid-out lines each.
    for (const char* name : {"DK032_fires.k", "DK033_fires.k"}) {
        const std::string path = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/dk/" + name;  // from any folder
        CAPTURE(path);
        const engine::CheckResult r = engine::check_file(path);
        CHECK(edit::format_deck(r.deck, r.diagnostics, {0}, {}).kept == 3);
        CHECK_FALSE(edit::format_deck_without_findings(r.deck, {0}, {}).has_value());
    }
}

TEST_CASE("format without findings: the rule decks (DK, RAD) give format_deck's result or give up") {
    std::size_t decks = 0, answered = 0;
    for (const char* folder : {"/decks/tests/dk", "/decks/tests/rad"})
        for (const auto& entry : std::filesystem::directory_iterator(std::string(SPHDECK_SOURCE_DIR) + folder)) {
            const std::string path = entry.path().string();
            if (!path.ends_with(".k") && !path.ends_with("_0000.rad")) continue;
            CAPTURE(path);
            const engine::CheckResult r = engine::check_file(path);
            const std::optional<edit::FormatResult> fast = edit::format_deck_without_findings(r.deck, {0}, {});
            ++decks;
            if (!fast) continue;
            ++answered;
            check_same(edit::format_deck(r.deck, r.diagnostics, {0}, {}), *fast);
        }
    CHECK(decks > 100);
    CHECK(answered > 10);  // laid-out decks among them take the quick way
}

}  // namespace test_format_without_findings_cpp
