#include "model/radioss_other_formats.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace sphdeck::model {

namespace rad = grammar::radioss;

std::optional<OtherFormatField> field_of_other_format(const rad::KeywordSpec& table, const rad::FormatSpec& format,
                                                      std::size_t card, std::uint32_t first, std::uint32_t last,
                                                      int version) {
    for (const rad::FormatSpec& other : table.formats) {  // newest first
        if (&other == &format || card >= other.cards.size()) continue;
        const rad::CardSpec& c = other.cards[card];
        const auto positions = rad::layout(c, version);
        for (std::size_t k = 0; k < c.fields.size() && k < positions.size(); ++k) {
            const rad::FieldSpec& f = c.fields[k];
            if (f.cell == rad::Cell::Line || f.cell == rad::Cell::Skip || f.cell == rad::Cell::Skip20) continue;
            const std::uint32_t start = positions[k].start, end = positions[k].start + positions[k].width;
            if (start <= first && last <= end) return OtherFormatField{&other, &f, start + 1, end};
        }
    }
    return std::nullopt;
}

void settle_trailing_text(std::vector<diag::Diagnostic>& out, std::size_t from, const grammar::CardLine& line,
                          std::string_view text, const rad::KeywordSpec& table, const rad::FormatSpec& format,
                          std::size_t card, int version, bool version_known) {
    for (std::size_t k = from; k < out.size();) {
        diag::Diagnostic& d = out[k];
        if (d.code != "DK006" || d.span.file != line.file || d.span.line != line.line || d.span.column == 0) {
            ++k;
            continue;
        }
        const auto held = field_of_other_format(table, format, card, d.span.column - 1, d.span.end_column - 1, version);
        if (!version_known) {
            // Fields some version reads are no overflow: what lies past them still is.
            std::uint32_t first = d.span.column - 1, past = 0;
            while (first < d.span.end_column - 1) {
                const auto in = field_of_other_format(table, format, card, first, first + 1, version);
                if (!in) break;
                past = in->last_column;
                first =
                    static_cast<std::uint32_t>(std::min<std::size_t>(text.find_first_not_of(" \t", past), text.size()));
            }
            if (held || first >= d.span.end_column - 1) {
                out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
                continue;
            }
            if (past) {
                d.span.column = first + 1;
                d.message = fmt::format("text after column {} is past the fields of every format of {} and is ignored",
                                        past, table.name);
            }
            ++k;
            continue;
        }
        if (held && held->format->since < format.since) {
            d.severity = diag::Severity::Info;
            d.message = fmt::format(
                "{} in columns {}-{} is a field of {} format {} that format {} no longer reads: the starter "
                "ignores it (an export that still writes it does no harm)",
                held->field->name, held->first_column, held->last_column, table.name, held->format->since,
                format.since);
        }
        ++k;
    }
}

}  // namespace sphdeck::model
