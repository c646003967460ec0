// CSV for spreadsheets and scripts (RFC 4180): a header row, then one record per row of the
// columns, CRLF line ends, integers as written and reals at full precision ({:.17g}), so a
// value read back is the value written. Names are quoted only when they need it.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace sphdeck::io {

// A named column of plain values, viewed (not owned). Shared by the CSV and VTK writers.
struct Column {
    using Values = std::variant<std::span<const long long>, std::span<const double>, std::span<const std::uint32_t>>;
    std::string name;
    Values values;

    std::size_t size() const;
};

// Throws std::invalid_argument when the columns differ in length (a caller's bug), and
// std::runtime_error when the stream fails.
void write_csv(std::ostream& out, std::span<const Column> columns);
// Writes `path`; throws std::runtime_error naming the file when it cannot be written.
void write_csv_file(const std::string& path, std::span<const Column> columns);

// One CSV field: as is, or in double quotes (inner quotes doubled) when it holds a comma,
// a quote, CR or LF, or begins or ends with a space.
std::string csv_field(std::string_view text);

}  // namespace sphdeck::io
