// Renaming an id (a part, section, material, EOS, set, curve, node... of engine/id_lookup.hpp) or a
// *PARAMETER name everywhere the deck and its includes name it: the same places references finds.
// Only the id fields change, and each keeps its columns: a fixed-format value stays right-aligned
// (or left-aligned, as written) within its field, a free-format value is replaced where it stands.
// A new id wider than one of its fields, or one that already names a block of that kind, is refused
// with a message saying so: a rename never leaves a deck that reads differently from what was meant.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/check.hpp"

namespace sphdeck::engine {

// What the position of a rename request names.
struct RenameTarget {
    std::string kind;    // an id kind ("PART", "NODE"...), or "PARAMETER"
    std::string name;    // the id ("7") or the parameter's name
    grammar::Span span;  // where it stands under the cursor (a parameter reference: the name, no '&')
};

// One replacement in a file's text: bytes [column, end_column) of the line become `text`.
struct TextReplacement {
    grammar::Span span;
    std::string text;
};

// A rename's edits, or why there are none (`refusal` not empty).
struct RenamePlan {
    std::vector<TextReplacement> edits;
    std::string refusal;
};

// The id or parameter under a position (1-based line, byte column) when it can be renamed; nullopt
// when nothing renameable stands there, or `refusal` says why it cannot be (a Radioss node, whose
// /SPHCEL and element lines the id walk leaves out).
std::optional<RenameTarget> rename_target_at(const CheckResult& deck, grammar::FileId file, std::uint32_t line,
                                             std::uint32_t column, std::string* refusal = nullptr);

// The edits that rename `target` to `new_name` in every file the deck read.
RenamePlan plan_rename(const CheckResult& deck, const RenameTarget& target, std::string_view new_name);

// The replacement of the value at 0-based bytes [value_start, value_end) of `line` in the fixed field
// [field_start, field_start + width) by `value` (at most `width` bytes), keeping the value's alignment;
// the smallest replacement that does it, as 0-based [start, end) and its text. In free format the value
// is replaced where it stands. Exposed for the tests.
struct FieldReplacement {
    std::size_t start = 0, end = 0;
    std::string text;
};
FieldReplacement replace_in_field(std::string_view line, std::size_t field_start, std::size_t width,
                                  std::size_t value_start, std::size_t value_end, std::string_view value,
                                  bool free_format);

}  // namespace sphdeck::engine
