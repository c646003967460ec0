#include "grammar/dyna/deck_reader.hpp"

#include <cctype>

#include "grammar/dyna/parameter_cards.hpp"
#include "grammar/parameters.hpp"

namespace sphdeck::grammar::dyna {

namespace {
std::string_view strip_cr(const char* begin, const char* end) {
    std::string_view s(begin, static_cast<std::size_t>(end - begin));
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    return s;
}
bool is_blank_text(std::string_view s) {
    for (char c : s)
        if (c != ' ' && c != '\t' && c != '\r') return false;
    return true;
}
CardFormat format_of_suffix(char suffix, CardFormat inherited) {
    switch (suffix) {
        case '+': return CardFormat::Long;
        case '%': return CardFormat::I10;
        case '-': return CardFormat::Standard;
        default: return inherited;
    }
}
}  // namespace

DeckReader::DeckReader(RawDeck& deck, const ReaderOptions& options) : deck_(deck), options_(options) {
    for (const auto& p : options.include_paths) {
        include_paths_.emplace_back(p);
        include_path_origins_.emplace_back("-I or include-paths");
    }
}

Span DeckReader::span_of(const char* begin, const char*, std::size_t column_begin, std::size_t column_end) const {
    (void)begin;
    const OpenFile& f = stack_.back();
    return Span{f.id, f.line, static_cast<std::uint32_t>(column_begin + 1), static_cast<std::uint32_t>(column_end + 1)};
}

void DeckReader::report(const char* code, diag::Severity severity, std::string message, Span span) {
    deck_.diagnostics.push_back(diag::Diagnostic{code, severity, std::move(message), span, {}});
}

// Lines after *END are ignored; the first non-blank one is reported (DK017).
bool DeckReader::after_end(const char* begin, const char* end) {
    OpenFile& f = current();
    if (!f.ended) return false;
    std::string_view text = strip_cr(begin, end);
    if (!f.reported_after_end && !is_blank_text(text)) {
        f.reported_after_end = true;
        report("DK017", diag::Severity::Info, "content after *END is ignored",
               span_of(begin, end, 0, std::max<std::size_t>(text.size(), 1)));
    }
    return true;
}

void DeckReader::on_comment() { ++current().line; }

void DeckReader::on_pgp_begin(const char* begin, const char* end) {
    OpenFile& f = current();
    ++f.line;
    if (after_end(begin, end)) return;
    f.in_encrypted = true;
    report("DK022", diag::Severity::Info, "encrypted content is skipped and not checked",
           span_of(begin, end, 0, strip_cr(begin, end).size()));
}

void DeckReader::on_pgp_end(const char* begin, const char* end) {
    OpenFile& f = current();
    if (!f.in_encrypted) return on_data(begin, end);
    ++f.line;
    f.in_encrypted = false;
}

void DeckReader::on_data(const char* begin, const char* end) {
    OpenFile& f = current();
    // A mapped file's pages behind the reader go back every few MB: reading a 1 GB deck keeps
    // the lines read, not the gigabyte, resident (the model is decoded from the text later).
    if (const auto at = static_cast<std::size_t>(begin - f.base); at >= f.released + release_step) {
        f.text->release(f.released, at);
        f.released = at;
    }
    ++f.line;
    if (f.in_encrypted || after_end(begin, end) || f.in_comment_block) return;
    std::string_view text = strip_cr(begin, end);
    if (!f.block) {
        if (!f.reported_stray_data && !is_blank_text(text)) {
            f.reported_stray_data = true;
            report("DK027", diag::Severity::Warning, "data line outside any keyword is ignored",
                   span_of(begin, end, 0, std::max<std::size_t>(text.size(), 1)));
        }
        return;
    }
    deck_.lines.push_back(CardLine{f.id, f.line, static_cast<std::uint32_t>(begin - f.base)});
    ++deck_.blocks[*f.block].line_count;
    ++deck_.stats.cards;
}

// An indented '*' line is a keyword only where a keyword can stand: not inside *COMMENT text
// (which ends at a '*' in column 1) or a *PARAMETER_EXPRESSION continuation ("  **(1/3)"),
// and only when a name follows.
bool DeckReader::indented_data(std::size_t star, const KeywordLineParts& parts) {
    if (star == 0) return false;
    if (parts.name.empty() || !std::isalpha(static_cast<unsigned char>(parts.name.front()))) return true;
    const OpenFile& f = stack_.back();
    if (f.in_comment_block) return true;
    return f.block && deck_.blocks[*f.block].keyword.rfind("*PARAMETER_EXPRESSION", 0) == 0;
}

void DeckReader::on_keyword(const char* begin, const char* end, const KeywordLineParts& parts) {
    std::size_t star = static_cast<std::size_t>(parts.name.data() - begin) - 1;
    if (indented_data(star, parts)) return on_data(begin, end);
    OpenFile& f = current();
    ++f.line;
    if (f.in_encrypted) return;
    if (f.ended && star == 0) f.dropped.note_dyna("*" + to_upper(parts.name));
    if (after_end(begin, end)) return;
    close_block();

    Block block;
    block.keyword.reserve(parts.name.size() + 1);
    block.keyword += '*';
    block.keyword += to_upper(parts.name);
    block.suffix = parts.suffix;
    block.format = format_of_suffix(parts.suffix, f.format);
    std::string_view args = parts.arguments;
    while (!args.empty() && (args.front() == ' ' || args.front() == '\t')) args.remove_prefix(1);
    while (!args.empty() && (args.back() == ' ' || args.back() == '\t' || args.back() == '\r')) args.remove_suffix(1);
    block.arguments = std::string(args);
    block.span = span_of(begin, end, star, star + 1 + parts.name.size());
    block.first_line = static_cast<std::uint32_t>(deck_.lines.size());
    block.scope = f.id;
    block.parameter_epoch = deck_.parameters.epoch();
    ++deck_.stats.keywords;

    if (star > 0) {
        report("DK020", diag::Severity::Warning, "keyword line does not start in column 1", block.span);
        // Safe: the line is read as this keyword already; in column 1 every reader reads it so.
        deck_.diagnostics.back().fixes.push_back(
            {"start the keyword line in column 1", true, {{span_of(begin, end, 0, star), ""}}});
    }
    if (parts.name.empty())
        report("DK001", diag::Severity::Error,
               "keyword line without a keyword name: LS-DYNA reads a '*' in column 1 as a keyword; write '$' for a "
               "comment",
               block.span);
    for (char c : parts.name) {
        if (std::islower(static_cast<unsigned char>(c))) {
            report("DK021", diag::Severity::Info, "keyword '" + block.keyword + "' written in lower case", block.span);
            // Safe: keyword names are read in upper case (block.keyword); the name only, not its arguments.
            deck_.diagnostics.back().fixes.push_back(
                {"write the keyword name in upper case",
                 true,
                 {{span_of(begin, end, star + 1, star + 1 + parts.name.size()), block.keyword.substr(1)}}});
            break;
        }
    }

    deck_.blocks.push_back(std::move(block));
    const Block& added = deck_.blocks.back();
    if (added.keyword == "*END") {
        f.ended = true;
        f.dropped.set_end(added.span);
        return;
    }
    f.in_comment_block = added.keyword == "*COMMENT";
    if (added.keyword == "*KEYWORD" || added.keyword.rfind("*KEYWORD_", 0) == 0) handle_keyword_line_arguments(added);
    f.block = deck_.blocks.size() - 1;
}

// At the end of a file: the warning for keyword blocks after its *END, which then stands for the
// information on the first line after it (grammar/dropped_after_end.hpp).
void DeckReader::report_dropped_blocks(std::size_t first_diagnostic) {
    current().dropped.report(deck_.diagnostics, first_diagnostic, "*END", stack_.size() > 1);
}

// Special keywords act when their block is complete: their data lines are known then, and
// an include read now keeps the blocks in deck order.
void DeckReader::close_block() {
    OpenFile& f = current();
    if (!f.block) return;
    std::size_t index = *f.block;
    f.block.reset();
    f.in_comment_block = false;
    const Block block = deck_.blocks[index];  // copy: includes append to deck_.blocks
    const std::string& k = block.keyword;
    if (k == "*INCLUDE" || k == "*INCLUDE_AUTO_OFFSET") {
        handle_include(block, false);
    } else if (k == "*INCLUDE_TRANSFORM") {
        handle_include(block, true);
    } else if (k == "*RVE_ANALYSIS_FEM") {
        // Its first card names the RVE mesh file (nodes, elements, parts, sets), which LS-DYNA
        // reads into the model: read like an include, so the ids the deck names there are known.
        handle_include(block, true);
    } else if (k == "*INCLUDE_PATH") {
        handle_include_path(block, false);
    } else if (k == "*INCLUDE_PATH_RELATIVE") {
        handle_include_path(block, true);
    } else if (k.rfind("*PARAMETER", 0) == 0) {
        define_parameters(deck_, block);
    }
}

}  // namespace sphdeck::grammar::dyna
