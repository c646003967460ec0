#include "lsp/semantic_tokens.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <unordered_map>

#include "engine/id_lookup.hpp"

namespace sphdeck::lsp {
using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

namespace rad = grammar::radioss;

bool starts_with_nocase(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
    return true;
}

// [begin, end) of `text` without surrounding blanks.
std::pair<std::size_t, std::size_t> trimmed(std::string_view text, std::size_t from = 0) {
    std::size_t begin = std::min(from, text.size()), end = text.size();
    while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
    while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\r')) --end;
    return {begin, end};
}

class Collector {
public:
    Collector(const CheckedDeck& deck, grammar::FileId file, LineRange range)
        : raw_(deck.result.deck), file_(file), range_(range), radioss_(deck.result.model.radioss.has_value()) {}

    void add(std::uint32_t line, std::uint32_t column, std::uint32_t length, TokenType type,
             std::uint32_t modifiers = 0) {
        if (length == 0 || !range_.holds(line)) return;
        tokens_.push_back({line, column, length, type, modifiers});
    }
    void add(const grammar::Span& span, TokenType type, std::uint32_t modifiers = 0) {
        if (span.file != file_ || span.end_column <= span.column) return;
        add(span.line, span.column, span.end_column - span.column, type, modifiers);
    }

    // Comment lines, `$#` headers, Radioss `#include` names and the include lines of *INCLUDE.
    void lines() {
        const std::uint32_t last = std::min(range_.last, raw_.sources.line_count(file_));
        for (std::uint32_t line = range_.first; line <= last; ++line) {
            const std::string_view text = raw_.sources.line_text(file_, line);
            if (text.empty()) continue;
            const char c = text[0];
            if (radioss_ && starts_with_nocase(text, "#include")) continue;  // an include line: includes()
            if (c == '$' || (radioss_ && c == '#')) {
                const auto [begin, end] = trimmed(text);
                add(line, static_cast<std::uint32_t>(begin) + 1, static_cast<std::uint32_t>(end - begin),
                    TokenType::Comment, text.size() > 1 && text[1] == '#' && c == '$' ? kHeader : 0);
            }
        }
    }

    void includes() {
        for (grammar::FileId id = 0; id < raw_.sources.size(); ++id) {
            const auto& f = raw_.sources.file(id);
            if (f.parent != file_ || !range_.holds(f.include_line)) continue;
            const std::string_view text = raw_.sources.line_text(file_, f.include_line);
            const std::size_t from = starts_with_nocase(text, "#include") ? 8 : 0;
            const auto [begin, end] = trimmed(text, from);
            add(f.include_line, static_cast<std::uint32_t>(begin) + 1, static_cast<std::uint32_t>(end - begin),
                TokenType::String, kInclude);
        }
    }

    void keywords_and_parameters() {
        for (const grammar::Block* block : blocks_in_range(raw_, file_, range_)) add(block->span, TokenType::Keyword);
        for (const grammar::Parameter& p : raw_.parameters.definitions())
            if (p.span.file == file_) add(p.span, TokenType::Parameter, kDeclaration);
    }

    void values(const TokenOptions& options) {
        visit_card_lines(raw_, radioss_, file_, range_, {options.max_block_lines, false},
                         [&](const DecodedLine& decoded) {
                             if (decoded.dyna) dyna_line(*decoded.dyna);
                             if (decoded.radioss) radioss_line(*decoded.line, *decoded.radioss);
                         });
    }

    std::vector<SemanticToken> take() {
        std::sort(tokens_.begin(), tokens_.end(), [](const SemanticToken& a, const SemanticToken& b) {
            return a.line != b.line ? a.line < b.line : a.column < b.column;
        });
        std::vector<SemanticToken> out;
        out.reserve(tokens_.size());
        for (const SemanticToken& t : tokens_)  // the first of overlapping tokens stays
            if (out.empty() || out.back().line != t.line || out.back().column + out.back().length <= t.column)
                out.push_back(t);
        return out;
    }

private:
    void dyna_line(const DynaCard& card) {
        for (std::size_t i = 0; i < card.values.size(); ++i) {
            const model::FieldValue& v = card.values[i];
            if (!v.spec || v.spec->type == keywords::FieldType::Unused || !v.explicit_value) continue;
            std::uint32_t modifiers = i % 2 == 1 ? kOddField : 0;
            TokenType type = TokenType::Number;
            if (!v.text.empty() && v.text[0] == '&') {
                type = TokenType::Parameter;
            } else if (const auto& role = dyna_role(card.match.schema->name, *v.spec)) {
                type = TokenType::Variable;
                if (role->defines) modifiers |= kDeclaration;
            } else if (!v.spec->choices.empty() || !v.spec->text_choices.empty()) {
                type = TokenType::EnumMember;
            } else if (v.spec->type == keywords::FieldType::Text) {
                type = TokenType::String;
            } else if (v.spec->type == keywords::FieldType::Label) {
                type = TokenType::Variable;
            } else if (v.spec->type == keywords::FieldType::Real) {
                type = TokenType::Real;
            }
            add(v.span, type, modifiers);
        }
    }

    void radioss_line(const grammar::CardLine& line, const RadiossCard& card) {
        if (card.title) {
            const auto [begin, end] = trimmed(raw_.text(line));
            add(line.line, static_cast<std::uint32_t>(begin) + 1, static_cast<std::uint32_t>(end - begin),
                TokenType::String);
            return;
        }
        for (std::size_t i = 0; i < card.values.size(); ++i) {
            const model::RadiossValue& v = card.values[i];
            if (!v.spec || !v.explicit_value) continue;
            std::uint32_t modifiers = i % 2 == 1 ? kOddField : 0;
            TokenType type = TokenType::Number;
            switch (v.spec->cell) {
                case rad::Cell::Skip:
                case rad::Cell::Skip20: continue;
                case rad::Cell::Text:
                case rad::Cell::Text20:
                case rad::Cell::Line: type = TokenType::String; break;
                case rad::Cell::Real: type = TokenType::Real; break;
                case rad::Cell::Int: type = TokenType::Number; break;
            }
            if (!v.text.empty() && v.text[0] == '[') {
                type = TokenType::Parameter;
            } else if (v.spec->cell == rad::Cell::Int) {
                if (const auto& role = radioss_role(*v.spec)) {
                    type = TokenType::Variable;
                    if (role->defines) modifiers |= kDeclaration;
                }
            }
            add(v.span, type, modifiers);
        }
    }

    // Id roles, once per field spec (a *NODE block asks the same field a million times).
    const std::optional<IdRole>& dyna_role(std::string_view keyword, const keywords::FieldSpec& field) {
        auto [it, added] = roles_.try_emplace(&field);
        if (added) it->second = dyna_id_role(keyword, field);
        return it->second;
    }
    const std::optional<IdRole>& radioss_role(const rad::FieldSpec& field) {
        auto [it, added] = roles_.try_emplace(&field);
        if (added) it->second = radioss_id_role(field);
        return it->second;
    }

    const grammar::RawDeck& raw_;
    grammar::FileId file_;
    LineRange range_;
    bool radioss_;
    std::vector<SemanticToken> tokens_;
    std::unordered_map<const void*, std::optional<IdRole>> roles_;
};

}  // namespace

std::vector<SemanticToken> semantic_tokens(const CheckedDeck& deck, grammar::FileId file, LineRange range,
                                           const TokenOptions& options) {
    if (file >= deck.result.deck.sources.size() || range.last < range.first) return {};
    Collector collector(deck, file, range);
    collector.lines();
    collector.includes();
    collector.keywords_and_parameters();
    collector.values(options);
    return collector.take();
}

}  // namespace sphdeck::lsp
