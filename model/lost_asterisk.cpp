#include "model/lost_asterisk.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "grammar/keywords/schema.hpp"
#include "grammar/parameters.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

constexpr std::size_t max_lost_lines = 8;  // per block

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A line of blank-separated numbers and nothing else (a card's values).
bool numbers_only(std::string_view text) {
    bool any = false;
    std::size_t at = 0;
    while (at < text.size()) {
        while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\r')) ++at;
        std::size_t end = at;
        while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != '\r') ++end;
        if (end == at) break;
        const std::string_view word = text.substr(at, end - at);
        if (word.find_first_not_of("0123456789+-.eEdD") != std::string_view::npos ||
            word.find_first_of("0123456789") == std::string_view::npos)
            return false;
        any = true;
        at = end;
    }
    return any;
}

// A line that reads as the first card of `keyword` in fixed columns: each number field blank or a
// number, at least one written, text fields anything (*SET_SEGMENT's SOLVER "MECH"). Options' cards
// before the base ones (a title, an id card) are not tried: the plain numbers test covers most of them.
bool fits_first_card(std::string_view text, const std::string& keyword) {
    const auto match = keywords::find_keyword(keyword);
    if (!match || match->schema->cards.empty() || match->schema->free_text) return false;
    if (text.find_first_of(",\t") != std::string_view::npos) return false;
    bool any = false;
    for (const keywords::FieldSpec& f : match->schema->cards.front().fields) {
        if (f.column - 1u >= text.size()) break;
        std::string_view field = text.substr(f.column - 1u, f.width);
        const std::size_t first = field.find_first_not_of(" \r");
        if (first == std::string_view::npos) continue;
        field = field.substr(first, field.find_last_not_of(" \r") - first + 1);
        if (f.type != keywords::FieldType::Integer && f.type != keywords::FieldType::Real) continue;
        if (!numbers_only(field) || field.find(' ') != std::string_view::npos) return false;
        any = true;
    }
    const std::size_t width = match->schema->cards.front().line_width;
    return any && (text.size() <= width || text.substr(width).find_first_not_of(" \r") == std::string_view::npos);
}

// The reading findings a block's misread lines make.
bool asterisk_finding(std::string_view code) { return follows_from_shift(code) || code == "DK009"; }

}  // namespace

std::optional<std::string> keyword_without_asterisk(std::string_view text) {
    if (text.empty() || !std::isalpha(static_cast<unsigned char>(text.front()))) return std::nullopt;
    std::size_t end = 0;
    while (end < text.size() && name_char(text[end])) ++end;
    if (end < 3 || text.substr(end).find_first_not_of(" \t\r") != std::string_view::npos) return std::nullopt;
    std::string keyword = "*" + grammar::to_upper(text.substr(0, end));
    for (std::string_view frame : {"*END", "*KEYWORD", "*TITLE", "*COMMENT"})
        if (keyword == frame) return std::nullopt;
    const auto match = keywords::find_keyword(keyword);
    if (!match || !match->unknown_options.empty()) return std::nullopt;
    return keyword;
}

std::optional<LostAsteriskLine> lost_asterisk_line(grammar::FileId file, std::uint32_t line, std::string_view text,
                                                   bool read_as_text) {
    auto keyword = keyword_without_asterisk(text);
    if (!keyword) return std::nullopt;
    return LostAsteriskLine{file, line, std::string(text.substr(0, text.find_first_of(" \t\r"))), std::move(*keyword),
                            read_as_text};
}

void note_lost_in_unread(const grammar::RawDeck& deck, const grammar::Block& block, grammar::CardLinePtr from,
                         std::vector<LostAsteriskLine>& out) {
    const bool titled = block.keyword.find("TITLE") != std::string::npos;
    for (grammar::CardLinePtr l = from; l != deck.end_lines(block) && out.size() < max_lost_lines; ++l) {
        if (titled && l == deck.begin_lines(block)) continue;
        if (auto lost = lost_asterisk_line(l->file, l->line, deck.text(*l), false)) out.push_back(std::move(*lost));
    }
}

void note_lost_in_comment(const grammar::RawDeck& deck, const grammar::Block& block,
                          std::vector<LostAsteriskLine>& out) {
    constexpr std::uint32_t max_comment_lines = 10000;  // a longer comment is a document, not a slip's victim
    const grammar::FileId file = block.span.file;
    const std::string_view text = deck.sources.file(file).text;
    // From the last card line before the comment in its file (no index of every line of a big deck), on to
    // the *COMMENT line, then its text up to the next keyword line.
    std::size_t at = 0;
    std::uint32_t n = 1;
    if (block.first_line > 0 && deck.lines[block.first_line - 1].file == file &&
        deck.lines[block.first_line - 1].line < block.span.line) {
        at = deck.lines[block.first_line - 1].offset;
        n = deck.lines[block.first_line - 1].line;
    }
    std::optional<LostAsteriskLine> pending;  // a keyword name, waiting for the next text line
    for (; at < text.size() && n <= block.span.line + max_comment_lines && out.size() < max_lost_lines; ++n) {
        const std::size_t eol = std::min(text.find('\n', at), text.size());
        std::string_view line = text.substr(at, eol - at);
        at = eol + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (n <= block.span.line || (!line.empty() && line.front() == '$')) continue;
        if (!line.empty() && line.front() == '*') break;  // the comment ends at the next keyword line
        if (pending && (numbers_only(line) || fits_first_card(line, pending->keyword)))
            out.push_back(std::move(*pending));
        pending = lost_asterisk_line(file, n, line, false);
    }
}

void diagnose_lost_asterisks(const grammar::RawDeck& deck, const grammar::Block& block,
                             std::span<const LostAsteriskLine> lines, std::vector<diag::Diagnostic>& out,
                             std::size_t from) {
    if (lines.empty()) return;
    const std::uint32_t block_end =
        block.line_count > 0 ? deck.lines[block.first_line + block.line_count - 1].line + 1 : lines.back().line + 1;
    std::vector<diag::Diagnostic> causes;
    std::vector<bool> folded(out.size(), false);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const LostAsteriskLine& at = lines[k];
        // The lines it stands for: from it to the next such line, or the block's end.
        const std::uint32_t until = k + 1 < lines.size() ? lines[k + 1].line : std::max(block_end, at.line + 1);
        auto in_range = [&](const diag::Diagnostic& d, bool after_only) {
            return d.span.file == at.file && d.span.line >= at.line + (after_only ? 1 : 0) && d.span.line < until &&
                   asterisk_finding(d.code);
        };
        // A compound name (SECTION_SOLID, ELEMENT_SHELL) is no title a person gives; a plain word (NODE) may be.
        const bool compound = at.keyword.find('_') != std::string::npos;
        if (at.read_as_text && !compound &&
            std::none_of(out.begin() + static_cast<std::ptrdiff_t>(from), out.end(),
                         [&](const diag::Diagnostic& d) { return in_range(d, true); }))
            continue;
        const std::size_t after = until - at.line - 1;
        diag::Diagnostic d{
            "DK033",
            diag::Severity::Warning,
            fmt::format("'{}' is the keyword {} without its '*' (did you mean {}?): LS-DYNA reads this line{} as "
                        "more lines of {}, and {} is never read",
                        at.written, at.keyword, at.keyword,
                        after == 0 ? "" : " and the lines after it up to the next keyword", block.keyword, at.keyword),
            grammar::Span{at.file, at.line, 1, static_cast<std::uint32_t>(at.written.size() + 1)},
            {}};
        d.notes.push_back({block.span, fmt::format("the block {} is read on to the next keyword line", block.keyword)});
        // Unsafe: the word may be text the block reads (a title), which the deck's own misreadings only suggest.
        d.fixes.push_back({fmt::format("write the keyword line {}", at.keyword),
                           false,
                           {{grammar::Span{at.file, at.line, 1, 1}, "*"}}});
        for (std::size_t i = from; i < out.size(); ++i)
            if (!folded[i] && in_range(out[i], false)) {
                d.severity = std::max(d.severity, out[i].severity);
                fold_into(d, diag::Diagnostic(out[i]));
                folded[i] = true;
            }
        causes.push_back(std::move(d));
    }
    if (causes.empty()) return;
    std::size_t kept = from;
    for (std::size_t i = from; i < out.size(); ++i)
        if (!folded[i]) {
            if (kept != i) out[kept] = std::move(out[i]);
            ++kept;
        }
    out.resize(kept);
    for (auto& d : causes) out.push_back(std::move(d));
}

}  // namespace sphdeck::model
