#include "io/csv_writer.hpp"

#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

namespace sphdeck::io {

std::size_t Column::size() const {
    return std::visit([](const auto& span) { return span.size(); }, values);
}

std::string csv_field(std::string_view text) {
    const bool quote = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                       (!text.empty() && (text.front() == ' ' || text.back() == ' '));
    if (!quote) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
    return out;
}

namespace {

void append_value(fmt::memory_buffer& buffer, const Column::Values& values, std::size_t row) {
    std::visit(
        [&](const auto& span) {
            using T = typename std::decay_t<decltype(span)>::value_type;
            if constexpr (std::is_floating_point_v<T>) {
                fmt::format_to(std::back_inserter(buffer), "{:.17g}", span[row]);
            } else {
                fmt::format_to(std::back_inserter(buffer), "{}", span[row]);
            }
        },
        values);
}

}  // namespace

void write_csv(std::ostream& out, std::span<const Column> columns) {
    const std::size_t rows = columns.empty() ? 0 : columns.front().size();
    for (const Column& c : columns)
        if (c.size() != rows)
            throw std::invalid_argument(
                fmt::format("csv column '{}' has {} values, expected {}", c.name, c.size(), rows));
    fmt::memory_buffer buffer;
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (i > 0) buffer.push_back(',');
        const std::string name = csv_field(columns[i].name);
        buffer.append(name.data(), name.data() + name.size());
    }
    buffer.append(std::string_view("\r\n"));
    for (std::size_t row = 0; row < rows; ++row) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            if (i > 0) buffer.push_back(',');
            append_value(buffer, columns[i].values, row);
        }
        buffer.append(std::string_view("\r\n"));
        if (buffer.size() > (1u << 20)) {
            out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
            buffer.clear();
        }
    }
    out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    if (!out) throw std::runtime_error("cannot write the CSV data");
}

void write_csv_file(const std::string& path, std::span<const Column> columns) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path));
    try {
        write_csv(out, columns);
    } catch (const std::runtime_error&) {
        throw std::runtime_error(fmt::format("cannot write '{}'", path));
    }
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

}  // namespace sphdeck::io
