// The JSON report: every finding of the run with its rule, location, notes and include chain.
#include "diag/render_json.hpp"

#include <nlohmann/json.hpp>

#include "diag/render_text.hpp"

namespace sphdeck::diag {
namespace {

using json = nlohmann::ordered_json;  // keeps fields in the documented order

// file/line/column/end_column of a span; file null and zeros when it has no location.
void put_location(json& out, const text::Span& span, const text::SourceMap& sources) {
    const bool located = detail::has_location(span, sources);
    out["file"] = located ? json(detail::file_name(sources.file(span.file))) : json(nullptr);
    out["line"] = located ? span.line : 0;
    out["column"] = located ? span.column : 0;
    out["end_column"] = located ? std::max(span.end_column, span.column + 1) : 0;
}

// The files that include the finding's file, main deck first, each with the line naming the next file.
json include_chain_json(const text::Span& span, const text::SourceMap& sources) {
    json chain = json::array();
    if (!detail::has_location(span, sources)) return chain;
    const std::vector<text::FileId> files = sources.include_chain(span.file);
    for (std::size_t i = 0; i + 1 < files.size(); ++i)
        chain.push_back(
            {{"file", detail::file_name(sources.file(files[i]))}, {"line", sources.file(files[i + 1]).include_line}});
    return chain;
}

// The finding's mends: each edit replaces the columns [column, end_column) of one line (equal
// columns insert), as TextEdit says.
json fixes_json(const Diagnostic& d, const text::SourceMap& sources) {
    json fixes = json::array();
    for (const Fix& fix : d.fixes) {
        json edits = json::array();
        for (const TextEdit& edit : fix.edits) {
            const bool located = detail::has_location(edit.span, sources);
            edits.push_back({{"file", located ? json(detail::file_name(sources.file(edit.span.file))) : json(nullptr)},
                             {"line", located ? edit.span.line : 0},
                             {"column", located ? edit.span.column : 0},
                             {"end_column", located ? std::max(edit.span.end_column, edit.span.column) : 0},
                             {"replacement", edit.replacement}});
        }
        fixes.push_back({{"description", fix.description}, {"safe", fix.safe}, {"edits", std::move(edits)}});
    }
    return fixes;
}

class JsonReport final : public Report {
public:
    explicit JsonReport(const RuleCatalog& rules) : rules_(rules) {}

    void add(const text::SourceMap& sources, const std::vector<Diagnostic>& diagnostics) override {
        for (const Diagnostic& d : diagnostics) {
            const RuleMeta* rule = rules_.find(d.code);
            json item = {{"code", d.code},
                         {"name", rule ? json(rule->name) : json(nullptr)},
                         {"severity", to_string(d.severity)},
                         {"message", d.message}};
            put_location(item, d.span, sources);
            json notes = json::array();
            for (const Note& note : d.notes) {
                json n = {{"message", note.message}};
                put_location(n, note.span, sources);
                notes.push_back(std::move(n));
            }
            item["notes"] = std::move(notes);
            item["fixes"] = fixes_json(d, sources);
            item["include_chain"] = include_chain_json(d.span, sources);
            item["url"] = rule ? json(rule->url) : json(nullptr);
            diagnostics_.push_back(std::move(item));
        }
    }

    std::string finish(const RunSummary& s) const override {
        json doc = {{"version", SPHDECK_VERSION},
                    {"diagnostics", diagnostics_},
                    {"summary",
                     {{"files", s.files},
                      {"keywords", s.keywords},
                      {"cards", s.cards},
                      {"particles", s.particles},
                      {"errors", s.counts.errors},
                      {"warnings", s.counts.warnings},
                      {"infos", s.counts.infos},
                      {"seconds", s.seconds}}}};
        // Decks may hold bytes that are not UTF-8: replace them instead of failing.
        return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
    }

private:
    const RuleCatalog& rules_;
    json diagnostics_ = json::array();
};

}  // namespace

std::unique_ptr<Report> make_json_report(const RuleCatalog& rules) { return std::make_unique<JsonReport>(rules); }

}  // namespace sphdeck::diag
