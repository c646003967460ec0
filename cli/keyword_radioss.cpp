#include "cli/keyword_radioss.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <fmt/format.h>

#include "grammar/radioss/cell_names.hpp"
#include "grammar/radioss/generated_layouts.hpp"
#include "grammar/radioss/id_kinds.hpp"
#include "grammar/radioss/keyword_lookup.hpp"

namespace sphdeck::cli {
namespace {

namespace rad = grammar::radioss;

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// The deck versions (Invers of /BEGIN) that read format `k` of the keyword (formats newest first).
std::string versions_text(const rad::KeywordSpec& keyword, std::size_t k) {
    const int since = keyword.formats[k].since;
    const int until = k == 0 ? 0 : keyword.formats[k - 1].since - 1;
    if (k == 0) return since == 0 ? "every deck version" : fmt::format("decks of Invers {} and later", since);
    if (since == 0) return fmt::format("decks of Invers up to {}", until);
    return fmt::format("decks of Invers {} to {}", since, until);
}

// The version whose cell widths show a format's columns: its own first version; the oldest
// format shows the 51 widths unless only V4 decks (Invers below 51) read it.
int columns_version(const rad::KeywordSpec& keyword, std::size_t k) {
    const int since = keyword.formats[k].since;
    if (since != 0) return since;
    return k > 0 && keyword.formats[k - 1].since <= 51 ? 44 : 51;
}

// What a generated cell's id names (FieldSpec::link).
std::string link_note(char link) {
    const std::string_view defined_by = rad::defined_by(rad::linked_kind(link));
    return defined_by.empty() ? std::string() : fmt::format("id of a {}", defined_by);
}

std::string radioss_card_notes(const rad::KeywordSpec& keyword, const rad::FormatSpec& format, std::size_t i) {
    const rad::CardSpec& card = format.cards[i];
    if (!card.count.empty())
        return fmt::format(
            "LIST: {} values in all, {} a line, as field {} of the group's first card says; no "
            "line for 0",
            card.count, card.fields.size(), card.count);
    if (card.repeat == rad::Repeat::Once && (card.present_if || !card.when.empty()))
        return fmt::format("once, only when {}; an absent card takes every default", card.condition);
    if (card.repeat == rad::Repeat::Once) return keyword.engine ? "once" : "once; an absent card takes every default";
    if (card.fields.size() == 1 && card.fields[0].cell == rad::Cell::Line && card.fields[0].name == "text")
        return "any further lines: kept as text, not checked";
    std::size_t first = i;
    while (first > 0 && format.cards[first - 1].repeat == rad::Repeat::Repeated) --first;
    const std::size_t group = format.cards.size() - first;
    if (group == 1) return "repeated: one line per item until the next keyword";
    return fmt::format("repeated: cards {}-{} repeat as a group until the next keyword", first + 1,
                       format.cards.size());
}

void print_card(const rad::CardSpec& card, int version, bool engine) {
    std::vector<std::array<std::string, 4>> rows{{"columns", "field", "type", "default and allowed values"}};
    const auto cells = rad::layout(card, version);
    for (std::size_t i = 0; i < card.fields.size() && i < cells.size(); ++i) {
        const rad::FieldSpec& f = card.fields[i];
        const bool to_end = f.cell == rad::Cell::Line;
        std::string columns = engine   ? std::to_string(i + 1)
                              : to_end ? fmt::format("{}-", cells[i].start + 1)
                                       : fmt::format("{}-{}", cells[i].start + 1, cells[i].start + cells[i].width);
        rows.push_back({std::move(columns), f.name.empty() ? "-" : std::string(f.name),
                        std::string(rad::cell_kind_name(f.cell)), f.link ? link_note(f.link) : std::string(f.note)});
    }
    if (engine) rows[0][0] = "value";
    std::array<std::size_t, 3> width{};
    for (const auto& row : rows)
        for (std::size_t c = 0; c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
    for (const auto& row : rows) {
        std::string line =
            fmt::format("  {:<{}}  {:<{}}  {:<{}}  {}", row[0], width[0], row[1], width[1], row[2], width[2], row[3]);
        while (!line.empty() && line.back() == ' ') line.pop_back();
        fmt::print("{}\n", line);
    }
}

}  // namespace

const rad::KeywordSpec* find_radioss_keyword(std::string_view name) {
    if (name.empty() || name.front() != '/') return nullptr;
    // The table the reader checks the cards with: hand-written, or generated where no hand-written
    // table names the keyword (a family table such as /PROP does not describe /PROP/SHELL).
    const std::string header = upper(name);
    const rad::KeywordLookup found = rad::lookup_keyword(header);
    if (found.cards) return found.cards;
    return rad::find_generated(header);
}

void print_radioss_keyword(const rad::KeywordSpec& keyword) {
    fmt::print("{}  (OpenRadioss {} keyword)\n", keyword.name, keyword.engine ? "engine" : "starter");
    if (!keyword.aliases.empty()) fmt::print("aliases: {}\n", fmt::join(keyword.aliases, ", "));
    if (!keyword.summary.empty()) fmt::print("{}\n", keyword.summary);
    if (!keyword.source.empty()) fmt::print("source: {}\n", keyword.source);
    if (!keyword.decoded) {
        fmt::print("\nknown and kept as is: its lines are not cut into fields or checked\n");
        return;
    }
    if (keyword.engine)
        fmt::print("engine deck (<run>_0001.rad): values list-directed, separated by blanks or commas\n");
    else if (keyword.title)
        fmt::print("a title line follows the header (in V4 decks, Invers below 51, the header path ends with it)\n");
    else
        fmt::print("no title line\n");
    for (std::size_t k = 0; k < keyword.formats.size(); ++k) {
        const rad::FormatSpec& format = keyword.formats[k];
        const int version = columns_version(keyword, k);
        std::string widths;
        if (!keyword.engine)
            widths = rad::is_v4(version) ? "; V4 cells: integers 8, reals 16 wide"
                     : format.since < 51 ? "; in V4 decks (Invers below 51) integers are 8 and reals 16 wide"
                                         : "";
        fmt::print("\nformat {} ({}{})\n", format.since, versions_text(keyword, k), widths);
        for (std::size_t i = 0; i < format.cards.size(); ++i) {
            fmt::print("Card {} ({})\n", i + 1, radioss_card_notes(keyword, format, i));
            print_card(format.cards[i], version, keyword.engine);
        }
    }
}

std::vector<std::pair<std::string, std::string>> radioss_list_rows() {
    std::vector<std::pair<std::string, std::string>> rows;
    for (const rad::KeywordSpec& k : rad::all_keywords()) {
        std::string names(k.name);
        if (!k.aliases.empty()) names += fmt::format(" ({})", fmt::join(k.aliases, ", "));
        std::string what = fmt::format("[radioss {}{}] {}", k.engine ? "engine" : "starter",
                                       k.decoded ? "" : ", kept as is", k.summary);
        rows.emplace_back(std::move(names), std::move(what));
    }
    for (const rad::KeywordSpec& k : rad::generated::keywords()) {
        std::size_t segments = 0;
        const rad::KeywordSpec* hand = rad::find_keyword(k.name, &segments);
        if (hand && hand->name == k.name) continue;  // the hand-written table's row says it
        rows.emplace_back(std::string(k.name),
                          fmt::format("[radioss {}, from the CFG files]", k.engine ? "engine" : "starter"));
    }
    std::sort(rows.begin(), rows.end());
    return rows;
}

std::string radioss_suggestion(std::string_view name) {
    const auto best = rad::suggest_keyword(upper(name));
    return best ? fmt::format("; did you mean {}?", *best) : "";
}

}  // namespace sphdeck::cli
