// Turns the generated CFG layouts (generated/radioss_layouts.cpp) into KeywordSpecs, once: every
// name is known, and the cards the generator followed are checked; the rest of a block ('x') is
// kept as text, unchecked.
#include <algorithm>
#include <charconv>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "grammar/radioss/generated_layouts.hpp"

namespace sphdeck::grammar::radioss::generated {
namespace {

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = s.find(sep, start);
        out.push_back(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) return out;
        start = end + 1;
    }
}

int to_int(std::string_view s) {
    int v = 0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return v;
}

// "NAME:I:10" → a cell of that kind and width ('B': unused columns).
FieldSpec field_of(std::string_view text) {
    const auto parts = split(text, ':');
    FieldSpec f;
    if (parts.size() < 3) return {"", Cell::Skip, 10};
    f.name = parts[0];
    f.width = static_cast<std::uint32_t>(to_int(parts[2]));
    if (parts.size() > 3 && !parts[3].empty()) f.link = parts[3][0];
    switch (parts[1].empty() ? 'B' : parts[1][0]) {
        case 'I': f.cell = Cell::Int; break;
        case 'R': f.cell = Cell::Real; break;
        case 'S': f.cell = Cell::Text; break;
        default: f.cell = Cell::Skip; f.name = {};
    }
    return f;
}

CardSpec unchecked() { return {{{"text", Cell::Line}}, Repeat::Repeated}; }

// "1?Ifail!0=FN:R:20,FT:R:20" → a card; nullopt for 'x' (the rest unchecked).
std::optional<CardSpec> card_of(std::string_view text) {
    if (text.empty() || text[0] == 'x') return std::nullopt;
    const std::size_t eq = text.find('=');
    CardSpec card;
    card.repeat = text[0] == 'r' ? Repeat::Repeated : Repeat::Once;
    const std::string_view head = text.substr(1, eq == std::string_view::npos ? 0 : eq - 1);
    if (!head.empty() && head[0] == '?') card.when = card.condition = head.substr(1);
    if (eq != std::string_view::npos && eq + 1 < text.size())
        for (std::string_view f : split(text.substr(eq + 1), ',')) card.fields.push_back(field_of(f));
    // A long text cell that ends its card (`%-100s` lines of /FUNCT_PYTHON, names) is the rest of
    // the line, as the title is.
    if (!card.fields.empty() && card.fields.back().cell == Cell::Text && card.fields.back().width >= 40)
        card.fields.back().cell = Cell::Line;
    return card;
}

// "v2026|t|cards" → the format and whether a title line follows the header.
FormatSpec format_of(std::string_view line, bool& title) {
    const auto parts = split(line, '|');
    FormatSpec format;
    format.since = to_int(parts[0].substr(1));
    title = parts.size() > 1 && parts[1] == "t";
    bool open = false;  // ends in an unchecked or repeated card: no line is "past the cards"
    if (parts.size() > 2 && !parts[2].empty())
        for (std::string_view c : split(parts[2], ';')) {
            auto card = card_of(c);
            if (!card) {
                format.cards.push_back(unchecked());
                open = true;
                break;
            }
            open = card->repeat == Repeat::Repeated;
            format.cards.push_back(std::move(*card));
        }
    if (!open) format.cards.push_back(unchecked());
    return format;
}

KeywordSpec keyword_of(const LayoutEntry& e) {
    KeywordSpec k;
    k.name = e.name;
    k.generated = true;
    k.source = "CFG files of the OpenRadioss starter (grammar/radioss/generated/radioss_layouts.cpp)";
    k.summary = "generated from the starter's CFG files";
    // Text past a card's last field is reported in the newest format only (model/radioss_decoder.cpp):
    // the CFG formats of older versions often end before columns decks of that version still fill.
    k.trailing_checked = true;
    const auto lines = split(e.body, '\n');
    k.engine = !lines.empty() && lines[0].find('e') != std::string_view::npos;
    std::vector<bool> titles;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        bool title = false;
        k.formats.push_back(format_of(lines[i], title));
        titles.push_back(title);
    }
    // The title line belongs to the keyword (read before the cards in decks of format 51 on):
    // the newest format says; a format of 51 or later that disagrees is not checked.
    k.title = !titles.empty() && titles.front();
    for (std::size_t i = 0; i < k.formats.size(); ++i)
        if (k.formats[i].since >= 51 && titles[i] != k.title) k.formats[i].cards = {unchecked()};
    if (k.engine) {
        // Engine lines are list-directed; their layouts are not checked (names only).
        k.decoded = false;
        k.title = false;
        for (FormatSpec& f : k.formats) f.cards = {unchecked()};
    }
    // Deck versions below the oldest format: no layout.
    if (k.formats.empty() || k.formats.back().since > 0) k.formats.push_back({0, {unchecked()}});
    return k;
}

bool compare(double value, std::string_view op, double number) {
    if (op == "=") return value == number;
    if (op == "!") return value != number;
    if (op == "<") return value < number;
    if (op == ">") return value > number;
    if (op == "<=") return value <= number;
    if (op == ">=") return value >= number;
    return false;
}

}  // namespace

bool is_engine_entry(const LayoutEntry& entry) {
    const std::string_view flags = entry.body.substr(0, entry.body.find('\n'));
    return flags.find('e') != std::string_view::npos;
}

const KeywordSpec* keyword_named(std::string_view name) {
    const auto all = layouts();
    auto it = std::lower_bound(all.begin(), all.end(), name,
                               [](const LayoutEntry& e, std::string_view n) { return e.name < n; });
    if (it == all.end() || it->name != name) return nullptr;
    static std::mutex guard;
    static std::vector<std::unique_ptr<KeywordSpec>> built(all.size());
    const std::lock_guard<std::mutex> lock(guard);
    auto& slot = built[static_cast<std::size_t>(it - all.begin())];
    if (!slot) slot = std::make_unique<KeywordSpec>(keyword_of(*it));
    return slot.get();
}

std::span<const KeywordSpec> keywords() {
    static const std::vector<KeywordSpec> all = [] {
        std::vector<KeywordSpec> out;
        out.reserve(layouts().size());
        for (const LayoutEntry& e : layouts()) out.push_back(keyword_of(e));
        return out;
    }();
    return all;
}

bool condition_holds(std::string_view condition, const EarlierValues& earlier) {
    if (condition.empty()) return true;
    for (std::string_view part : split(condition, '&')) {
        const std::size_t op = part.find_first_of("=!<>");
        if (op == std::string_view::npos || op == 0) return false;
        std::size_t number_at = op + 1;
        if (number_at < part.size() && part[number_at] == '=') ++number_at;
        double number = 0.0;
        const std::string text(part.substr(number_at));
        try {
            number = std::stod(text);
        } catch (...) {
            return false;
        }
        if (!compare(earlier(part.substr(0, op)), part.substr(op, number_at - op), number)) return false;
    }
    return true;
}

}  // namespace sphdeck::grammar::radioss::generated
