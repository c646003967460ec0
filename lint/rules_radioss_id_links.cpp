// Ids named by the cards of generated OpenRadioss layouts (the CFG's ATTRIBUTES types: FUNCT,
// SENSOR, SYSTEM, SETS of /SETS/GRNOD or /SETS/SURF, MAT, PROP, COMPONENT) against the ids the
// starter deck's headers define. A deck with //SUBMODEL is not judged: submodels offset ids.
#include <fmt/format.h>

#include "lint/rules_radioss.hpp"

namespace sphdeck::lint::radioss {
namespace {

struct LinkKind {
    char kind;
    const char* code;
    const char* what;  // the headers that define such ids
};

constexpr LinkKind kinds[] = {
    {'F', "REF009", "/FUNCT or /TABLE"}, {'S', "REF009", "/SENSOR"},  {'Y', "REF009", "/SKEW or /FRAME"},
    {'G', "REF008", "/GRNOD"},           {'U', "REF008", "/SURF"},    {'M', "REF004", "/MAT"},
    {'P', "REF003", "/PROP"},            {'C', "REF002", "/PART"}};

}  // namespace

void check_generated_references(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    if (f.submodels) return;
    for (const model::RadiossIdUse& use : f.id_uses) {
        for (const LinkKind& k : kinds) {
            if (k.kind != use.kind) continue;
            const auto defined = f.header_ids.find(use.kind);
            if (defined != f.header_ids.end() && defined->second.count(use.id)) break;
            c.report(k.code, use.span,
                     fmt::format("{} {} of {} names no {} of the deck", use.field, use.id, use.keyword, k.what));
            break;
        }
    }
}

}  // namespace sphdeck::lint::radioss
