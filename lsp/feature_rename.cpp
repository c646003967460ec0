// textDocument/prepareRename and textDocument/rename: an id or a *PARAMETER name renamed in every file
// of the deck (engine/id_rename.hpp decides the edits and refuses what would change the deck's meaning).
#include <set>
#include <tuple>

#include "engine/id_rename.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {

nlohmann::json prepare_rename(const CheckedDeck& deck, grammar::FileId file, TextPosition position) {
    const auto& sources = deck.result.deck.sources;
    if (file >= sources.size()) return nullptr;
    const LineColumn at = line_column(sources, file, position);
    std::string refusal;
    auto target = engine::rename_target_at(deck.result, file, at.line, at.column, &refusal);
    if (!target && !refusal.empty()) throw FeatureError{error_code::request_failed, refusal};
    if (!target) return nullptr;
    return {{"range", range_json(sources, target->span)}, {"placeholder", target->name}};
}

nlohmann::json rename(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    const auto& sources = deck.result.deck.sources;
    TextPosition position;
    if (file >= sources.size() || !params.is_object() || !params.contains("position") ||
        !parse_position(params["position"], position))
        return nullptr;
    const auto name = params.find("newName");
    if (name == params.end() || !name->is_string())
        throw FeatureError{error_code::invalid_params, "rename: newName is missing"};
    const LineColumn at = line_column(sources, file, position);
    std::string refusal;
    auto target = engine::rename_target_at(deck.result, file, at.line, at.column, &refusal);
    if (!target)
        throw FeatureError{error_code::request_failed,
                           refusal.empty() ? "nothing to rename here: put the cursor on an id or a &parameter"
                                           : refusal};
    const engine::RenamePlan plan = engine::plan_rename(deck.result, *target, name->get<std::string>());
    if (!plan.refusal.empty()) throw FeatureError{error_code::request_failed, "cannot rename: " + plan.refusal};
    nlohmann::json changes = nlohmann::json::object();
    // A file included twice is two instances of one text: its edits are made once.
    std::set<std::tuple<std::string, std::uint32_t, std::uint32_t>> made;
    for (const auto& edit : plan.edits) {
        const std::string uri = uri_from_path(sources.file(edit.span.file).path);
        if (!made.emplace(uri, edit.span.line, edit.span.column).second) continue;
        changes[uri].push_back({{"range", range_json(sources, edit.span)}, {"newText", edit.text}});
    }
    return {{"changes", std::move(changes)}};
}

}  // namespace sphdeck::lsp
