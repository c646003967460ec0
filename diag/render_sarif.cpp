// The SARIF 2.1.0 report (linter-conventions.md §6.4); tests validate it against the OASIS schema.
#include "diag/render_sarif.hpp"

#include <cctype>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "diag/render_text.hpp"

namespace sphdeck::diag {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kSrcRoot = "%SRCROOT%";

const char* sarif_level(Severity s) {
    switch (s) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Info: return "note";
    }
    return "warning";
}

// RFC 3986: keep unreserved characters and '/', percent-encode every other byte.
std::string percent_encoded(std::string_view path) {
    std::string out;
    for (char c : path) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/')
            out += c;
        else
            out += fmt::format("%{:02X}", byte);
    }
    return out;
}

json rule_descriptor(const RuleMeta& rule) {
    return {{"id", rule.code},
            {"name", rule.name},
            {"shortDescription", {{"text", rule.summary}}},
            {"fullDescription", {{"text", rule.what}}},
            {"help", {{"text", rule.help_text}, {"markdown", rule.help_markdown}}},
            {"helpUri", rule.url},
            {"defaultConfiguration", {{"level", sarif_level(rule.severity)}}}};
}

json artifact_location(const text::SourceFile& file) {
    bool relative = false;
    json artifact = {{"uri", sarif_uri(file, relative)}};
    if (relative) artifact["uriBaseId"] = kSrcRoot;
    return artifact;
}

// Deck-wide findings have no span: they point at the first line of the main deck, because code
// scanning drops results without a location.
json physical_location(const text::Span& span, const text::SourceMap& sources) {
    const bool located = detail::has_location(span, sources);
    const json artifact = artifact_location(sources.file(located ? span.file : 0));
    json region = {{"startLine", located ? span.line : 1}};
    if (located) {
        region["startColumn"] = span.column;
        region["endColumn"] = std::max(span.end_column, span.column + 1);
    }
    return {{"physicalLocation", {{"artifactLocation", artifact}, {"region", region}}}};
}

// SARIF fixes (§3.55): one artifactChange per file, each edit a replacement of a one-line region
// (a zero-length region inserts). Edits without a location cannot be expressed and are left out.
json sarif_fixes(const Diagnostic& d, const text::SourceMap& sources) {
    json fixes = json::array();
    for (const Fix& fix : d.fixes) {
        json changes = json::array();
        std::vector<text::FileId> files;
        for (const TextEdit& edit : fix.edits) {
            if (!detail::has_location(edit.span, sources)) continue;
            json replacement = {{"deletedRegion",
                                 {{"startLine", edit.span.line},
                                  {"startColumn", edit.span.column},
                                  {"endColumn", std::max(edit.span.end_column, edit.span.column)}}},
                                {"insertedContent", {{"text", edit.replacement}}}};
            std::size_t k = 0;
            while (k < files.size() && files[k] != edit.span.file) ++k;
            if (k == files.size()) {
                files.push_back(edit.span.file);
                changes.push_back({{"artifactLocation", artifact_location(sources.file(edit.span.file))},
                                   {"replacements", json::array()}});
            }
            changes[k]["replacements"].push_back(std::move(replacement));
        }
        if (changes.empty()) continue;  // the schema wants at least one artifactChange
        fixes.push_back({{"description", {{"text", fix.description}}}, {"artifactChanges", std::move(changes)}});
    }
    return fixes;
}

class SarifReport final : public Report {
public:
    explicit SarifReport(const RuleCatalog& rules) : rules_(rules) {}

    void add(const text::SourceMap& sources, const std::vector<Diagnostic>& diagnostics) override {
        for (const Diagnostic& d : diagnostics) {
            std::string text = d.message;
            json related = json::array();
            for (const Note& note : d.notes) {
                if (!detail::has_location(note.span, sources)) {
                    text += "\nnote: " + note.message;  // no location: part of the message
                    continue;
                }
                json location = physical_location(note.span, sources);
                location["id"] = related.size();
                location["message"] = {{"text", note.message}};
                related.push_back(std::move(location));
            }
            json result = {{"ruleId", d.code}};
            if (auto index = rules_.index_of(d.code)) result["ruleIndex"] = *index;
            result["level"] = sarif_level(d.severity);
            result["message"] = {{"text", text}};
            if (sources.size() > 0) result["locations"] = json::array({physical_location(d.span, sources)});
            if (!related.empty()) result["relatedLocations"] = std::move(related);
            if (json fixes = sarif_fixes(d, sources); !fixes.empty()) result["fixes"] = std::move(fixes);
            results_.push_back(std::move(result));
        }
    }

    std::string finish(const RunSummary& summary) const override {
        json rules = json::array();
        for (const RuleMeta& rule : rules_.rules) rules.push_back(rule_descriptor(rule));
        json driver = {{"name", "sphdeck"},
                       {"version", SPHDECK_VERSION},
                       {"semanticVersion", SPHDECK_VERSION},
                       {"informationUri", rules_.project_url},
                       {"rules", std::move(rules)}};
        json run = {{"tool", {{"driver", std::move(driver)}}}};
        std::error_code ec;
        const auto cwd = std::filesystem::current_path(ec);
        if (!ec) {
            std::string root = "file://" + percent_encoded(cwd.generic_string());
            if (!root.ends_with('/')) root += '/';
            run["originalUriBaseIds"] = {{kSrcRoot, {{"uri", root}}}};
        }
        run["invocations"] = json::array({{{"executionSuccessful", summary.complete}}});
        run["results"] = results_;
        json log = {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                    {"version", "2.1.0"},
                    {"runs", json::array({std::move(run)})}};
        return log.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
    }

private:
    const RuleCatalog& rules_;
    json results_ = json::array();
};

}  // namespace

std::string sarif_uri(const text::SourceFile& file, bool& relative) {
    const std::string path = tool_path(file);
    relative = !path.starts_with('/');
    return relative ? percent_encoded(path) : "file://" + percent_encoded(path);
}

std::unique_ptr<Report> make_sarif_report(const RuleCatalog& rules) { return std::make_unique<SarifReport>(rules); }

}  // namespace sphdeck::diag
