// What the editor server answers about a checked deck, one function per request, each a pure
// function of the deck and the request's parameters that returns the LSP result as JSON (null when
// there is nothing to say). The server (lsp/server.*) finds the deck and the file a request is
// about, then calls these; they never read a file or write to the client.
// One file per feature: lsp/feature_hover.cpp, feature_definition.cpp, feature_completion.cpp,
// feature_symbols.cpp, feature_folding.cpp, feature_code_actions.cpp, feature_formatting.cpp,
// feature_rename.cpp, feature_document_links.cpp, feature_code_lens.cpp, feature_workspace_symbols.cpp.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "text/source_map.hpp"
#include "lsp/checked_deck.hpp"
#include "lsp/json_rpc.hpp"
#include "lsp/text_position.hpp"

namespace sphdeck::lsp {

// textDocument/hover: a keyword (what it is), a field (name, columns, type, default, allowed values,
// effective value), an id (what it names). Returns a Hover ({"contents": MarkupContent, "range"}) or null.
nlohmann::json hover(const CheckedDeck& deck, grammar::FileId file, TextPosition position);

// textDocument/definition: where the id, `&name` parameter or include file under the cursor is
// defined. Returns Location | Location[] | null.
nlohmann::json definition(const CheckedDeck& deck, grammar::FileId file, TextPosition position);

// textDocument/references: every place that names the same id (with the definition when
// `include_declaration`). Returns Location[] (possibly empty).
nlohmann::json references(const CheckedDeck& deck, grammar::FileId file, TextPosition position,
                          bool include_declaration);

// textDocument/completion: keyword names at the start of a line, allowed values of enum fields,
// ids that exist for id fields. Returns CompletionList.
nlohmann::json completion(const CheckedDeck& deck, grammar::FileId file, TextPosition position);

// textDocument/documentSymbol of one file of the deck: keywords, parts with their titles
// (DocumentSymbol[]).
nlohmann::json document_symbols(const CheckedDeck& deck, grammar::FileId file);

// textDocument/foldingRange: one range per keyword block (and comment runs). FoldingRange[].
nlohmann::json folding_ranges(const CheckedDeck& deck, grammar::FileId file);

// textDocument/codeAction for the diagnostics of the request's context (`params` is the request's
// whole params object: textDocument, range, context). CodeAction[] with WorkspaceEdits on `uri`.
nlohmann::json code_actions(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// textDocument/semanticTokens/full, /full/delta (answered with the whole set unless nothing
// changed) and /range: SemanticTokens ({"resultId", "data"}) by the legend of
// semantic_tokens_legend() (lsp/semantic_tokens.hpp). A full request on a file over 100,000 lines
// leaves out the values of blocks over 1,000 lines; a range request colours everything it covers.
nlohmann::json semantic_tokens_full(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);
nlohmann::json semantic_tokens_delta(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);
nlohmann::json semantic_tokens_range(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);
nlohmann::json semantic_tokens_legend();

// textDocument/inlayHint for params.range: field names beside values, defaults of blank fields,
// values of `&name` references. params["settings"] (the client's "inlayHints" settings, added by
// the server): enable, bulkBlocks (default false), defaults, parameterValues. InlayHint[].
nlohmann::json inlay_hints(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// textDocument/signatureHelp on a card line: the card's fields as one signature, the field under
// the cursor (blank part included; on a line being typed, the card it will be read as) active.
// SignatureHelp or null.
nlohmann::json signature_help(const CheckedDeck& deck, grammar::FileId file, TextPosition position);

// textDocument/formatting: the edits `sphdeck format` makes to the file (lsp/feature_formatting.cpp),
// TextEdit[]; textDocument/rangeFormatting: those on the lines of params.range.
nlohmann::json formatting(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);
nlohmann::json range_formatting(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// textDocument/prepareRename: the id or `&name` under the cursor ({"range", "placeholder"}), null
// when there is none; textDocument/rename (params.newName): a WorkspaceEdit of every id field that
// names it, in every file of the deck (engine/id_rename.hpp). A refused rename (a new id too wide
// for a field, one that exists) throws FeatureError with the reason.
nlohmann::json prepare_rename(const CheckedDeck& deck, grammar::FileId file, TextPosition position);
nlohmann::json rename(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// textDocument/documentLink: the file names of the file's include lines, each linked to the file the
// check read for it. DocumentLink[].
nlohmann::json document_links(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// textDocument/codeLens: "used by N" on each definition the file holds. CodeLens[] (resolved).
nlohmann::json code_lenses(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params);

// workspace/symbol: the definitions of every deck matching `query` (symbol_matches). SymbolInformation[].
nlohmann::json workspace_symbols(const std::vector<const CheckedDeck*>& decks, std::string_view query);
// Whether a symbol `name` matches a workspace/symbol query: its characters in order, any case.
bool symbol_matches(std::string_view query, std::string_view name);

// A request a feature understood but cannot carry out: answered with this JSON-RPC error.
struct FeatureError : std::runtime_error {
    FeatureError(int error_code, const std::string& message) : std::runtime_error(message), code(error_code) {}
    int code;
};

// The feature requests by method name, for the server: it finds the deck and the file that a
// request's textDocument names, then asks here. `handled` is false for a method no feature answers
// (the server then says MethodNotFound). The table is lsp/feature_dispatch.cpp: one row a feature.
struct FeatureAnswer {
    bool handled = false;
    nlohmann::json result;
};
FeatureAnswer answer_feature(std::string_view method, const CheckedDeck& deck, grammar::FileId file,
                             const nlohmann::json& params);

// What the features offer, merged into the server's initialize result ("hoverProvider": true...).
nlohmann::json feature_capabilities();

}  // namespace sphdeck::lsp
