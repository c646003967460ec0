// One pass over a card line for the bulk decoder (model/card_decoder_plain.cpp): where the line
// ends, as RawDeck::text finds it, and whether it holds a comma (free format) or a tab, the two
// things that send a line to the full decoder. Sixteen bytes at a time: three memchr calls (the
// end, ',', '\t') cost more than the scan on lines of 30-80 characters.
#pragma once

#include <string_view>

#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar {

struct ScannedLine {
    std::string_view text;      // RawDeck::text(line): without "\r\n"
    bool comma_or_tab = false;  // a ',' or '\t' in text
};

ScannedLine scan_line(const RawDeck& deck, const CardLine& line);

}  // namespace sphdeck::grammar
