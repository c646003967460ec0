#include "text/line_rewrite.hpp"

#include <algorithm>
#include <utility>

namespace sphdeck::text {

void write_in_field(std::string& line, std::size_t start, std::size_t width, std::string_view value, Align align) {
    const std::size_t at = align == Align::Right && value.size() < width ? start + width - value.size() : start;
    if (line.size() < at + value.size()) line.resize(at + value.size(), ' ');
    line.replace(at, value.size(), value);
}

void trim_trailing_blanks(std::string& line) {
    while (!line.empty() && line.back() == ' ') line.pop_back();
}

std::string shift_line(std::string_view line, int columns) {
    std::string out = columns > 0 ? std::string(line.substr(std::min(line.size(), static_cast<std::size_t>(columns))))
                                  : std::string(static_cast<std::size_t>(-columns), ' ') + std::string(line);
    trim_trailing_blanks(out);
    return out;
}

TextEdit whole_line_edit(FileId file, std::uint32_t line, std::size_t old_length, std::string replacement) {
    return TextEdit{Span{file, line, 1, static_cast<std::uint32_t>(old_length) + 1}, std::move(replacement)};
}

}  // namespace sphdeck::text
