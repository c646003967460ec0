#include "engine/position_index.hpp"
#include "model/card_sequence.hpp"

#include "grammar/radioss/keyword_lookup.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>

#include "grammar/radioss/reader.hpp"
#include "model/radioss_card_sequence.hpp"

namespace sphdeck::engine {
namespace {

using keywords::CardRepeat;
using keywords::CardSpec;
namespace rad = grammar::radioss;

using model::CardSequence;
using model::read_by_reader;

}  // namespace

const grammar::Block* block_at(const grammar::RawDeck& deck, grammar::FileId file, std::uint32_t line) {
    const grammar::Block* found = nullptr;
    for (const grammar::Block& b : deck.blocks) {
        if (b.span.file != file) continue;
        if (b.span.line > line) break;  // blocks of one file come in line order
        found = &b;
    }
    return found;
}

grammar::CardLinePtr card_line_at(const grammar::RawDeck& deck, const grammar::Block& block, std::uint32_t line) {
    grammar::CardLinePtr begin = deck.begin_lines(block);
    grammar::CardLinePtr end = deck.end_lines(block);
    grammar::CardLinePtr at =
        std::lower_bound(begin, end, line, [](const grammar::CardLine& l, std::uint32_t n) { return l.line < n; });
    return at != end && at->line == line && at->file == block.span.file ? at : nullptr;
}

std::uint32_t block_last_line(const grammar::RawDeck& deck, const grammar::Block& block) {
    if (block.line_count == 0) return block.span.line;
    const grammar::CardLine& last = *(deck.end_lines(block) - 1);
    return last.file == block.span.file ? std::max(last.line, block.span.line) : block.span.line;
}

std::optional<keywords::KeywordMatch> decodable_match(const grammar::Block& block) {
    if (block.keyword.empty() || block.keyword[0] != '*' || read_by_reader(block.keyword)) return std::nullopt;
    auto match = keywords::find_keyword(block.keyword);
    if (!match || !match->unknown_options.empty() || match->schema->free_text) return std::nullopt;
    return match;
}

void walk_dyna_block(const grammar::RawDeck& deck, const grammar::Block& block, const DynaCardVisitor& visit) {
    auto match = decodable_match(block);
    if (!match) return;
    std::vector<diag::Diagnostic> dropped;
    model::CardDecoder decoder(deck, dropped);
    CardSequence sequence(*match);
    DynaCard card{*match, nullptr, nullptr, {}};
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
        card.card = sequence.next();
        if (!card.card) return;
        card.line = l;
        decoder.decode(block, *l, *card.card, card.values);
        dropped.clear();
        sequence.advance(*card.card, card.values);
        if (!visit(card)) return;
    }
}

std::optional<DynaCard> dyna_card_at(const grammar::RawDeck& deck, const grammar::Block& block,
                                     grammar::CardLinePtr line) {
    auto match = decodable_match(block);
    if (!match) return std::nullopt;
    std::vector<diag::Diagnostic> dropped;
    model::CardDecoder decoder(deck, dropped);
    CardSequence sequence(*match);
    DynaCard card{*match, nullptr, nullptr, {}};
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
        const CardSpec* spec = sequence.next();
        if (!spec) return std::nullopt;
        // A block of one repeated card (*NODE, *ELEMENT_SPH): every line is that card.
        if (sequence.only_repeats(*spec)) l = line;
        if (l == line) {
            card.card = spec;
            card.line = l;
            decoder.decode(block, *l, *spec, card.values);
            return card;
        }
        decoder.decode(block, *l, *spec, card.values);
        dropped.clear();
        sequence.advance(*spec, card.values);
    }
    return std::nullopt;
}

const keywords::CardSpec* dyna_card_after(const grammar::RawDeck& deck, const grammar::Block& block,
                                          grammar::CardLinePtr before) {
    auto match = decodable_match(block);
    if (!match) return nullptr;
    std::vector<diag::Diagnostic> dropped;
    model::CardDecoder decoder(deck, dropped);
    CardSequence sequence(*match);
    std::vector<model::FieldValue> values;
    grammar::CardLinePtr stop = before ? before + 1 : deck.begin_lines(block);
    for (grammar::CardLinePtr l = deck.begin_lines(block); l != stop; ++l) {
        const CardSpec* spec = sequence.next();
        if (!spec) return nullptr;
        if (sequence.only_repeats(*spec)) return spec;
        decoder.decode(block, *l, *spec, values);
        dropped.clear();
        sequence.advance(*spec, values);
    }
    return sequence.next();
}

const rad::KeywordSpec* radioss_keyword(const grammar::Block& block, std::size_t* prefix) {
    if (block.keyword.empty() || block.keyword[0] != '/') return nullptr;
    // The table the reader walks (model/radioss_decoder.cpp): hand-written or generated.
    const rad::KeywordLookup found = rad::lookup_keyword(block.keyword);
    if (prefix) *prefix = found.prefix_segments;
    return found.cards;
}

bool radioss_engine_block(const grammar::RawDeck& deck, const grammar::Block& block) {
    const grammar::FileId root = deck.sources.include_chain(block.span.file).front();
    if (rad::is_engine_file_name(deck.sources.file(root).display_name)) return true;
    // One-file decks: blocks before /END/ENGINE of the same file are the engine input.
    for (const grammar::Block* b = &block + 1; b < deck.blocks.data() + deck.blocks.size(); ++b)
        if (b->keyword == "/END/ENGINE" && deck.sources.include_chain(b->span.file).front() == root) return true;
    return false;
}

namespace {
// The walk of model/radioss_decoder.cpp's Walker: the title line, then the cards in the order of
// model::RadiossCardSequence. `target` set: only that
// line is decoded, and a single repeated card jumps straight to it.
template <typename Visit>
void radioss_walk(const grammar::RawDeck& deck, const grammar::Block& block, int version, grammar::CardLinePtr target,
                  Visit visit) {
    RadiossCard out;
    out.keyword = radioss_keyword(block);
    if (!out.keyword || !out.keyword->decoded) return;
    out.engine = radioss_engine_block(deck, block);
    if (out.keyword->engine != out.engine) return;
    out.version = out.engine ? rad::latest_version : version;
    const rad::FormatSpec& format = out.keyword->format_for(out.version);
    grammar::CardLinePtr l = deck.begin_lines(block);
    grammar::CardLinePtr end = deck.end_lines(block);
    if (out.keyword->title && !out.engine && !rad::is_v4(version) && l != end) {
        if (l == target) {
            out.title = true;
            visit(l, out);
            return;
        }
        ++l;
    }
    const auto& cards = format.cards;
    model::RadiossCardSequence sequence(cards);
    std::vector<diag::Diagnostic> dropped;
    model::RadiossCardDecoder decoder(deck, dropped);
    for (; l != end; ++l) {
        if (target && l > target) return;
        auto next = sequence.next(deck.text(*l));
        if (next.step == model::RadiossCardSequence::Step::Past) return;
        if (next.step == model::RadiossCardSequence::Step::Blank) continue;
        // One repeated card: every further line is read as it.
        if (target && next.index >= sequence.first_repeated() && sequence.one_repeated_card()) l = target;
        // Looking for one line: the others are decoded only where their values steer the walk
        // (the count of a LIST card, /INISPHCEL/FULL's nvarsph).
        const bool wanted = !target || l == target;
        if (wanted || sequence.needs_values(next.index)) {
            decoder.decode(*l, cards[next.index], out.version, out.engine, out.values, {},
                           out.keyword->trailing_checked);
            dropped.clear();
        }
        sequence.advance(next.index, out.values);
        if (!wanted) continue;
        out.card = &cards[next.index];
        if (!visit(l, out)) return;
    }
}
}  // namespace

void walk_radioss_block(const grammar::RawDeck& deck, const grammar::Block& block, int version,
                        const RadiossCardVisitor& visit) {
    radioss_walk(deck, block, version, nullptr, visit);
}

std::optional<RadiossCard> radioss_card_at(const grammar::RawDeck& deck, const grammar::Block& block,
                                           grammar::CardLinePtr line, int version) {
    std::optional<RadiossCard> found;
    radioss_walk(deck, block, version, line, [&](grammar::CardLinePtr, const RadiossCard& card) {
        found = card;
        return false;
    });
    return found;
}

std::optional<grammar::FileId> included_file(const grammar::SourceMap& sources, grammar::FileId file,
                                             std::uint32_t line) {
    for (grammar::FileId id = 0; id < sources.size(); ++id) {
        const auto& f = sources.file(id);
        if (f.parent == file && f.include_line == line) return id;
    }
    return std::nullopt;
}

std::optional<ParameterReference> parameter_definition_at(const grammar::RawDeck& deck, grammar::FileId file,
                                                          std::uint32_t line, std::uint32_t column) {
    for (const grammar::Parameter& p : deck.parameters.definitions())
        if (p.span.file == file && p.span.line == line && column >= p.span.column && column < p.span.end_column)
            return ParameterReference{p.name, p.span};
    return std::nullopt;
}

std::vector<ParameterReference> parameter_references(std::string_view text, grammar::FileId file, std::uint32_t line) {
    std::vector<ParameterReference> out;
    auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t at = text.find('&'); at != std::string_view::npos; at = text.find('&', at + 1)) {
        std::size_t end = at + 1;
        while (end < text.size() && name_char(text[end])) ++end;
        if (end == at + 1) continue;
        out.push_back(
            {std::string(text.substr(at + 1, end - at - 1)),
             grammar::Span{file, line, static_cast<std::uint32_t>(at + 1), static_cast<std::uint32_t>(end + 1)}});
    }
    return out;
}

std::optional<ParameterReference> parameter_reference_at(const grammar::SourceMap& sources, grammar::FileId file,
                                                         std::uint32_t line, std::uint32_t column) {
    if (file >= sources.size()) return std::nullopt;
    std::string_view text = sources.line_text(file, line);
    if (text.find('&') == std::string_view::npos) return std::nullopt;
    for (auto& reference : parameter_references(text, file, line))
        if (column >= reference.span.column && column < reference.span.end_column) return reference;
    return std::nullopt;
}

}  // namespace sphdeck::engine
