#include "edit/format_deck.hpp"

#include <algorithm>
#include <set>

#include "edit/format_sink.hpp"
#include "grammar/file_paths.hpp"
#include "grammar/read_deck.hpp"
#include "lint/registry.hpp"

namespace sphdeck::edit {
namespace detail {

bool has_letter(std::string_view text) {
    return std::any_of(text.begin(), text.end(),
                       [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); });
}

void LineChanges::append(LineChanges&& other) {
    if (changes.empty()) {
        changes = std::move(other.changes);
    } else {
        changes.reserve(changes.size() + other.changes.size());
        changes.insert(changes.end(), std::make_move_iterator(other.changes.begin()),
                       std::make_move_iterator(other.changes.end()));
        other.changes = {};
    }
    for (std::size_t k = 0; k < counts.size(); ++k) counts[k] += other.counts[k];
    for (auto& k : other.kept)
        if (kept.size() < 1000) kept.push_back(std::move(k));
    kept_count += other.kept_count;
}

CardLineState format_card_line(const FormatScope& scope, const grammar::CardLine& line, std::string_view text,
                               const CardCells& cells, bool free_allowed, std::string& buffer, LineChanges& out,
                               bool no_comma_or_tab) {
    const auto slots = cells.slots;
    const auto kinds = cells.kinds;
    if (no_comma_or_tab && already_laid_out(text, slots, kinds)) return CardLineState::Fixed;
    if (grammar::is_blank(text)) return CardLineState::Blank;  // a blank card: every default, kept as written
    if (!free_allowed) {                                       // titles, headings, file names: their text as written
        if (scope.findings_needed && !has_letter(text)) scope.give_up();  // a heading of numbers (DK032)?
        return CardLineState::Fixed;
    }
    // Without the findings: a line laid out already in plain numbers is one no finding of the reading holds
    // back (a finding's line is kept even when laid out: DK004 `1.0` in an integer field).
    if (scope.findings_needed && plain_laid_out(text, slots, kinds, cells.integer_fields)) return CardLineState::Fixed;
    if (const std::string_view* code = scope.doubt(line.file, line.line)) {
        out.keep(line.file, line.line, std::string("finding ") + std::string(*code));
        return CardLineState::Kept;
    }
    if (scope.abandoned()) return CardLineState::Kept;  // the findings are needed: this pass's result is not used
    const bool free = free_allowed && grammar::is_free_format(text);
    if (free && !scope.options.to_fixed) return CardLineState::Free;  // free lines stay free
    const LineLayout laid =
        free ? free_to_fixed(text, slots, kinds, buffer) : layout_fixed_line(text, slots, kinds, buffer);
    if (laid.verdict == LineVerdict::Doubt) {
        out.keep(line.file, line.line, laid.doubt);
        return CardLineState::Kept;
    }
    if (laid.verdict == LineVerdict::Same || buffer == text) return CardLineState::Fixed;
    std::string_view trimmed = text;
    while (!trimmed.empty() && trimmed.back() == ' ') trimmed.remove_suffix(1);
    const FormatChange kind =
        free ? FormatChange::ToFixed : (buffer == trimmed ? FormatChange::TrailingBlanks : FormatChange::Realigned);
    out.change(line.file, line.line, text, buffer, kind);
    return CardLineState::Fixed;
}

std::string field_header(std::span<const std::string_view> names, std::span<const grammar::FixedField> slots) {
    std::string out = "$#";
    for (std::size_t i = 0; i < names.size() && i < slots.size(); ++i) {
        if (names[i].empty()) continue;
        const std::size_t end = std::size_t{slots[i].start} + slots[i].width;
        const std::size_t room = end > out.size() + 1 ? end - out.size() - 1 : 0;  // a blank before each name
        std::string_view name = names[i].substr(0, room);
        if (name.empty()) continue;
        out.append(end - out.size() - name.size(), ' ');
        for (char c : name) out += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    }
    return out;
}

bool is_field_header(std::string_view text) { return text.size() >= 2 && text[0] == '$' && text[1] == '#'; }

}  // namespace detail

std::string_view to_string(FormatChange c) {
    switch (c) {
        case FormatChange::Realigned: return "values realigned";
        case FormatChange::TrailingBlanks: return "trailing blanks";
        case FormatChange::KeywordCase: return "keyword case";
        case FormatChange::Header: return "field headers";
        case FormatChange::ToFixed: return "free to fixed";
    }
    return "?";
}

std::vector<grammar::FileId> files_to_format(const grammar::RawDeck& deck, bool includes) {
    std::vector<grammar::FileId> out;
    std::set<std::string> seen;
    for (grammar::FileId id = 0; id < deck.sources.size(); ++id) {
        const grammar::SourceFile& f = deck.sources.file(id);
        if (f.depth > 0 && !includes) continue;
        if (seen.insert(grammar::canonical_path(f.path).string()).second) out.push_back(id);  // by any name
    }
    return out;
}

namespace {

// Findings that say a line may not read as its author laid it out: those of the rules whose registry row
// says the layout is in doubt (lint::Layout::Doubtful), and any finding that offers a mend.
bool casts_doubt(const diag::Diagnostic& d) {
    static const std::set<std::string, std::less<>> codes = [] {
        std::set<std::string, std::less<>> doubtful;
        for (const lint::RuleInfo& rule : lint::all_rules())
            if (rule.layout == lint::Layout::Doubtful) doubtful.emplace(rule.code);
        return doubtful;
    }();
    return codes.count(d.code) != 0 || !d.fixes.empty();
}

// Both formatters, then the changes of their passes in file and line order.
FormatResult run_formatters(const detail::FormatScope& scope) {
    detail::LineChanges changes;
    if (grammar::format_of(scope.deck) == grammar::DeckFormat::Radioss)
        detail::format_radioss(scope, changes);
    else
        detail::format_dyna(scope, changes);

    // Keyword lines, headers and card lines come from different passes: in file and line order.
    const auto before = [](const diag::TextEdit& a, const diag::TextEdit& b) {
        return a.span.file != b.span.file ? a.span.file < b.span.file : a.span.line < b.span.line;
    };
    if (!std::is_sorted(changes.changes.begin(), changes.changes.end(), before))  // includes interleave files
        std::stable_sort(changes.changes.begin(), changes.changes.end(), before);
    FormatResult result;
    result.edits = std::move(changes.changes);
    result.changes = changes.counts;
    result.kept = changes.kept_count;
    result.kept_lines = std::move(changes.kept);
    return result;
}

}  // namespace

std::optional<FormatResult> format_deck_without_findings(const grammar::RawDeck& deck,
                                                         const std::vector<grammar::FileId>& files,
                                                         const FormatOptions& options) {
    std::atomic<bool> findings_needed{false};
    detail::FormatScope scope{deck, options, {files.begin(), files.end()}, {}, &findings_needed};
    FormatResult result = run_formatters(scope);
    if (findings_needed.load()) return std::nullopt;
    return result;
}

FormatResult format_deck(const grammar::RawDeck& deck, const std::vector<diag::Diagnostic>& findings,
                         const std::vector<grammar::FileId>& files, const FormatOptions& options) {
    detail::FormatScope scope{deck, options, {files.begin(), files.end()}, {}};
    // A finding's notes name more lines of the same doubt (a card's other non-numbers under one error):
    // they are kept too, else moving them changes which line the finding lands on, and a second
    // format moves another (fuzz format_dyna, 29 Nov 2026).
    const auto doubt = [&](const text::Span& span, const std::string& code) {
        if (span.valid() && scope.formats(span.file))
            scope.doubtful.emplace(detail::line_key(span.file, span.line), code);
    };
    for (const diag::Diagnostic& d : findings) {
        if (!d.span.valid() || !casts_doubt(d)) continue;
        doubt(d.span, d.code);
        for (const diag::Note& note : d.notes) doubt(note.span, d.code);
    }

    return run_formatters(scope);
}

}  // namespace sphdeck::edit
