// grammar::scan_line must give RawDeck::text and the comma/tab verdict of two memchr calls, for
// every line length around the 16-byte chunks, "\r\n" endings and a last line without '\n'.
#include <doctest/doctest.h>

#include <random>
#include <string>

#include "grammar/line_scan.hpp"
#include "grammar/read_deck.hpp"

namespace test_line_scan_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {
bool has_comma_or_tab(std::string_view text) {
    return text.find(',') != std::string_view::npos || text.find('\t') != std::string_view::npos;
}
}  // namespace

TEST_CASE("line scan: the text and comma/tab verdict of RawDeck::text and memchr") {
    std::mt19937 rng(19);
    for (const bool final_newline : {true, false}) {
        std::string text = "*KEYWORD\n*NODE\n";
        for (int length = 0; length <= 90; ++length)
            for (int variant = 0; variant < 4; ++variant) {
                std::string line(static_cast<std::size_t>(length), ' ');
                for (char& c : line) c = static_cast<char>('0' + rng() % 10);
                if (length > 0 && variant == 1) line[rng() % line.size()] = ',';
                if (length > 0 && variant == 2) line[rng() % line.size()] = '\t';
                if (variant == 3) line += '\r';  // a "\r\n" ending
                text += line + '\n';
            }
        text += "       1       2       3,";  // the last line, with or without its newline
        if (final_newline) text += '\n';
        const grammar::RawDeck deck = grammar::read_deck_buffer(text, "scan.k");
        REQUIRE(deck.lines.size() > 300);
        for (const grammar::CardLine& l : deck.lines) {
            const grammar::ScannedLine scanned = grammar::scan_line(deck, l);
            CAPTURE(l.line);
            CHECK(scanned.text == deck.text(l));
            CHECK(scanned.comma_or_tab == has_comma_or_tab(deck.text(l)));
        }
    }
}
}  // namespace test_line_scan_cpp
