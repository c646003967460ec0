// Internal to edit/format_*: where the LS-DYNA and OpenRadioss formatters put their line changes, and
// the lines they must leave alone.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "edit/format_deck.hpp"
#include "edit/format_line.hpp"
#include "grammar/raw_deck.hpp"
#include "text/line_rewrite.hpp"

namespace sphdeck::edit::detail {

inline std::uint64_t line_key(grammar::FileId file, std::uint32_t line) { return (std::uint64_t{file} << 32) | line; }

struct FormatScope {
    const grammar::RawDeck& deck;
    const FormatOptions& options;
    std::unordered_set<grammar::FileId> files;                     // the files formatted
    std::unordered_map<std::uint64_t, std::string_view> doubtful;  // line key -> the finding's code
    // Set when the findings are not known (format_deck_without_findings): the first line asked about them
    // raises it, and the passes stop, their result unused (threads read it too).
    std::atomic<bool>* findings_needed = nullptr;

    bool formats(grammar::FileId file) const { return files.count(file) != 0; }
    bool abandoned() const { return findings_needed && findings_needed->load(std::memory_order_relaxed); }
    // Without the findings, a reading that may hold a misreading's cause gives up too: a cause (DK032 a
    // missing heading, DK033 a keyword without its '*', DK029/DK030 shifts) folds the findings of other
    // lines into notes, which hold those lines back even when laid out. Such readings show lines past a
    // block's cards, a heading or title of numbers, or a block the formatter does not lay out.
    void give_up() const {
        if (findings_needed) findings_needed->store(true, std::memory_order_relaxed);
    }
    const std::string_view* doubt(grammar::FileId file, std::uint32_t line) const {
        if (findings_needed) {
            findings_needed->store(true, std::memory_order_relaxed);
            return nullptr;
        }
        auto it = doubtful.find(line_key(file, line));
        return it == doubtful.end() ? nullptr : &it->second;
    }
};

bool has_letter(std::string_view text);  // an ASCII letter in it (a title, not a line of numbers)

// The `$#` line naming `card`'s fields over their columns at `slots`, as LS-PrePost writes it.
std::string field_header(std::span<const std::string_view> names, std::span<const grammar::FixedField> slots);
bool is_field_header(std::string_view text);  // a `$#` comment line

// Line changes of one pass (or one thread of it), merged into the result in line order.
struct LineChanges {
    std::vector<diag::TextEdit> changes;  // one whole line each (columns 1 to its length + 1)
    std::array<std::size_t, format_change_kinds> counts{};
    std::vector<KeptLine> kept;
    std::size_t kept_count = 0;

    void change(grammar::FileId file, std::uint32_t line, std::string_view old_text, std::string text,
                FormatChange kind) {
        changes.push_back(text::whole_line_edit(file, line, old_text.size(), std::move(text)));
        ++counts[static_cast<std::size_t>(kind)];
    }
    void keep(grammar::FileId file, std::uint32_t line, std::string_view why) {
        if (kept.size() < 1000) kept.push_back({file, line, std::string(why)});
        ++kept_count;
    }
    void append(LineChanges&& other);
};

// A card's columns: where its fields are written, their kinds, which read integers (bit i: field i).
struct CardCells {
    std::span<const grammar::FixedField> slots;
    std::span<const CellKind> kinds;
    std::uint64_t integer_fields = 0;
};

// How a card line of `text` lays out in `cells`; records the change or the doubt.
// `free_allowed`: the card has a field that is not text (a comma in a title is text); `no_comma_or_tab`:
// the caller scanned the line (grammar::scan_line), so a line laid out already is passed at once.
enum class CardLineState { Blank, Kept, Free, Fixed };
CardLineState format_card_line(const FormatScope& scope, const grammar::CardLine& line, std::string_view text,
                               const CardCells& cells, bool free_allowed, std::string& buffer, LineChanges& out,
                               bool no_comma_or_tab = false);

void format_dyna(const FormatScope& scope, LineChanges& out);
void format_radioss(const FormatScope& scope, LineChanges& out);

}  // namespace sphdeck::edit::detail
