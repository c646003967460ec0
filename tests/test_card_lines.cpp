// grammar::CardLines keeps regular lines as runs (issue 40 item 2): whatever it keeps, every way of
// reading the lines (index, CardLinePtr walks, jumps, lower_bound, append with a move) must give the lines
// pushed, and a bulk block's lines must not be stored one by one.
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <algorithm>
#include <random>
#include <vector>

#include "grammar/card_lines.hpp"
#include "grammar/dyna/reader.hpp"
#include "grammar/raw_deck.hpp"

namespace test_card_lines_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using grammar::CardLine;
using grammar::CardLinePtr;
using grammar::CardLines;

namespace {
bool same(const CardLine& a, const CardLine& b) { return a.file == b.file && a.line == b.line && a.offset == b.offset; }

// Lines as a reader pushes them: runs of one width, broken by comment lines, width changes, a new file.
std::vector<CardLine> mixed_lines(std::mt19937& rng, std::size_t count) {
    std::vector<CardLine> out;
    CardLine at{0, 1, 0};
    std::uint32_t width = 17;
    while (out.size() < count) {
        out.push_back(at);
        const unsigned what = rng() % 1000;  // runs of about a hundred lines
        if (what < 2)
            ++at.file, at.line = 1, at.offset = 0;  // another file
        else if (what < 5)
            at.line += 2, at.offset += 2 * width;  // a comment line skipped
        else if (what < 8)
            width = 5 + rng() % 80;  // another width
        else if (what < 10)
            at.offset += 1;  // one longer line
        at.line += 1;
        at.offset += width;
    }
    return out;
}

void check_all(const CardLines& lines, const std::vector<CardLine>& want) {
    REQUIRE(lines.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) REQUIRE(same(lines[i], want[i]));
    std::size_t i = 0;
    for (CardLinePtr p = lines.begin(); p != lines.end(); ++p, ++i) {
        REQUIRE(same(*p, want[i]));
        REQUIRE(p->line == want[i].line);
        REQUIRE(p.index() == i);
    }
    REQUIRE(i == want.size());
}
}  // namespace

TEST_CASE("card lines: regular lines become runs, and read back as pushed") {
    std::vector<CardLine> want;
    for (std::uint32_t k = 0; k < 1000; ++k) want.push_back({3, 10 + k, 100 + 57 * k});  // one bulk block
    CardLines lines;
    for (const CardLine& l : want) lines.push_back(l);
    check_all(lines, want);
    CHECK(lines.runs() == 1);
    CHECK(lines.stored_lines() == 0);

    // A comment line in the block: two runs; a short block of three lines: stored.
    want.push_back({3, 1011, 100 + 57 * 1001});
    for (std::uint32_t k = 0; k < 3; ++k) want.push_back({3, 2000 + k, 90000 + 9 * k});
    for (std::size_t i = 1000; i < want.size(); ++i) lines.push_back(want[i]);
    check_all(lines, want);
    CHECK(lines.runs() == 1);
    CHECK(lines.stored_lines() == 4);
}

TEST_CASE("card lines: random mixes read back alike by index, walks, jumps and lower_bound") {
    std::mt19937 rng(40);
    for (int round = 0; round < 20; ++round) {
        const std::vector<CardLine> want = mixed_lines(rng, 200 + rng() % 3000);
        CardLines lines;
        for (const CardLine& l : want) lines.push_back(l);
        check_all(lines, want);
        CHECK(lines.runs() > 0);
        CHECK(lines.stored_lines() < want.size() / 2);
        for (int jump = 0; jump < 200; ++jump) {
            const auto a = static_cast<std::ptrdiff_t>(rng() % want.size());
            const auto b = static_cast<std::ptrdiff_t>(rng() % want.size());
            CardLinePtr p = lines.at(static_cast<std::size_t>(a));
            REQUIRE(same(p[b - a], want[static_cast<std::size_t>(b)]));
            p += b - a;
            REQUIRE(same(*p, want[static_cast<std::size_t>(b)]));
            REQUIRE(p - lines.begin() == b);
            REQUIRE(same(*(lines.end() - (static_cast<std::ptrdiff_t>(want.size()) - b)),
                         want[static_cast<std::size_t>(b)]));
        }
        // Offsets rise within one file: find each line by its offset, as the re-check's splice does.
        const auto first_other = std::find_if(want.begin(), want.end(), [](const CardLine& l) { return l.file != 0; });
        const auto end = lines.begin() + (first_other - want.begin());
        for (std::ptrdiff_t k = 0; k < first_other - want.begin(); k += 7) {
            const CardLinePtr found = std::lower_bound(lines.begin(), end, want[static_cast<std::size_t>(k)].offset,
                                                       [](const CardLine& l, std::uint32_t o) { return l.offset < o; });
            REQUIRE(found.index() == static_cast<std::size_t>(k));
        }
    }
}

TEST_CASE("card lines: lines pushed in runs of consecutive lines keep what one by one keeps") {
    std::mt19937 rng(41);
    for (int round = 0; round < 40; ++round) {
        const std::vector<CardLine> want = mixed_lines(rng, 100 + rng() % 4000);
        CardLines one_by_one, in_runs;
        for (const CardLine& l : want) one_by_one.push_back(l);
        // As a reader hands them: stretches of one file on consecutive line numbers, cut at random too.
        for (std::size_t i = 0; i < want.size();) {
            std::size_t end = i + 1;
            const std::size_t most = i + 1 + rng() % 300;
            while (end < want.size() && end < most && want[end].file == want[i].file &&
                   want[end].line == want[end - 1].line + 1)
                ++end;
            std::vector<std::uint32_t> starts;
            for (std::size_t k = i; k < end; ++k) starts.push_back(want[k].offset);
            in_runs.push_back_lines(want[i].file, want[i].line, starts.data(), starts.size());
            i = end;
        }
        check_all(in_runs, want);
        CHECK(in_runs.runs() == one_by_one.runs());
        CHECK(in_runs.stored_lines() == one_by_one.stored_lines());
    }
}

TEST_CASE("card lines: append moves lines (runs stay runs), pop_back, moves and copies") {
    std::mt19937 rng(7);
    const std::vector<CardLine> want = mixed_lines(rng, 5000);
    CardLines from;
    for (const CardLine& l : want) from.push_back(l);

    // Lines [100, 4000) moved back 3 lines and 50 bytes (modulo 2^32, as the splice moves them), file 9.
    CardLines to;
    to.push_back({9, 1, 0});
    to.append(from, 100, 4000,
              CardLines::Move{static_cast<std::uint32_t>(-3), static_cast<std::uint32_t>(-50), true, 9});
    std::vector<CardLine> moved{{9, 1, 0}};
    for (std::size_t i = 100; i < 4000; ++i) moved.push_back({9, want[i].line - 3, want[i].offset - 50});
    check_all(to, moved);
    CHECK(to.runs() > 0);

    // pop_back off a run and off stored lines.
    for (int k = 0; k < 40; ++k) to.pop_back(), moved.pop_back();
    check_all(to, moved);
    to.push_back(moved.back()), to.pop_back();
    check_all(to, moved);

    // A CardLinePtr stays valid when its lines move (as a pointer into a vector did); a copy is its own.
    const CardLinePtr p = to.at(123);
    CardLines moved_to = std::move(to);
    CHECK(same(*p, moved[123]));
    CHECK(same(p[200], moved[323]));
    CardLines copy = moved_to;
    copy.push_back({1, 1, 1});
    CHECK(moved_to.size() == moved.size());
    check_all(moved_to, moved);
}

TEST_CASE("card lines: the 1M deck's bulk blocks keep no line objects") {
    std::string text = "*KEYWORD\n*NODE\n$#   nid               x               y               z\n";
    for (int k = 1; k <= 500; ++k) text += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", k, 0.1 * k, 0.0, 0.0);
    text += "*ELEMENT_SPH\n";
    for (int k = 1; k <= 500; ++k) text += fmt::format("{:8d}{:8d}{:16.6f}\n", k, 1, 1e-3);
    text += "*END\n";
    const grammar::RawDeck deck = grammar::dyna::read_buffer(text, "bulk.k");
    const auto nodes = std::find_if(deck.blocks.begin(), deck.blocks.end(),
                                    [](const grammar::Block& b) { return b.keyword == "*NODE"; });
    REQUIRE(nodes != deck.blocks.end());
    REQUIRE(nodes + 1 != deck.blocks.end());
    CHECK(deck.lines.size() == 1000);
    CHECK(deck.lines.stored_lines() == 0);
    CHECK(deck.lines.runs() == 2);
    CHECK(deck.text(*deck.begin_lines(*nodes)).substr(0, 8) == "       1");
    CHECK(deck.text(*(deck.end_lines(*nodes) - 1)).substr(0, 8) == "     500");
    CHECK(deck.end_lines(*nodes)->line == (nodes + 1)->span.line + 1);  // the next block's first line
}

}  // namespace test_card_lines_cpp
