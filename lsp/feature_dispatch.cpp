// The table from LSP method names to the feature functions of lsp/features.hpp, and the
// capabilities they announce. A feature joins by adding its row here.
#include "lsp/features.hpp"

#include <array>

namespace sphdeck::lsp {
namespace {
using Handler = nlohmann::json (*)(const CheckedDeck&, grammar::FileId, const nlohmann::json& params);

struct FeatureRow {
    std::string_view method;      // "textDocument/hover"
    std::string_view capability;  // its key in ServerCapabilities
    Handler handler;
};

// The request's position (params.position); a request without one gets a null answer.
template <nlohmann::json (*Feature)(const CheckedDeck&, grammar::FileId, TextPosition)>
nlohmann::json at_position(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    TextPosition position;
    if (!params.is_object() || !params.contains("position") || !parse_position(params["position"], position))
        return nullptr;
    return Feature(deck, file, position);
}

nlohmann::json references_of(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    TextPosition position;
    if (!params.is_object() || !params.contains("position") || !parse_position(params["position"], position))
        return nlohmann::json::array();
    bool declaration = false;
    if (auto context = params.find("context"); context != params.end() && context->is_object())
        if (auto d = context->find("includeDeclaration"); d != context->end() && d->is_boolean()) declaration = *d;
    return references(deck, file, position, declaration);
}

nlohmann::json symbols_of(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    return document_symbols(deck, file);
}
nlohmann::json folding_of(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    return folding_ranges(deck, file);
}

// One row a feature.
nlohmann::json rename_of(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    return rename(deck, file, params);
}

constexpr std::array<FeatureRow, 18> kFeatures{{
    {"textDocument/hover", "hoverProvider", at_position<hover>},
    {"textDocument/definition", "definitionProvider", at_position<definition>},
    {"textDocument/references", "referencesProvider", references_of},
    {"textDocument/completion", "completionProvider", at_position<completion>},
    {"textDocument/documentSymbol", "documentSymbolProvider", symbols_of},
    {"textDocument/foldingRange", "foldingRangeProvider", folding_of},
    {"textDocument/codeAction", "codeActionProvider", code_actions},
    {"textDocument/semanticTokens/full", "semanticTokensProvider", semantic_tokens_full},
    {"textDocument/semanticTokens/full/delta", "semanticTokensProvider", semantic_tokens_delta},
    {"textDocument/semanticTokens/range", "semanticTokensProvider", semantic_tokens_range},
    {"textDocument/inlayHint", "inlayHintProvider", inlay_hints},
    {"textDocument/signatureHelp", "signatureHelpProvider", at_position<signature_help>},
    {"textDocument/formatting", "documentFormattingProvider", formatting},
    {"textDocument/rangeFormatting", "documentRangeFormattingProvider", range_formatting},
    {"textDocument/prepareRename", "renameProvider", at_position<prepare_rename>},
    {"textDocument/rename", "renameProvider", rename_of},
    {"textDocument/documentLink", "documentLinkProvider", document_links},
    {"textDocument/codeLens", "codeLensProvider", code_lenses},
}};
}  // namespace

FeatureAnswer answer_feature(std::string_view method, const CheckedDeck& deck, grammar::FileId file,
                             const nlohmann::json& params) {
    for (const auto& row : kFeatures)
        if (row.method == method) return {true, row.handler(deck, file, params)};
    return {};
}

nlohmann::json feature_capabilities() {
    nlohmann::json capabilities = nlohmann::json::object();
    for (const auto& row : kFeatures) capabilities[std::string(row.capability)] = true;
    // Completion is asked for on these characters too (a keyword after '*', a value after ',').
    capabilities["completionProvider"] = {{"triggerCharacters", {"*", ","}}, {"resolveProvider", false}};
    capabilities["codeActionProvider"] = {{"codeActionKinds", {"quickfix", "source.fixAll.sphdeck"}}};
    // Typing a card line: blanks align a value, commas separate free-format ones.
    capabilities["signatureHelpProvider"] = {{"triggerCharacters", {" ", ","}}};
    capabilities["renameProvider"] = {{"prepareProvider", true}};
    capabilities["documentLinkProvider"] = {{"resolveProvider", false}};
    capabilities["codeLensProvider"] = {{"resolveProvider", false}};
    capabilities["workspaceSymbolProvider"] = true;  // answered by the server across decks (workspace_symbols)
    capabilities["semanticTokensProvider"] = {{"legend", semantic_tokens_legend()},
                                              {"range", true},
                                              {"full", {{"delta", true}}}};
    return capabilities;
}

}  // namespace sphdeck::lsp
