// textDocument/codeAction: for each sphdeck diagnostic of the request's context, the mends its finding
// carries (diag::Fix, the data `sphdeck check --fix` applies: DK029's moved line, DK002's realigned
// values...), then suppress its rule for the card (or block) or for the file with the existing comment
// directives (edit/suppression_fixes.hpp: `$ sphdeck: disable=CODE`, `disable-file=`; `#` in Radioss
// decks), fixes too. Every action is a diag::Fix turned into LSP edits here.
// No action is offered twice: findings sharing a range share their actions. With context.only asking
// for source.fixAll, one action applies every safe fix of the file (edit::choose_fixes, as the CLI).
#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <string>

#include "edit/fix_choice.hpp"
#include "edit/suppression_fixes.hpp"
#include "lint/registry.hpp"
#include "engine/position_index.hpp"
#include "grammar/file_paths.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

nlohmann::json action_position(std::uint32_t line, std::uint32_t character) {
    return {{"line", line}, {"character", character}};
}

nlohmann::json text_edit(std::uint32_t line, std::uint32_t start, std::uint32_t end_line, std::uint32_t end,
                         std::string text) {
    return {{"range", {{"start", action_position(line, start)}, {"end", action_position(end_line, end)}}},
            {"newText", std::move(text)}};
}

struct Request {
    const CheckedDeck& deck;
    grammar::FileId file;
    std::string uri;
    char comment;  // '$' LS-DYNA, '#' Radioss
};

// A diag::Fix as LSP edits on this file's text (UTF-16 columns); empty when it edits another file.
nlohmann::json lsp_edits(const Request& r, const diag::Fix& fix) {
    const auto& sources = r.deck.result.deck.sources;
    nlohmann::json edits = nlohmann::json::array();
    for (const diag::TextEdit& e : fix.edits) {
        if (e.span.file != r.file || e.span.line == 0) return nlohmann::json::array();
        const std::string_view text = sources.line_text(e.span.file, e.span.line);
        edits.push_back(text_edit(e.span.line - 1, utf16_offset(text, e.span.column - 1), e.span.line - 1,
                                  utf16_offset(text, e.span.end_column - 1), display_text(e.replacement)));
    }
    return edits;
}

std::string title_of(const diag::Fix& fix) {
    std::string title = fix.description;
    if (!title.empty()) title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(title[0])));
    return title;
}

// The findings the editor's diagnostic stands for: those of its code starting on its line, the one
// at its column first (several findings of a code may share a line).
std::vector<const diag::Diagnostic*> findings_of(const Request& r, const std::string& code, TextPosition start) {
    std::vector<const diag::Diagnostic*> out;
    const auto& sources = r.deck.result.deck.sources;
    for (const diag::Diagnostic& found : r.deck.result.diagnostics) {
        if (found.code != code || found.span.file != r.file || found.span.line != start.line + 1) continue;
        const std::string_view text = sources.line_text(r.file, found.span.line);
        const bool at_column = found.span.column > 0 && utf16_offset(text, found.span.column - 1) == start.character;
        out.insert(at_column ? out.begin() : out.end(), &found);
    }
    return out;
}

// A fix as a quick fix of the editor's diagnostic, safe ones preferred; nullopt when it edits another file.
std::optional<nlohmann::json> quick_fix(const Request& r, const diag::Fix& fix, const nlohmann::json& diagnostic) {
    nlohmann::json edits = lsp_edits(r, fix);
    if (edits.empty()) return std::nullopt;
    nlohmann::json a = {{"title", title_of(fix)},
                        {"kind", "quickfix"},
                        {"diagnostics", nlohmann::json::array({diagnostic})},
                        {"edit", {{"changes", {{r.uri, std::move(edits)}}}}}};
    if (fix.safe) a["isPreferred"] = true;
    return a;
}

// The mends the finding carries itself (diag::Fix: the same data `check --fix` applies).
void carried_fixes(const Request& r, const diag::Diagnostic& found, const nlohmann::json& diagnostic,
                   nlohmann::json& out) {
    for (const diag::Fix& fix : found.fixes)
        if (auto a = quick_fix(r, fix, diagnostic)) out.push_back(std::move(*a));
}

// "Fix all safe fixes in this file" (source.fixAll.sphdeck): one round of `check --fix` on this file,
// the fixes chosen as the CLI chooses them (edit::choose_fixes).
std::optional<nlohmann::json> fix_all(const Request& r) {
    const auto& sources = r.deck.result.deck.sources;
    const edit::FixRound round = edit::choose_fixes(sources, r.deck.result.diagnostics, edit::FixLevel::Safe);
    const auto found = round.edits.find(grammar::canonical_path(sources.file(r.file).path).string());
    if (found == round.edits.end()) return std::nullopt;
    diag::Fix all{"", true, {}};
    for (const diag::TextEdit& e : found->second) {
        all.edits.push_back(e);
        all.edits.back().span.file = r.file;  // the same path: a file included twice has one text
    }
    nlohmann::json edits = lsp_edits(r, all);
    if (edits.empty()) return std::nullopt;
    return nlohmann::json{{"title", fmt::format("Apply the safe fixes of sphdeck ({})", round.fixes)},
                          {"kind", "source.fixAll.sphdeck"},
                          {"edit", {{"changes", {{r.uri, std::move(edits)}}}}}};
}

// Whether the request's context.only (absent: everything but source actions) asks for `kind`.
bool wanted_action(const nlohmann::json& context, std::string_view kind) {
    const auto only = context.find("only");
    if (only == context.end() || !only->is_array()) return kind == "quickfix";
    for (const auto& k : *only) {
        if (!k.is_string()) continue;
        const std::string asked = k.get<std::string>();
        if (kind == asked || (kind.starts_with(asked) && kind[asked.size()] == '.')) return true;
    }
    return false;
}

// Adds `action` unless one with the same title and edit is there: several findings sharing a range
// (or one finding listed twice) get one action, which names each of their diagnostics.
void add_once(nlohmann::json& out, nlohmann::json action) {
    for (auto& existing : out) {
        if (existing["title"] != action["title"] || existing["edit"] != action["edit"]) continue;
        auto& list = existing["diagnostics"];
        if (action.contains("diagnostics"))
            for (const auto& d : action["diagnostics"])
                if (std::find(list.begin(), list.end(), d) == list.end()) list.push_back(d);
        return;
    }
    out.push_back(std::move(action));
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
    if (wanted_action(*context, "source.fixAll.sphdeck"))
        if (auto all = fix_all(r)) out.push_back(std::move(*all));
    const auto diagnostics = context->find("diagnostics");
    if (!wanted_action(*context, "quickfix") || diagnostics == context->end() || !diagnostics->is_array()) return out;
    nlohmann::json fixes = nlohmann::json::array(), suppressions = nlohmann::json::array();
    for (const auto& d : *diagnostics) {
        if (!d.is_object() || !d.contains("code") || !d["code"].is_string()) continue;
        if (auto source = d.find("source"); source != d.end() && *source != "sphdeck") continue;
        TextPosition start;
        if (!d.contains("range") || !d["range"].is_object() || !d["range"].contains("start") ||
            !parse_position(d["range"]["start"], start))
            continue;
        const std::string code = d["code"].get<std::string>();
        const auto found = findings_of(r, code, start);
        if (!found.empty()) {
            nlohmann::json carried = nlohmann::json::array();
            carried_fixes(r, *found.front(), d, carried);
            for (auto& a : carried) add_once(fixes, std::move(a));
        }
        const lint::RuleInfo* rule = lint::find_rule(code);
        if (!rule || rule->code != code) continue;  // a directive names rules the registry knows
        // Suppressing the rule, as fixes too (edit/suppression_fixes.hpp): for the card, for the file.
        const grammar::RawDeck& raw = deck.result.deck;
        for (const diag::Fix& fix : {edit::suppress_for_card(raw, file, start.line + 1, code, r.comment),
                                     edit::suppress_in_file(raw.sources, file, code, r.comment)})
            if (auto a = quick_fix(r, fix, d)) add_once(suppressions, std::move(*a));
    }
    // The mends first (what the user most likely wants), then the suppressions.
    for (auto& a : fixes) out.push_back(std::move(a));
    for (auto& a : suppressions) out.push_back(std::move(a));
    return out;
}

}  // namespace sphdeck::lsp
