// The LS-DYNA side of `sphdeck format`: keyword names upper case, each card line of a known keyword laid
// out in its card's columns (the block's widths), `$#` headers on request.
#include <omp.h>

#include <map>

#include "model/card_sequence.hpp"
#include "edit/format_sink.hpp"
#include "edit/laid_out_test.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/line_scan.hpp"
#include "model/card_decoder.hpp"
#include "model/missing_card.hpp"
#include "model/repeated_line.hpp"
#include "text/text_window.hpp"

namespace sphdeck::edit::detail {
namespace {

using keywords::CardRepeat;
using keywords::CardSpec;
using keywords::FieldType;

using model::CardSequence;
using model::read_by_reader;

CellKind dyna_kind_of(FieldType t) {
    switch (t) {
        case FieldType::Integer:
        case FieldType::Real: return CellKind::Number;
        case FieldType::Label: return CellKind::Label;
        case FieldType::Text: return CellKind::Text;
        case FieldType::Unused: return CellKind::Unused;
    }
    return CellKind::Text;
}

// A card's columns in one format, its cells' kinds and its header, computed once per card and format.
struct CardColumns {
    std::vector<grammar::FixedField> slots;
    std::vector<CellKind> kinds;
    std::uint64_t integer_fields = 0;  // bit i: field i reads an integer
    bool free_allowed = false;
    std::string header;
    CardCells cells() const { return {slots, kinds, integer_fields}; }
};

class DynaColumnCache {
public:
    const CardColumns& of(std::string_view keyword, const CardSpec& card, grammar::CardFormat format) {
        auto [it, added] = cache_.try_emplace({&card, format});
        if (!added) return it->second;
        CardColumns& c = it->second;
        c.slots = keywords::layout_to_write(keyword, card, format);
        std::vector<std::string_view> names;
        for (const auto& f : card.fields) {
            if (f.type == FieldType::Integer && c.kinds.size() < 64)
                c.integer_fields |= std::uint64_t{1} << c.kinds.size();
            c.kinds.push_back(dyna_kind_of(f.type));
            c.free_allowed = c.free_allowed || (f.type != FieldType::Text && f.type != FieldType::Unused);
            names.push_back(f.type == FieldType::Unused ? std::string_view{} : f.name);
        }
        c.header = field_header(names, c.slots);
        return c;
    }

private:
    std::map<std::pair<const CardSpec*, grammar::CardFormat>, CardColumns> cache_;
};

std::optional<keywords::KeywordMatch> decodable_match(const grammar::Block& block) {
    if (block.keyword.empty() || block.keyword[0] != '*' || read_by_reader(block.keyword)) return std::nullopt;
    auto match = keywords::find_keyword(block.keyword);
    if (!match || !match->unknown_options.empty() || match->schema->free_text) return std::nullopt;
    return match;
}

// Finds keyword lines by walking forward from the last card line seen in their file, so a deck of two
// million lines is not indexed (SourceMap::line_text would index every line up to *END, touching every
// page of the deck again).
class KeywordLines {
public:
    explicit KeywordLines(const grammar::RawDeck& deck) : deck_(deck) {}
    // The text of `line` of `file` (without "\r\n").
    std::string_view at(grammar::FileId file, std::uint32_t line) {
        const std::string_view text = deck_.sources.file(file).text;
        Cursor& c = cursors_[file];
        if (c.line > line) c = {};
        while (c.line < line && c.offset < text.size()) {
            const std::size_t nl = text.find('\n', c.offset);
            if (nl == std::string_view::npos) return {};
            c = {c.line + 1, nl + 1};
        }
        std::size_t end = std::min(text.find('\n', c.offset), text.size());
        if (end > c.offset && text[end - 1] == '\r') --end;
        return c.line == line ? text.substr(c.offset, end - c.offset) : std::string_view{};
    }
    // A card line seen: later keyword lines of its file are found from here.
    void seen(const grammar::CardLine& l) {
        Cursor& c = cursors_[l.file];
        if (l.line >= c.line) c = {l.line, l.offset};
    }

private:
    struct Cursor {
        std::uint32_t line = 1;
        std::size_t offset = 0;
    };
    const grammar::RawDeck& deck_;
    std::map<grammar::FileId, Cursor> cursors_;
};

// The keyword name upper case (LS-DYNA reads it in any case).
void keyword_case(const grammar::Block& block, KeywordLines& lines, LineChanges& out) {
    const grammar::Span& s = block.span;
    const std::string_view line = lines.at(s.file, s.line);
    if (s.end_column > line.size() + 1 || s.column == 0) return;
    std::string upper(line);
    bool changed = false;
    for (std::size_t i = s.column - 1; i < s.end_column - 1; ++i)
        if (upper[i] >= 'a' && upper[i] <= 'z') upper[i] = static_cast<char>(upper[i] - 'a' + 'A'), changed = true;
    if (changed) out.change(s.file, s.line, line, std::move(upper), FormatChange::KeywordCase);
}

// The line before a card line (a `$#` header?); empty on the file's first line.
std::string_view line_before(const grammar::RawDeck& deck, const grammar::CardLine& line) {
    const std::string_view text = deck.sources.file(line.file).text;
    if (line.offset == 0) return {};
    std::size_t end = line.offset - 1;                                       // its '\n'
    const std::size_t begin = end == 0 ? 0 : text.rfind('\n', end - 1) + 1;  // npos + 1 == 0
    if (end > begin && text[end - 1] == '\r') --end;
    return text.substr(begin, end - begin);
}

// The line break of the file after `line`'s text ("\r\n" where the file has it).
std::string_view line_break(const grammar::RawDeck& deck, const grammar::CardLine& line, std::size_t length) {
    const std::string_view file = deck.sources.file(line.file).text;
    const std::size_t at = std::size_t{line.offset} + length;
    return at < file.size() && file[at] == '\r' ? "\r\n" : "\n";
}

// `--headers`: the `$#` line above the first line of each run of one card: an existing `$#` line there
// is rewritten, otherwise one is inserted (in the same edit as the card line's own change).
void header_above(const FormatScope& scope, const grammar::CardLine& line, std::string_view text,
                  const std::string& header, LineChanges& out) {
    if (line.line > 1) {
        const std::string_view above = line_before(scope.deck, line);
        if (is_field_header(above)) {
            if (above != header) out.change(line.file, line.line - 1, above, header, FormatChange::Header);
            return;
        }
    }
    const std::string_view eol = line_break(scope.deck, line, text.size());
    if (!out.changes.empty() && out.changes.back().span.file == line.file &&
        out.changes.back().span.line == line.line) {
        out.changes.back().replacement.insert(0, header + std::string(eol));
        ++out.counts[static_cast<std::size_t>(FormatChange::Header)];
        return;
    }
    out.change(line.file, line.line, text, header + std::string(eol) + std::string(text), FormatChange::Header);
}

// Lines between two hand-backs of the deck's pages read (peak memory).
constexpr std::size_t lines_per_release = 16384;

// Every line from `from` on read as one repeated card (*NODE, *ELEMENT_SPH: millions of lines), laid
// out on all threads, each on a contiguous range, merged back in order.
void format_repeated(const FormatScope& scope, grammar::CardLinePtr from, grammar::CardLinePtr to,
                     const CardColumns& columns, LineChanges& out) {
    const std::size_t n = static_cast<std::size_t>(to - from);
    const int threads = n < 8192 ? 1 : omp_get_max_threads();
    std::vector<LineChanges> parts(static_cast<std::size_t>(threads));
    const CardCells cells = columns.cells();
    const LaidOutTest laid_out(cells.slots, cells.kinds);
#pragma omp parallel num_threads(threads)
    {
        const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
        const std::size_t team = static_cast<std::size_t>(omp_get_num_threads());
        const std::size_t begin = n * t / team, end = n * (t + 1) / team;
        std::string buffer;
        const grammar::SourceText& source = scope.deck.sources.file(from->file).text;
        std::size_t released = begin;
        std::size_t released_offset = begin < end ? from[begin].offset : 0;
        text::TextWindow window(source);  // the lines read through it (text/text_window.hpp)
        // One walk of the lines, each read once (a CardLinePtr jumped to line i looks its stretch up).
        grammar::CardLinePtr at = from + static_cast<std::ptrdiff_t>(begin);
        for (std::size_t i = begin; i < end; ++i, ++at) {
            const grammar::CardLine card = *at;
            // Most lines are laid out already: one pass over the text says so; the others are read as usual.
            std::optional<std::size_t> length = laid_out.length(window.from(card.offset, laid_out.look_ahead()));
            if (!length) {
                const grammar::ScannedLine line = grammar::scan_line(scope.deck, card);
                format_card_line(scope, card, line.text, cells, columns.free_allowed, buffer, parts[t],
                                 !line.comma_or_tab);
                length = line.text.size();
            }
            // As the reader does once the model is built: mapped pages read go back (peak memory).
            if (i + 1 - released == lines_per_release || i + 1 == end) {
                source.release(released_offset, card.offset + *length);
                released = i + 1;
                if (i + 1 < end) released_offset = (at + 1)->offset;
                if (scope.abandoned()) break;  // the findings are needed: this pass's result is not used
            }
        }
    }
    for (auto& p : parts) out.append(std::move(p));
}

void format_dyna_block(const FormatScope& scope, const grammar::Block& block, DynaColumnCache& columns,
                       LineChanges& out) {
    const auto match = decodable_match(block);
    if (!match) {
        if (block.line_count > 0) scope.give_up();  // lines it does not lay out: their findings unknown
        return;
    }
    const grammar::RawDeck& deck = scope.deck;
    std::vector<diag::Diagnostic> dropped;
    model::CardDecoder decoder(deck, dropped);
    CardSequence sequence(*match);
    std::vector<model::FieldValue> values;
    std::string buffer;
    const CardSpec* previous = nullptr;
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
        const CardSpec* card = sequence.next();
        if (!card) {  // past the block's cards: kept as written
            scope.give_up();
            return;
        }
        const CardColumns& c = columns.of(block.keyword, *card, block.format);
        if (sequence.only_repeats(*card) && !scope.options.headers) {
            if (scope.formats(l->file)) format_repeated(scope, l, deck.end_lines(block), c, out);
            return;
        }
        const std::string_view text = deck.text(*l);
        // A card cut above the line (DK035) or the line pasted twice (DK036): a misreading's cause, perhaps.
        if (scope.findings_needed && card->repeat != keywords::CardRepeat::Repeated &&
            ((!match->schema->generated && model::early_card_line(deck, block, l, *card, sequence.cards())) ||
             model::repeats_line_above(deck, block, l)))
            scope.give_up();
        if (scope.formats(l->file)) {
            const CardLineState state = format_card_line(scope, *l, text, c.cells(), c.free_allowed, buffer, out);
            // A line with a finding keeps its ruler: it may be the finding's evidence (DK035: the ruler names the
            // card the line was typed as, not the one it is read as).
            if (scope.options.headers && card != previous && state == CardLineState::Fixed &&
                !(!scope.findings_needed && scope.doubt(l->file, l->line)))
                header_above(scope, *l, text, c.header, out);
        }
        previous = card;
        // A card read once that makes a finding, or a card missing at the end: the block may misread, and the
        // finding that names the cause (two lines made one, DK037; a line broken in two, DK038) keeps its line.
        if (sequence.needs_values(*card) || (scope.findings_needed && card->repeat != keywords::CardRepeat::Repeated)) {
            decoder.decode(block, *l, *card, values);
            if (scope.findings_needed && !dropped.empty()) scope.give_up();
            dropped.clear();
        }
        sequence.advance(*card, values);
    }
    if (scope.findings_needed && sequence.missing_card()) scope.give_up();
}

}  // namespace

void format_dyna(const FormatScope& scope, LineChanges& out) {
    DynaColumnCache columns;
    KeywordLines keyword_lines(scope.deck);
    for (const grammar::Block& block : scope.deck.blocks) {
        if (block.keyword.empty() || block.keyword[0] != '*') continue;
        if (!scope.formats(block.span.file)) continue;
        if (scope.abandoned()) return;
        keyword_case(block, keyword_lines, out);
        format_dyna_block(scope, block, columns, out);
        if (block.line_count > 0) keyword_lines.seen(*(scope.deck.end_lines(block) - 1));
    }
}

}  // namespace sphdeck::edit::detail
