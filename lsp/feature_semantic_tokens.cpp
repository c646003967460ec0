// textDocument/semanticTokens/full, /full/delta and /range: lsp/semantic_tokens.* collects the
// tokens, here they are numbered by the legend and encoded as LSP's relative integers.
#include <functional>
#include <string>

#include "lsp/features.hpp"
#include "lsp/semantic_tokens.hpp"

namespace sphdeck::lsp {
namespace {

// A file longer than this gets the values of its big blocks (over kBigBlock card lines: nodes,
// particles) left out of a full request; editors that ask by range colour them as they scroll.
constexpr std::uint32_t kFullRequestLines = 100000;
constexpr std::uint32_t kBigBlock = 1000;

nlohmann::json encode(const grammar::SourceMap& sources, grammar::FileId file,
                      const std::vector<SemanticToken>& tokens) {
    std::vector<std::uint32_t> data;
    data.reserve(tokens.size() * 5);
    std::uint32_t previous_line = 0, previous_start = 0;  // 0-based
    std::uint32_t text_line = 0;
    std::string_view text;
    for (const SemanticToken& t : tokens) {
        if (t.line != text_line) text = sources.line_text(file, text_line = t.line);
        const std::uint32_t start = utf16_offset(text, t.column - 1);
        const std::uint32_t end = utf16_offset(text, t.column - 1 + t.length);
        if (end <= start) continue;
        const std::uint32_t line = t.line - 1;
        data.push_back(line - previous_line);
        data.push_back(line == previous_line ? start - previous_start : start);
        data.push_back(end - start);
        data.push_back(static_cast<std::uint32_t>(t.type));
        data.push_back(t.modifiers);
        previous_line = line;
        previous_start = start;
    }
    // The result id names the content: a delta request whose previous id matches gets no edits.
    std::size_t hash = data.size();
    for (std::uint32_t v : data) hash = hash * 1000003u ^ v;
    return {{"resultId", std::to_string(hash)}, {"data", std::move(data)}};
}

nlohmann::json whole_file(const CheckedDeck& deck, grammar::FileId file) {
    const auto& sources = deck.result.deck.sources;
    if (file >= sources.size()) return {{"data", nlohmann::json::array()}};
    const std::uint32_t lines = sources.line_count(file);
    TokenOptions options;
    if (lines > kFullRequestLines) options.max_block_lines = kBigBlock;
    return encode(sources, file, semantic_tokens(deck, file, {1, lines}, options));
}

}  // namespace

nlohmann::json semantic_tokens_full(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    return whole_file(deck, file);
}

nlohmann::json semantic_tokens_delta(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    nlohmann::json tokens = whole_file(deck, file);
    // Unchanged since the id the client holds: an empty delta; otherwise the whole set (LSP allows
    // answering a delta request with SemanticTokens).
    if (params.is_object() &&
        params.value("previousResultId", std::string()) == tokens.value("resultId", std::string()))
        return {{"resultId", tokens["resultId"]}, {"edits", nlohmann::json::array()}};
    return tokens;
}

nlohmann::json semantic_tokens_range(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    const auto& sources = deck.result.deck.sources;
    TextPosition start, end;
    if (!params.is_object() || !params.contains("range") || !params["range"].is_object() ||
        !parse_position(params["range"].value("start", nlohmann::json()), start) ||
        !parse_position(params["range"].value("end", nlohmann::json()), end) || file >= sources.size())
        return nullptr;
    // A range as long as a full request of a big file is capped the same way (editors ask for a screenful).
    TokenOptions options;
    if (end.line >= start.line && end.line - start.line > kFullRequestLines) options.max_block_lines = kBigBlock;
    nlohmann::json out = encode(sources, file, semantic_tokens(deck, file, {start.line + 1, end.line + 1}, options));
    out.erase("resultId");
    return out;
}

nlohmann::json semantic_tokens_legend() {
    nlohmann::json types = nlohmann::json::array(), modifiers = nlohmann::json::array();
    for (auto t : kTokenTypes) types.push_back(std::string(t));
    for (auto m : kTokenModifiers) modifiers.push_back(std::string(m));
    return {{"tokenTypes", std::move(types)}, {"tokenModifiers", std::move(modifiers)}};
}

}  // namespace sphdeck::lsp
