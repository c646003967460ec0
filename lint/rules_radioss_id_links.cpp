// Ids named by the cards of generated OpenRadioss layouts (the CFG's ATTRIBUTES types: FUNCT,
// SENSOR, SYSTEM, SETS of /SETS/GRNOD or /SETS/SURF, MAT, PROP, COMPONENT) against the ids the
// starter deck's headers define; a group may be a /SET of its id. A deck with //SUBMODEL is not judged: submodels
// offset ids.
#include <fmt/format.h>

#include "grammar/radioss/id_kinds.hpp"
#include "lint/rules_radioss.hpp"

namespace sphdeck::lint::radioss {
namespace {

namespace rad = grammar::radioss;

// The rule that judges the ids of each CFG type a generated cell links (FieldSpec::link; its kind and
// the headers that define it: grammar/radioss/id_kinds.hpp).
struct LinkRule {
    char link;
    const char* code;
};
constexpr LinkRule rules[] = {{'F', "REF009"}, {'S', "REF009"}, {'Y', "REF009"}, {'G', "REF008"},
                              {'U', "REF008"}, {'M', "REF004"}, {'P', "REF003"}, {'C', "REF002"}};

// Whether a header of the starter deck defines `id` of the kind `link` names or of a kind of its space:
// a /SET for a node group or a surface (the starter turns the set into the groups the options ask for:
// fill_igr.F, one group per kind with the set's id). Skews and frames are one CFG type, 'Y'.
bool defines(const model::RadiossFacts& f, char link, long long id) {
    for (const auto& [defined, ids] : f.header_ids)
        if (rad::ids_meet(rad::linked_kind(defined), rad::linked_kind(link)) && ids.count(id)) return true;
    return false;
}

}  // namespace

void check_generated_references(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    if (f.submodels) return;
    for (const model::RadiossIdUse& use : f.id_uses) {
        for (const LinkRule& rule : rules) {
            if (rule.link != use.kind) continue;
            if (defines(f, use.kind, use.id)) break;
            const std::string_view kind = rad::linked_kind(use.kind);
            c.report(rule.code, use.span,
                     fmt::format("{} {} of {} names no {}{} of the deck", use.field, use.id, use.keyword,
                                 rad::defined_by(kind), rad::is_group(kind) ? " or /SET" : ""));
            break;
        }
    }
}

}  // namespace sphdeck::lint::radioss
