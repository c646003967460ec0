// Big *NODE and *ELEMENT_SPH blocks are decoded on several threads (model/deck_check.cpp): the
// model and the findings must be exactly those of the one-thread walk, in the same order.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <map>
#include <set>
#include <string>

#include "grammar/read_deck.hpp"
#include "model/model_builder.hpp"
#include "same_model.hpp"
#include "same_model.hpp"

namespace test_bulk_decode_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// A deck big enough for the parallel path, with the irregular lines it must fix up: an id that
// does not read, an NEND range, a bad coordinate, a node card without coordinates.
std::string big_deck(int n) {
    std::string text = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= n; ++i) {
        if (i == 100)
            text += "     abc     1.0     2.0     3.0\n";  // DK003, line skipped
        else if (i == 5000)
            text += fmt::format("{:8d}     1.x     2.0     3.0\n", i);  // DK003 on X
        else
            text += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", i, 0.001 * i, 0.002 * i, 0.5);
    }
    text += "*ELEMENT_SPH\n";
    for (int i = 1; i <= n; ++i) {
        if (i == 7)
            text += fmt::format("{:8d}{:8d}{:16.6f}{:8d}\n", i, 1, 0.25, i + 3);  // NEND range: 7..10
        else if (i >= 8 && i <= 10)
            continue;
        else if (i == 9000)
            text += "  zz9000       1       1.0\n";  // DK003, skipped
        else
            text += fmt::format("{:8d}{:8d}{:16.6f}\n", i, 1 + i % 3, 1.0 + i);
    }
    text += "*END\n";
    return text;
}

struct Built {
    model::Model model;
    std::vector<diag::Diagnostic> diagnostics;
    model::DeckSummary summary;
};

Built build(const grammar::RawDeck& deck, bool parallel) {
    Built b;
    model::ModelBuilder builder(deck);
    b.summary = model::check_deck(
        deck, b.diagnostics,
        [&](const grammar::Block& bl, const keywords::KeywordMatch& m, const keywords::CardSpec& c,
            grammar::CardLinePtr l, const std::vector<model::FieldValue>& v) { builder.on_card(bl, m, c, l, v); },
        parallel ? &builder.bulk_visitor() : nullptr);
    b.model = builder.finish(b.diagnostics);
    return b;
}

// The parallel walk's model, particle count and findings are the serial walk's.
void check_same_walks(const Built& serial, const Built& parallel) {
    test::check_same_bulk_columns(serial.model, parallel.model);
    CHECK(serial.summary.particles == parallel.summary.particles);
    test::check_same_findings(serial.diagnostics, parallel.diagnostics);
}

}  // namespace

TEST_CASE("bulk decode: the parallel walk gives the model and findings of the serial one") {
    const int n = 20000;
    grammar::RawDeck deck = grammar::read_deck_buffer(big_deck(n), "big.k");
    Built serial = build(deck, false);
    Built parallel = build(deck, true);

    // The serial result is the reference: check it is what the deck says before comparing.
    CHECK(serial.model.nodes.id.size() == static_cast<std::size_t>(n - 1));   // the "abc" line dropped
    CHECK(serial.model.particles.size() == static_cast<std::size_t>(n - 1));  // 7..10 from one line, zz dropped
    CHECK(serial.summary.particles == static_cast<std::size_t>(n - 1 + 1));   // the skipped line still counts

    const auto& b = parallel.model;
    check_same_walks(serial, parallel);
    CHECK(serial.diagnostics.size() >= 3);  // the two DK003 on nodes and the one on particles at least

    // The NEND range expands in place, with the mass and line of its card.
    for (std::size_t i = 6; i < 10; ++i) {
        CHECK(b.particles.node[i] == static_cast<long long>(i + 1));
        CHECK(b.particles.mass[i] == doctest::Approx(0.25));
        CHECK(b.particles.line[i] == b.particles.line[6]);
    }
}

TEST_CASE("bulk decode: NEND ranges the deck's nodes cannot hold are refused alike on threads") {
    // 10000 node lines; every particle card asks for a range of 3, so the ranges together would
    // need 30000 particles, more than twice the nodes: the first 6666 are generated, the rest
    // refused (DK007), and one card asks for 1e15 particles by itself (the OOM of issue 14).
    const int n = 10000;
    std::string text = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= n; ++i) text += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", i, 0.001 * i, 0.0, 0.0);
    text += "*ELEMENT_SPH\n";
    for (int i = 1; i <= n; ++i) {
        if (i == 5)
            text += fmt::format("{:8d}{:8d}{:16.6f}{:>8}\n", i, 1, 1.0, "1e15");
        else
            text += fmt::format("{:8d}{:8d}{:16.6f}{:8d}\n", i, 1, 1.0, i + 2);
    }
    text += "*END\n";
    grammar::RawDeck deck = grammar::read_deck_buffer(text, "ranges.k");
    Built serial = build(deck, false);
    Built parallel = build(deck, true);

    CHECK(serial.model.particles.size() == 6666 * 3 + (n - 6666));
    CHECK(serial.summary.particles == serial.model.particles.size());
    std::size_t refused = 0, alone = 0;
    for (const auto& d : serial.diagnostics) {
        if (d.code != "DK007") continue;
        ++refused;
        // The flood guard (model/flood_guard.cpp) keeps the first findings of a block and counts the
        // rest in the last one: "(and N more DK007 finding(s) ...)".
        if (const auto more = d.message.find("(and "); more != std::string::npos)
            refused += std::stoul(d.message.substr(more + 5));
        if (d.span.line == 10000 + 3 + 5) {  // *KEYWORD, *NODE, the nodes, *ELEMENT_SPH, then card 5
            ++alone;
            CHECK(d.message.find("range of 999999999999996 particles; the deck defines 10000 node(s)") !=
                  std::string::npos);
            CHECK(d.span.column == 37);  // NEND's "1e15", underlined where it is written
        }
    }
    CHECK(alone == 1);
    CHECK(refused == static_cast<std::size_t>(n - 6666));

    CHECK(serial.model.particles.node == parallel.model.particles.node);
    CHECK(serial.model.particles.line == parallel.model.particles.line);
    CHECK(serial.summary.particles == parallel.summary.particles);
    REQUIRE(serial.diagnostics.size() == parallel.diagnostics.size());
    for (std::size_t i = 0; i < serial.diagnostics.size(); ++i) {
        CHECK(serial.diagnostics[i].code == parallel.diagnostics[i].code);
        CHECK(serial.diagnostics[i].message == parallel.diagnostics[i].message);
        CHECK(serial.diagnostics[i].span.line == parallel.diagnostics[i].span.line);
    }
}

// The lean path (model/card_decoder_plain.cpp) takes plain lines only; every line below must fall
// back to the full decoder, and the parallel walk (lean path) must still match the serial one
// (full decoder only), finding by finding, span by span.
TEST_CASE("bulk decode: lines the lean path must leave to the full decoder") {
    const int n = 12000;
    std::string text = "*KEYWORD\n*PARAMETER\nR XX      2.5\n*NODE\n";
    const char* odd_nodes[] = {
        "      11,1.0,2.0,3.0",                                     // free format
        "      12\t       1.0             2.0             3.0",     // tab moving X when expanded
        "      13            &XX             2.0             3.0",  // parameter
        "",                                                         // blank line: NID required
        "      15             1.0             2.0             3.0       0       0        junk past 80",  // DK006
        "   16            1.0D3             2.0             3.0",                                        // Fortran real
        "      +17            1.0             2.0             3.0",                         // '+' integer (misaligned)
        "99999999999999999             1.0             2.0",                                // 17 digits > 2^53: DK007
        "      19             1.0             2.0             3.0      x",                  // TC not an integer
        "      20             1.0             2.0             3.0       1.5",               // TC written as real
        "      21             1.0             2.0             3.0\r",                       // CRLF line end
        "      22             1.x             2.0             3.0",                         // DK003
        "      23     1.0e+400             2.0             3.0",                            // overflow
        "      24             1.0             2.0             3.0       0       0  extra",  // columns 73-80
    };
    for (int i = 1; i <= n; ++i) {
        if (i >= 11 && i <= 24)
            text += std::string(odd_nodes[i - 11]) + "\n";
        else if (i == 30)
            text += "$ a comment inside the block\n";
        else
            text += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", i, 0.001 * i, 0.002 * i, 0.5);
    }
    text += "*ELEMENT_SPH\n";
    const char* odd_particles[] = {
        "      11       1     1.0    &XX",             // parameter in NEND
        "      12       1  1.0e+00    13",             // NEND range
        "      14,1,1.0",                              // free format
        "      15          1.0e+00",                   // PID blank: required
        "      16       1        -",                   // a lone '-'
        "      17       1  1.0e+00      17  7",        // NEND reaches 41-42 (DK023)
        "      18       1  1.0e+00        x",          // text in an unused column (if any)
        "      19       1  .5",                        // real without a leading digit
        "      20       1  5.",                        // real without digits after the point
        "      21       1        1.000000      1e15",  // NEND range of 1e15 written as real: DK007
    };
    for (int i = 1; i <= n; ++i) {
        if (i >= 11 && i <= 21) {
            if (i - 11 < static_cast<int>(std::size(odd_particles))) text += std::string(odd_particles[i - 11]) + "\n";
        } else {
            text += fmt::format("{:8d}{:8d}{:16.6f}\n", i, 1 + i % 3, 1.0 + i);
        }
    }
    text += "*END\n";
    grammar::RawDeck deck = grammar::read_deck_buffer(text, "odd.k");
    Built serial = build(deck, false);
    Built parallel = build(deck, true);

    check_same_walks(serial, parallel);
    // The odd lines do report: the comparison is not between two empty lists.
    std::set<std::string> codes;
    for (const auto& d : serial.diagnostics) codes.insert(d.code);
    CHECK(codes.count("DK002"));
    CHECK(codes.count("DK003"));
    CHECK(codes.count("DK006"));
    CHECK(codes.count("DK007"));
    CHECK(codes.count("DK008"));
    CHECK(codes.count("DK016"));
}

// Broken lines of the same width as the lines around them stay inside their run of lines (grammar/card_lines.hpp),
// which the parallel walk reads from one view of its window: each must still go to the full decoder and be
// reported on its own line, as the serial walk reports it.
TEST_CASE("bulk decode: broken lines inside a run of lines of one width") {
    const int n = 10000;
    const auto node = [](int i) { return fmt::format("{:8d}{:16.8e}{:16.8e}{:16.8e}\n", i, 0.001 * i, -0.5, 0.25); };
    std::map<int, std::string> planted = {
        {1000, "    1000  1.0000000Oe+00 -5.00000000e-01  2.50000000e-01\n"},   // O for 0: DK003
        {2000, "    2000  1,00000000e+00 -5.00000000e-01  2.50000000e-01\n"},   // decimal comma
        {3000, "    30O0  1.00000000e+00 -5.00000000e-01  2.50000000e-01\n"},   // O in the id
        {4000, "    4000  1.000000e+00-5.00000000e-01     2.50000000e-01\n"},   // y glued to x
        {5001, "    5001  1.00000000e+00 -5.00000000e-01  2.50000000e-0\r\n"},  // CRLF, one digit less
    };
    std::string text = "*KEYWORD\n*NODE\n";
    for (int i = 1; i <= n; ++i) {
        const auto p = planted.find(i);
        if (p != planted.end()) REQUIRE(p->second.size() == node(i).size());
        text += p != planted.end() ? p->second : node(i);
    }
    text += "*ELEMENT_SPH\n";
    for (int i = 1; i <= n; ++i)
        text += i == 7000 ? fmt::format("{:8d}{:8d}{:>16}\n", i, 1, "1.0e-6x")  // DK003 on the mass
                          : fmt::format("{:8d}{:8d}{:16.8e}\n", i, 1, 1e-6);
    text += "*END\n";
    grammar::RawDeck deck = grammar::read_deck_buffer(text, "runs.k");
    REQUIRE(deck.lines.runs() > 0);  // the lines are runs, broken ones included
    Built serial = build(deck, false);
    Built parallel = build(deck, true);

    check_same_walks(serial, parallel);
    // Each planted line has its finding on it: the deck's line is the node's + 2 (*KEYWORD, *NODE).
    std::set<std::uint32_t> lines;
    for (const auto& d : parallel.diagnostics) lines.insert(d.span.line);
    for (int i : {1000, 2000, 3000, 4000}) CHECK(lines.count(static_cast<std::uint32_t>(i + 2)));
    CHECK(lines.count(static_cast<std::uint32_t>(n + 3 + 7000)));
    bool crlf_read = false;  // node 5001: its CRLF line reads
    for (std::size_t k = 0; k < parallel.model.nodes.id.size(); ++k)
        if (parallel.model.nodes.id[k] == 5001) crlf_read = parallel.model.nodes.z[k] == 2.5;  // "2.50000000e-0"
    CHECK(crlf_read);
}
}  // namespace test_bulk_decode_cpp
