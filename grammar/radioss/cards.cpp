#include "grammar/radioss/cards.hpp"

#include <algorithm>

namespace sphdeck::grammar::radioss {
namespace {

const std::vector<KeywordSpec>& table() {
    static const std::vector<KeywordSpec> keywords = [] {
        std::vector<KeywordSpec> out;
        detail::add_mesh_keywords(out);
        detail::add_property_keywords(out);
        detail::add_sph_keywords(out);
        return out;
    }();
    return keywords;
}

// `header` starts with `prefix` on whole segments: "/MAT" matches "/MAT/LAW6/1", not "/MATX".
bool matches(std::string_view header, std::string_view prefix) {
    return header.size() >= prefix.size() && header.compare(0, prefix.size(), prefix) == 0 &&
           (header.size() == prefix.size() || header[prefix.size()] == '/');
}

std::size_t count_card_segments(std::string_view prefix) {
    return static_cast<std::size_t>(std::count(prefix.begin(), prefix.end(), '/'));
}

}  // namespace

const FieldSpec* CardSpec::field(std::string_view name) const {
    for (const FieldSpec& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

std::size_t CardSpec::index(std::string_view name) const {
    for (std::size_t i = 0; i < fields.size(); ++i)
        if (fields[i].name == name) return i;
    return fields.size();
}

const FormatSpec& KeywordSpec::format_for(int version) const {
    for (const FormatSpec& f : formats)
        if (f.since <= version) return f;
    return formats.back();
}

std::uint32_t cell_width(Cell cell, int version) {
    const bool v4 = is_v4(version);
    switch (cell) {
        case Cell::Int:
        case Cell::Text:
        case Cell::Skip: return v4 ? 8 : 10;
        case Cell::Real:
        case Cell::Text20:
        case Cell::Skip20: return v4 ? 16 : 20;
        case Cell::Line: return line_width(version);
    }
    return 10;
}

std::uint32_t line_width(int version) { return is_v4(version) ? 80 : 100; }

std::vector<FixedField> layout(const CardSpec& card, int version) {
    std::vector<FixedField> out;
    std::uint32_t start = 0;
    for (const FieldSpec& f : card.fields) {
        // A Line cell takes the rest of the line, whatever its length (titles may run past 100).
        const std::uint32_t width = f.cell == Cell::Line ? 1u << 30 : f.width ? f.width : cell_width(f.cell, version);
        out.push_back({start, width});
        start += width;
    }
    return out;
}

std::vector<std::string_view> path_segments(std::string_view header) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < header.size()) {
        if (header[i] == '/') {
            ++i;
            continue;
        }
        std::size_t end = header.find('/', i);
        if (end == std::string_view::npos) end = header.size();
        out.push_back(header.substr(i, end - i));
        i = end;
    }
    return out;
}

const KeywordSpec* find_keyword(std::string_view header, std::size_t* prefix_segments) {
    const KeywordSpec* best = nullptr;
    std::size_t best_length = 0;
    for (const KeywordSpec& k : table()) {
        auto consider = [&](std::string_view prefix) {
            if (prefix.size() > best_length && matches(header, prefix)) best = &k, best_length = prefix.size();
        };
        consider(k.name);
        for (std::string_view alias : k.aliases) consider(alias);
    }
    if (best && prefix_segments) {
        std::string_view prefix = header.substr(0, best_length);
        *prefix_segments = count_card_segments(prefix);
    }
    return best;
}

std::span<const KeywordSpec> all_keywords() { return table(); }

}  // namespace sphdeck::grammar::radioss
