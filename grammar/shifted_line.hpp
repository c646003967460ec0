// Why a fixed-format line reads wrong when its values are fine: the whole line sits a few columns off
// its fields (a blank typed or deleted at its start), or the block was written in other field widths
// (8-column fields where the keyword reads 10, standard where it reads long). Decided only when the
// realigned reading is certain; the realigned text keeps every value character for character.
// Called only on lines that already produced a finding or sit under a `$#` header, never on the bulk path.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/fields.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/line_tokens.hpp"

namespace sphdeck::grammar {

// Gives every token of `text`, moved `shift` columns left, the field that holds it whole. False when a
// token straddles two fields, lies outside the card's fields or in an unused one, two tokens share a
// field, or a value does not read as its field's type.
// `types`: one per field (an LS-DYNA card's field types, or an OpenRadioss card's cells as types).
bool place_tokens(std::string_view text, std::span<LineToken> tokens, std::span<const FixedField> slots,
                  std::span<const keywords::FieldType> types, int shift);

// The field types of an LS-DYNA card, in order.
std::vector<keywords::FieldType> field_types(const keywords::CardSpec& card);

struct LineShift {
    int columns = 0;               // > 0: the values sit right of their fields
    bool changes_reading = false;  // a value is cut, glued or read in another field as written
    bool from_header = false;      // decided by the `$#` header above the line
    std::string realigned;         // the line with every value moved back into its field
};

// The shift of a line of `card` (fields at `slots`) by at most 4 columns, or nullopt. Evidence: every
// value ends (or starts) exactly `columns` past its field's end (start) while read as is some value
// straddles a boundary; or `header` (the `$#` comment line above, OpenRadioss `#`, empty when none) names the fields
// right-aligned to their ends and the values all end `columns` past them.
// A card that starts with a long text field (a title) is never looked at: its blanks are text. A shift that
// would move a real (`1.0`) into an integer field is not taken: no certain reading.
std::optional<LineShift> find_shift(std::string_view text, std::string_view header, std::span<const FixedField> slots,
                                    std::span<const keywords::FieldType> types);
std::optional<LineShift> find_shift(std::string_view text, std::string_view header, std::span<const FixedField> slots,
                                    const keywords::CardSpec& card);

struct WrittenWidths {
    std::vector<FixedField> slots;  // where the values were written
    std::string described;          // "8-column fields", "8/16-column fields"
};

// Field widths a line was evidently written in instead of `format`'s: the card's layout in another
// format, or standard widths with every 10-column field written in 8. Every value must sit whole and
// aligned in its field there, while read in `format` some value straddles.
std::optional<WrittenWidths> find_written_widths(std::string_view text, const keywords::CardSpec& card,
                                                 CardFormat format);

// One value written across the end of its field: a right-aligned value pushed a column or a few
// right, `     0.002` typed `      0.002` (read as 0.00 and 2, silently). The run of characters reads as
// one number of the left field's type and fits in it; blanks stand before it inside the left field (a
// value from the field's first column is left-aligned, not pushed), its right part does not fill the
// next field (values packed full width touch legitimately), and every other value sits whole in a
// field of its own.
struct Straddle {
    std::size_t field = 0;                 // the field it runs across the end of
    std::size_t begin = 0, end = 0;        // 0-based [begin, end) of the value
    std::size_t overrun = 0;               // columns past the field's end
    std::optional<std::string> realigned;  // the line moved `overrun` left, when every value keeps its field
};
std::optional<Straddle> find_straddle(std::string_view text, std::span<const FixedField> slots,
                                      const keywords::CardSpec& card);

// The cheap test that makes a line worth find_straddle (it runs on every line the serial walk decodes):
// two non-blank characters touch across a field end, the left field starts with a blank and the next
// field does not end with a value.
inline bool may_straddle(std::string_view text, std::span<const FixedField> slots) {
    for (std::size_t i = 0; i + 1 < slots.size(); ++i) {
        const std::size_t b = std::size_t{slots[i].start} + slots[i].width;
        if (b >= text.size()) return false;
        if (text[b - 1] == ' ' || text[b] == ' ' || text[slots[i].start] != ' ' || slots[i + 1].start != b) continue;
        const std::size_t next_end = b + slots[i + 1].width;
        if (next_end > text.size() || text[next_end - 1] == ' ') return true;
    }
    return false;
}

// True when `text` reads cleanly in the fields at `slots` with every value aligned to its field.
bool reads_aligned(std::string_view text, std::span<const FixedField> slots, const keywords::CardSpec& card);

// `text` with each value moved from its field at `from` to the same field at `to` (right-aligned, text
// left-aligned); nullopt when a value does not fit or does not sit whole in one field of `from`.
std::optional<std::string> rewrite_fields(std::string_view text, std::span<const FixedField> from,
                                          std::span<const FixedField> to, const keywords::CardSpec& card);

// "8-column fields" or "8/16-column fields": the widths of `slots` in order, each once.
std::string describe_widths(std::span<const FixedField> slots);

}  // namespace sphdeck::grammar
