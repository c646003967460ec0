#include "lint/rules.hpp"

namespace sphdeck::lint {

void run_rules(RuleContext& context) {
    check_references(context);
    check_control_sph(context);
    check_section_sph(context);
    if (!context.model.radioss) check_sph_particles(context);  // *ELEMENT_SPH masses; Radioss cells: RAD026
    check_sph_materials(context);
    check_isph(context);
    if (context.options.geometry) check_preview(context);
    check_radioss(context);
}

}  // namespace sphdeck::lint
