// Rewriting one line of a deck: a value written into a field, a line shifted a few columns, the edit that
// replaces a whole line. The realign and shift fixes (grammar/, model/) and the formatter (edit/) write
// lines through these, so each step is written once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "text/source_map.hpp"
#include "text/text_edit.hpp"

namespace sphdeck::text {

enum class Align { Left, Right };

// Writes `value` into the field at 0-based columns [start, start + width) of `line`: right-aligned (its last
// character on the field's last column) or from the field's first column; a value as wide as its field or
// wider starts on the first column. The line grows with blanks to hold it; only the value's columns change.
void write_in_field(std::string& line, std::size_t start, std::size_t width, std::string_view value, Align align);

// `line` without its trailing blanks.
void trim_trailing_blanks(std::string& line);

// `line` moved `columns` left (> 0: its first `columns` characters dropped; the caller knows they are
// blanks) or right (< 0: blanks put in front), its trailing blanks dropped.
std::string shift_line(std::string_view line, int columns);

// The edit that replaces line `line` of `file`, `old_length` bytes long (no line break), by `replacement`:
// columns 1 to old_length + 1, so the line break stays.
TextEdit whole_line_edit(FileId file, std::uint32_t line, std::size_t old_length, std::string replacement);

}  // namespace sphdeck::text
