// Ids the SPH cards name, checked as the starter checks them: /SPH/INOUT (hm_read_sphio.F) its
// part (error 437), its surface among the /SURF headers (error 438) and the three nodes of a frontier given by nodes
// (USR2SYS in sysfus.F: error 78; format 140 on); /INISPHCEL/FULL (hm_read_inistate_d00.F) its particles (UEL2SYS over
// the /SPHCEL cells: an id not found is skipped, warning 3045).
#include <fmt/format.h>

#include "lint/rules_radioss.hpp"

namespace sphdeck::lint::radioss {

void check_sph_references(RuleContext& c) {
    const model::RadiossFacts& f = *c.model.radioss;
    for (const model::RadiossInout& io : f.inouts) {
        if (!c.model.part(std::to_string(io.part.value)))
            c.report("REF002", io.part.explicit_value ? io.part.span : io.span,
                     fmt::format("/SPH/INOUT {} part_ID {} names no /PART (starter error 437)", io.id, io.part.value));
        // A surface takes precedence: the nodes are read only when surf_ID is 0.
        if (io.surface.value > 0) {
            if (f.surfaces_known && !f.has_surface(io.surface.value))
                c.report("REF008", io.surface.span,
                         fmt::format("/SPH/INOUT {} surf_ID {} names no /SURF or /SET (starter error 438)", io.id,
                                     io.surface.value));
            continue;
        }
        for (const auto& n : io.nodes)
            if (n.value != 0 && !c.node_index().find(n.value))
                c.report("REF001", n.span,
                         fmt::format("/SPH/INOUT {} node {} is not defined (starter error 78)", io.id, n.value));
    }
    std::size_t missing = 0;
    for (const model::RadiossInitialState& s : f.initial_states) {
        if (c.particle_index().find(s.cell)) continue;
        if (++missing > max_listed) continue;  // the starter counts them in one warning
        c.report("REF001", diag::Severity::Warning, s.span,
                 fmt::format("/INISPHCEL/FULL names particle {}, which no /SPHCEL defines: the starter skips its "
                             "initial state (warning 3045)",
                             s.cell));
    }
    if (missing > max_listed)
        c.report("REF001", diag::Severity::Warning, f.initial_states.front().span,
                 fmt::format("/INISPHCEL/FULL: {} initial states name no /SPHCEL particle in all ({} shown)", missing,
                             max_listed));
}

}  // namespace sphdeck::lint::radioss
