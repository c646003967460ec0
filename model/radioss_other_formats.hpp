// Text past a generated card's last field that another format of the keyword reads as a field:
// /HEAT/MAT IFORM in columns 81-90, a field of formats 51-2019 that format 2022 dropped. In a deck
// of a known version an older format's field is obsolete (the starter ignores it: an info, not an
// overflow); in a fragment without /BEGIN, whose version is its includer's, a field some version
// reads is no overflow at all.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/radioss/cards.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::model {

struct OtherFormatField {
    const grammar::radioss::FormatSpec* format = nullptr;
    const grammar::radioss::FieldSpec* field = nullptr;
    std::uint32_t first_column = 0, last_column = 0;  // 1-based, inclusive
};

// The field of another format than `format` (the newest such) whose cells hold 0-based columns
// [first, last) of card `card`, or nullopt.
std::optional<OtherFormatField> field_of_other_format(const grammar::radioss::KeywordSpec& table,
                                                      const grammar::radioss::FormatSpec& format, std::size_t card,
                                                      std::uint32_t first, std::uint32_t last, int version);

// Settles the DK006 findings from `from` on that lie on `line` (its `text`): when `version_known` is
// false, the text other formats read as fields is left out of them (a finding of nothing else is
// dropped); else an info when an older format reads the text as a field.
void settle_trailing_text(std::vector<diag::Diagnostic>& out, std::size_t from, const grammar::CardLine& line,
                          std::string_view text, const grammar::radioss::KeywordSpec& table,
                          const grammar::radioss::FormatSpec& format, std::size_t card, int version,
                          bool version_known);

}  // namespace sphdeck::model
