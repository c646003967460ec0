// `sphdeck format`: a read deck rewritten in its canonical layout as per-line text edits, so the CLI
// (in place, --check, --diff) and the editor (textDocument/formatting) share one result. LS-DYNA cards
// follow the keyword's layout in the block's widths (grammar/keywords), OpenRadioss cards the starter's
// cells (grammar/radioss); keyword names become upper case; `--headers` writes a `$#` line naming the
// fields above each card. Everything else keeps its bytes: comments, titles, blank lines, unknown or
// encrypted text, text fields, *INCLUDE and *PARAMETER blocks, and every line the reading found odd
// (a finding of the deck syntax on it) or whose values cannot be placed without doubt.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "edit/format_options.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::edit {

// How a line changed, for the summary.
enum class FormatChange : std::uint8_t { Realigned, TrailingBlanks, KeywordCase, Header, ToFixed };
inline constexpr std::size_t format_change_kinds = 5;
std::string_view to_string(FormatChange c);  // "realigned", "trailing blanks", ...

// A card line left exactly as written, and why.
struct KeptLine {
    grammar::FileId file = grammar::no_file;
    std::uint32_t line = 0;
    std::string reason;
};

struct FormatResult {
    std::vector<diag::TextEdit> edits;  // in file and line order; span.file is the file's id in the deck
    std::array<std::size_t, format_change_kinds> changes{};  // lines changed, by kind
    std::size_t kept = 0;                                    // card lines left as written
    std::vector<KeptLine> kept_lines;                        // the first of them (at most 1000)
};

// The files of `deck` to format: the deck's own files (depth 0), and with `includes` every included
// file too; a file included twice is formatted once (its first instance).
std::vector<grammar::FileId> files_to_format(const grammar::RawDeck& deck, bool includes);

// The edits that format `files` of `deck`; `findings` are the deck's findings (engine::check_deck's):
// a line with a finding that casts doubt on its layout (DK003 a value across a field, DK029 a shifted
// line, DK016 a tab...; RAD025, RAD030; any finding with a fix) is left as written.
FormatResult format_deck(const grammar::RawDeck& deck, const std::vector<diag::Diagnostic>& findings,
                         const std::vector<grammar::FileId>& files, const FormatOptions& options);

// The same result without the findings, when it does not depend on them: nullopt as soon as a card line
// would be asked whether a finding lies on it (a line not laid out already: it may change or be kept).
// `format --check` of a deck laid out already then needs only its reading, not the model and rules that
// make the findings (issue 40); on nullopt the caller checks the deck and calls format_deck.
std::optional<FormatResult> format_deck_without_findings(const grammar::RawDeck& deck,
                                                         const std::vector<grammar::FileId>& files,
                                                         const FormatOptions& options);

}  // namespace sphdeck::edit
