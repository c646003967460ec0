#include "lint/typo_consequences.hpp"

#include <fmt/format.h>

#include "grammar/keywords/schema.hpp"
#include "grammar/radioss/keyword_lookup.hpp"

namespace sphdeck::lint {

namespace {
bool model_rule(const std::string& code) {
    return code.starts_with("REF") || code.starts_with("SPH") || code.starts_with("RAD");
}
}  // namespace

void point_to_misspelt_keywords(std::vector<diag::Diagnostic>& diagnostics) {
    std::vector<diag::Note> causes;
    for (const diag::Diagnostic& d : diagnostics) {
        if (d.code != "DK001" || d.severity != diag::Severity::Error || d.fixes.empty() || d.fixes[0].edits.empty())
            continue;
        const std::string& suggested = d.fixes[0].edits[0].replacement;
        std::string meant;
        if (suggested.starts_with('/')) {  // an OpenRadioss header: the model reads every one the starter knows
            if (!grammar::radioss::lookup_keyword(suggested).known) continue;
            meant = suggested;
        } else {
            auto match = keywords::find_keyword(suggested);
            if (!match || match->schema->generated) continue;  // a keyword the model does not read changes nothing
            meant = std::string(match->schema->name);
        }
        // The fix's description names the keyword as read: "replace *PRAT with *PART".
        std::string_view written = d.fixes[0].description;
        if (written.starts_with("replace ")) written = written.substr(8, written.find(" with ") - 8);
        causes.push_back({d.span, fmt::format("this may follow from the unknown keyword {} (did you mean {}?): its "
                                              "block was not read",
                                              written, meant)});
        if (causes.size() == 3) break;
    }
    if (causes.empty()) return;
    for (diag::Diagnostic& d : diagnostics)
        if (model_rule(d.code)) d.notes.insert(d.notes.end(), causes.begin(), causes.end());
}

}  // namespace sphdeck::lint
