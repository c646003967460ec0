// A checked deck's findings as LSP Diagnostics, grouped by the file they are in: the same codes,
// severities, messages and column ranges `sphdeck check` reports, notes with a location as
// relatedInformation, notes without one folded into the message, and the rule's documentation as
// codeDescription.href.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "diag/diagnostic.hpp"
#include "engine/check.hpp"

namespace sphdeck::lsp {

// The URI a file of the deck is published under: the editor's own URI for an open document.
// `key` is the file's engine::Documents::key, `path` the path the reader opened.
using UriOf = std::function<std::string(const std::filesystem::path& key, const std::string& path)>;

struct FileFindings {
    std::string path;                                      // as the reader opened it
    nlohmann::json diagnostics = nlohmann::json::array();  // Diagnostic[]
};

// Every file the deck read (keyed by Documents::key), each with the diagnostics located in it, an
// empty list when it has none. Findings without a location go to the main file's first line.
std::map<std::filesystem::path, FileFindings> findings_by_file(const engine::CheckResult& result, const UriOf& uri_of);

// One finding as an LSP Diagnostic.
nlohmann::json lsp_diagnostic(const diag::Diagnostic& d, const grammar::SourceMap& sources,
                              const std::function<std::string(grammar::FileId)>& uri_of_file);

// The documentation page of a rule: the URL the JSON and SARIF reports give, or docs/rules/CODE.md
// on the project's site for a code the registry does not know.
std::string rule_doc_url(const std::string& code);

// 1 error, 2 warning, 3 information (LSP DiagnosticSeverity).
int lsp_severity(diag::Severity severity);

}  // namespace sphdeck::lsp
