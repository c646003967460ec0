#include "lsp/diagnostics.hpp"

#include <vector>

#include "engine/documents.hpp"
#include "lint/rule_catalog.hpp"
#include "lsp/text_position.hpp"

namespace sphdeck::lsp {
namespace {
bool located_diagnostic(const grammar::Span& span, const grammar::SourceMap& sources) {
    return span.valid() && span.file < sources.size() && span.line > 0;
}
}  // namespace

int lsp_severity(diag::Severity severity) {
    switch (severity) {
        case diag::Severity::Error: return 1;
        case diag::Severity::Warning: return 2;
        case diag::Severity::Info: return 3;
    }
    return 1;
}

std::string rule_doc_url(const std::string& code) {
    const diag::RuleCatalog& catalog = lint::rule_catalog();
    if (const diag::RuleMeta* rule = catalog.find(code); rule && !rule->url.empty()) return rule->url;
    return catalog.project_url + "/blob/main/docs/rules/" + code + ".md";
}

nlohmann::json lsp_diagnostic(const diag::Diagnostic& d, const grammar::SourceMap& sources,
                              const std::function<std::string(grammar::FileId)>& uri_of_file) {
    std::string message = d.message;
    nlohmann::json related = nlohmann::json::array();
    for (const diag::Note& note : d.notes) {
        if (located_diagnostic(note.span, sources)) {
            related.push_back(
                {{"location", {{"uri", uri_of_file(note.span.file)}, {"range", range_json(sources, note.span)}}},
                 {"message", note.message}});
        } else {
            message += "\nnote: " + note.message;  // what `check` prints as "= note: ..."
        }
    }
    nlohmann::json out = {{"range",
                           located_diagnostic(d.span, sources) ? range_json(sources, d.span) : range_json(sources, {})},
                          {"severity", lsp_severity(d.severity)},
                          {"code", d.code},
                          {"codeDescription", {{"href", rule_doc_url(d.code)}}},
                          {"source", "sphdeck"},
                          {"message", std::move(message)}};
    if (!related.empty()) out["relatedInformation"] = std::move(related);
    return out;
}

std::map<std::filesystem::path, FileFindings> findings_by_file(const engine::CheckResult& result, const UriOf& uri_of) {
    const grammar::SourceMap& sources = result.deck.sources;
    std::map<std::filesystem::path, FileFindings> out;
    std::vector<std::filesystem::path> keys;  // one per file instance; an include read twice is one file
    keys.reserve(sources.size());
    for (grammar::FileId id = 0; id < sources.size(); ++id) {
        keys.push_back(engine::Documents::key(sources.file(id).path));
        out.try_emplace(keys.back(), FileFindings{sources.file(id).path, nlohmann::json::array()});
    }
    if (keys.empty()) return out;
    const auto uri_of_file = [&](grammar::FileId id) { return uri_of(keys[id], sources.file(id).path); };
    for (const diag::Diagnostic& d : result.diagnostics) {
        const grammar::FileId file = located_diagnostic(d.span, sources) ? d.span.file : 0;
        out[keys[file]].diagnostics.push_back(lsp_diagnostic(d, sources, uri_of_file));
    }
    return out;
}

}  // namespace sphdeck::lsp
