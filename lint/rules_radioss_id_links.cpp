// Ids named by the cards of generated OpenRadioss layouts (the CFG's ATTRIBUTES types: FUNCT,
// SENSOR, SYSTEM, SETS of /SETS/GRNOD or /SETS/SURF, MAT, PROP, COMPONENT) against the ids the
// starter deck's headers define; a group may be a /SET of its id. A deck with //SUBMODEL is not judged: submodels offset ids.
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
    {'G', "REF008", "/GRNOD or /SET"},   {'U', "REF008", "/SURF or /SET"}, {'M', "REF004", "/MAT"},
    {'P', "REF003", "/PROP"},            {'C', "REF002", "/PART"}};

bool defines(const model::RadiossFacts& f, char kind, long long id) {
    const auto defined = f.header_ids.find(kind);
    if (defined != f.header_ids.end() && defined->second.count(id)) return true;
    // A group (node group, surface) may be a /SET of that id: the starter turns the set into the
    // groups the options ask for (starter fill_igr.F, one group per kind with the set's id).
    const bool group = kind == 'G' || kind == 'U';
    const auto sets = f.header_ids.find('T');
    return group && sets != f.header_ids.end() && sets->second.count(id);
}

}  // namespace

void check_generated_references(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    if (f.submodels) return;
    for (const model::RadiossIdUse& use : f.id_uses) {
        for (const LinkKind& k : kinds) {
            if (k.kind != use.kind) continue;
            if (defines(f, use.kind, use.id)) break;
            c.report(k.code, use.span,
                     fmt::format("{} {} of {} names no {} of the deck", use.field, use.id, use.keyword, k.what));
            break;
        }
    }
}

}  // namespace sphdeck::lint::radioss
