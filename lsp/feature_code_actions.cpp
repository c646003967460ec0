// textDocument/codeAction: for each sphdeck diagnostic of the request's context, suppress its rule
// for the card (or block) or for the file with the existing comment directives
// (lint/suppressions.hpp: `$ sphdeck: disable=CODE`, `disable-file=`; `#` in Radioss decks), and
// realign values that stray over their columns where that fix is certain (grammar/realign.hpp), and the
// mends a finding carries itself (DK029, DK030).
#include <cctype>
#include <fmt/format.h>
#include <string>

#include "grammar/realign.hpp"
#include "lint/registry.hpp"
#include "lint/suppressions.hpp"
#include "lsp/deck_lookup.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {
namespace {

// Lines at the top of a file searched for a `disable-file=` directive to extend.
constexpr std::uint32_t kHeaderLines = 50;

nlohmann::json position(std::uint32_t line, std::uint32_t character) {
    return {{"line", line}, {"character", character}};
}

nlohmann::json text_edit(std::uint32_t line, std::uint32_t start, std::uint32_t end_line, std::uint32_t end,
                         std::string text) {
    return {{"range", {{"start", position(line, start)}, {"end", position(end_line, end)}}}, {"newText", std::move(text)}};
}

nlohmann::json action(std::string title, const nlohmann::json& diagnostic, const std::string& uri, nlohmann::json edit,
                      bool preferred = false) {
    nlohmann::json out = {{"title", std::move(title)},
                          {"kind", "quickfix"},
                          {"diagnostics", nlohmann::json::array({diagnostic})},
                          {"edit", {{"changes", {{uri, nlohmann::json::array({std::move(edit)})}}}}}};
    if (preferred) out["isPreferred"] = true;
    return out;
}

struct Request {
    const CheckedDeck& deck;
    grammar::FileId file;
    std::string uri;
    char comment;  // '$' LS-DYNA, '#' Radioss
};

// The UTF-16 column just after the last code of a well-formed directive of `scope` on a comment
// line (1-based `line`), or nullopt.
std::optional<std::uint32_t> directive_end(const Request& r, std::string_view text, std::uint32_t line,
                                           lint::Suppression::Scope scope) {
    if (text.empty() || (text[0] != r.comment && text[0] != '$')) return std::nullopt;
    lint::Suppression directive;
    std::vector<diag::Diagnostic> problems;
    if (!lint::parse_suppression(text, r.file, line, directive, problems) || !problems.empty() ||
        directive.scope != scope || directive.items.empty())
        return std::nullopt;
    return utf16_offset(text, directive.items.back().end_column - 1);
}

// "Suppress CODE in this file": a code added to the file's `disable-file=` directive near its
// top, else a directive line at the top (after a Radioss file's `#RADIOSS` line, which tells the
// format).
nlohmann::json file_suppression(const Request& r, const std::string& code, const nlohmann::json& diagnostic) {
    const auto& sources = r.deck.result.deck.sources;
    const std::uint32_t lines = std::min(sources.line_count(r.file), kHeaderLines);
    const std::string title = fmt::format("Suppress {} in this file", code);
    for (std::uint32_t l = 1; l <= lines; ++l)
        if (auto at = directive_end(r, sources.line_text(r.file, l), l, lint::Suppression::Scope::File))
            return action(title, diagnostic, r.uri, text_edit(l - 1, *at, l - 1, *at, "," + code));
    std::uint32_t line = 0;
    if (r.comment == '#' && sources.line_text(r.file, 1).rfind("#RADIOSS", 0) == 0) line = 1;
    return action(title, diagnostic, r.uri,
                  text_edit(line, 0, line, 0, fmt::format("{} sphdeck: disable-file={}\n", r.comment, code)));
}

// "Suppress CODE for this card": a `disable=` line just before the finding's line; before a
// keyword line it silences the whole block.
nlohmann::json card_suppression(const Request& r, const std::string& code, std::uint32_t line0,
                                const nlohmann::json& diagnostic) {
    const auto& raw = r.deck.result.deck;
    const grammar::Block* block = block_at(raw, r.file, line0 + 1);
    const bool keyword_line = block && block->span.line == line0 + 1;
    const std::string title =
        fmt::format("Suppress {} for this {}", code, keyword_line ? "keyword block" : "card");
    // A `disable=` directive just above takes the code too.
    if (line0 > 0) {
        const std::string_view above = raw.sources.line_text(r.file, line0);
        if (auto end = directive_end(r, above, line0, lint::Suppression::Scope::NextBlock))
            return action(title, diagnostic, r.uri, text_edit(line0 - 1, *end, line0 - 1, *end, "," + code));
    }
    return action(title, diagnostic, r.uri,
                  text_edit(line0, 0, line0, 0, fmt::format("{} sphdeck: disable={}\n", r.comment, code)));
}

// "Realign the values of this card into their columns" for a value glued across a field boundary.
std::optional<nlohmann::json> realign(const Request& r, std::uint32_t line0, const nlohmann::json& diagnostic) {
    if (r.comment != '$') return std::nullopt;  // LS-DYNA cards: the Radioss cell layouts differ per version
    const auto& raw = r.deck.result.deck;
    const grammar::Block* block = block_at(raw, r.file, line0 + 1);
    if (!block) return std::nullopt;
    const grammar::CardLine* line = card_line_at(raw, *block, line0 + 1);
    if (!line) return std::nullopt;
    auto card = dyna_card_at(raw, *block, *line);
    if (!card) return std::nullopt;
    const std::string_view text = raw.text(*line);
    auto fixed = grammar::realign_card(text, *card->card, block->format);
    if (!fixed) return std::nullopt;
    return action("Realign the values of this card into their columns", diagnostic, r.uri,
                  text_edit(line0, 0, line0, utf16_offset(text, static_cast<std::uint32_t>(text.size())), display_text(*fixed)),
                  true);
}

// The mends the finding itself carries (diag::Fix: DK029's realigned line, DK030's rewritten block), for
// the finding of `code` that starts on this line of this file.
void carried_fixes(const Request& r, const std::string& code, std::uint32_t line0, const nlohmann::json& diagnostic,
                   nlohmann::json& out) {
    const auto& sources = r.deck.result.deck.sources;
    for (const diag::Diagnostic& found : r.deck.result.diagnostics) {
        if (found.code != code || found.span.file != r.file || found.span.line != line0 + 1) continue;
        for (const diag::Fix& fix : found.fixes) {
            nlohmann::json edits = nlohmann::json::array();
            for (const diag::TextEdit& e : fix.edits) {
                if (e.span.file != r.file || e.span.line == 0) continue;
                const std::string_view text = sources.line_text(e.span.file, e.span.line);
                edits.push_back(text_edit(e.span.line - 1, utf16_offset(text, e.span.column - 1), e.span.line - 1,
                                          utf16_offset(text, e.span.end_column - 1), display_text(e.replacement)));
            }
            if (edits.empty()) continue;
            std::string title = fix.description;
            if (!title.empty()) title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(title[0])));
            nlohmann::json a = {{"title", std::move(title)},
                                {"kind", "quickfix"},
                                {"diagnostics", nlohmann::json::array({diagnostic})},
                                {"edit", {{"changes", {{r.uri, std::move(edits)}}}}}};
            if (fix.safe) a["isPreferred"] = true;
            out.push_back(std::move(a));
        }
        return;
    }
}

}  // namespace

nlohmann::json code_actions(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    nlohmann::json out = nlohmann::json::array();
    const auto& sources = deck.result.deck.sources;
    if (file >= sources.size() || !params.is_object()) return out;
    std::string uri = uri_from_path(sources.file(file).path);
    if (auto document = params.find("textDocument"); document != params.end() && document->is_object())
        if (auto u = document->find("uri"); u != document->end() && u->is_string()) uri = u->get<std::string>();
    const Request r{deck, file, uri, deck.result.model.radioss ? '#' : '$'};
    const auto context = params.find("context");
    if (context == params.end() || !context->is_object()) return out;
    const auto diagnostics = context->find("diagnostics");
    if (diagnostics == context->end() || !diagnostics->is_array()) return out;
    for (const auto& d : *diagnostics) {
        if (!d.is_object() || !d.contains("code") || !d["code"].is_string()) continue;
        if (auto source = d.find("source"); source != d.end() && *source != "sphdeck") continue;
        TextPosition start;
        if (!d.contains("range") || !d["range"].is_object() || !d["range"].contains("start") ||
            !parse_position(d["range"]["start"], start))
            continue;
        const std::string code = d["code"].get<std::string>();
        if (code == "DK002" || code == "DK003")
            if (auto fix = realign(r, start.line, d)) out.push_back(std::move(*fix));
        carried_fixes(r, code, start.line, d, out);
        const lint::RuleInfo* rule = lint::find_rule(code);
        if (!rule || rule->code != code) continue;  // a directive names rules the registry knows
        out.push_back(card_suppression(r, code, start.line, d));
        out.push_back(file_suppression(r, code, d));
    }
    return out;
}

}  // namespace sphdeck::lsp
