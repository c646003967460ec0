// REF rules: references between definitions (ids of nodes, parts, sections, materials, sets).
// One row per rule: code, name, default severity, since-version, source, summary and the
// documentation `sphdeck rule CODE` prints (what / why / fix / before / after).
// The deck snippets are column-exact: keep fields aligned when editing them.
#include "lint/registry.hpp"

namespace sphdeck::lint::detail {
namespace {

constexpr RuleInfo kRefRules[] = {
    // REF001 undefined-node
    {.code = "REF001",
     .name = "undefined-node",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "a particle or a node set names a node that no *NODE defines",
     .doc = {.what = "Reports an *ELEMENT_SPH particle, a generated NID-NEND range or a node set "
                     "that names a node id no *NODE defines.",
             .why = "An SPH particle lives on a node: NID is both the node and the particle id, "
                    "and the node gives its position (*ELEMENT_SPH, NID). Without the node the "
                    "particle has no coordinates, and the solver stops at input.",
             .fix = "Define the node, or correct the id (check NEND ranges against the node "
                    "numbering).",
             .before = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     102       1          8.0e-9
)deck",
             .after = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
)deck"}},

    // REF002 undefined-part
    {.code = "REF002",
     .name = "undefined-part",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "a particle or a part set names a *PART that does not exist",
     .doc = {.what = "Reports an *ELEMENT_SPH particle or a part set that names a part id with no "
                     "*PART.",
             .why = "The part gives the particle its section, material and equation of state "
                    "(*ELEMENT_SPH, PID; *PART). A particle without one cannot be computed, and "
                    "the solver stops at input.",
             .fix = "Correct the part id, or define the missing *PART.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       2          8.0e-9
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
)deck"}},

    // REF003 undefined-section
    {.code = "REF003",
     .name = "undefined-section",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "*PART SECID with no *SECTION_ keyword of that id",
     .doc = {.what = "Reports a *PART whose SECID matches no *SECTION_ keyword.",
             .why = "The section holds the element formulation; for SPH parts it is the "
                    "*SECTION_SPH that sets the smoothing length and kernel (*PART, SECID; "
                    "*SECTION_SPH). A part without it cannot be computed, and the solver stops at "
                    "input.",
             .fix = "Point SECID at an existing section, or define the section.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         2         1         1         0         0         0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // REF004 undefined-material
    {.code = "REF004",
     .name = "undefined-material",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "*PART MID with no *MAT_ keyword of that id",
     .doc = {.what = "Reports a *PART whose MID matches no *MAT_ keyword.",
             .why = "Without its material a part has no density and no constitutive law (*PART, "
                    "MID); the solver stops at input.",
             .fix = "Point MID at an existing material, or define the material.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         5         1         0         0         0         0
*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1    1.0e-9   -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1    1.0e-9   -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck"}},

    // REF005 undefined-eos
    {.code = "REF005",
     .name = "undefined-eos",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "*PART EOSID with no *EOS_ keyword of that id",
     .doc = {.what = "Reports a *PART whose non-zero EOSID matches no *EOS_ keyword (0 means no "
                     "equation of state and is not reported here).",
             .why = "Materials such as *MAT_NULL take their pressure from the equation of state "
                    "the part names (*PART, EOSID); a dangling id stops the solver at input.",
             .fix = "Point EOSID at an existing *EOS_, or define it.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         2         0         0         0         0
*EOS_MURNAGHAN
$#   eosid     gamma        k0        v0
         1       7.0     320.0       1.0
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*EOS_MURNAGHAN
$#   eosid     gamma        k0        v0
         1       7.0     320.0       1.0
)deck"}},

    // REF006 duplicate-id
    {.code = "REF006",
     .name = "duplicate-id",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "two nodes, particles, parts, sections, materials, EOS or boxes share an id",
     .doc = {.what = "Reports two definitions of the same kind with the same id: nodes, "
                     "particles, parts, sections, materials, equations of state or boxes. Both "
                     "locations are shown.",
             .why = "References by id become ambiguous: the solver stops with a duplicate-id "
                    "error or uses one of the two definitions, and nobody reading the deck can "
                    "tell which was meant (*PART, *SECTION, *MAT and the other keywords identify "
                    "their objects by id).",
             .fix = "Renumber one of the two definitions and update the references that meant it.",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.3       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         2       1.3       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // REF007 unused-definition
    {.code = "REF007",
     .name = "unused-definition",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "references",
     .summary = "a section, material, EOS or box that nothing references",
     .doc = {.what = "Reports a section, material, equation of state or box that no part, control "
                     "card or other keyword references.",
             .why = "An unused definition costs the solver nothing, but it often means a "
                    "reference points at the wrong id and the intended definition was left out, "
                    "or it is a leftover of an earlier model that confuses the next reader (*PART "
                    "SECID, MID, EOSID; *CONTROL_SPH BOXID).",
             .fix = "Check that the parts use the intended ids; delete the definition if it is "
                    "really unused.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         2       1.3       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // REF008 undefined-set
    {.code = "REF008",
     .name = "undefined-set",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "a node or part set id that is not defined",
     .doc = {.what = "Reports a reference to a node set or part set id that no *SET_ keyword "
                     "defines, e.g. SIDA of *DEFINE_SPH_TO_SPH_COUPLING while SATYP is 0 (part "
                     "set).",
             .why = "The referring keyword applies to nothing, or the solver stops at input. SPH "
                    "keywords often default to a set: SATYP and SBTYP of "
                    "*DEFINE_SPH_TO_SPH_COUPLING are 0 for part sets and 1 for parts, so a part "
                    "id left with type 0 is read as an undefined set "
                    "(*DEFINE_SPH_TO_SPH_COUPLING, SATYP and SBTYP).",
             .fix = "Define the set, or change the type flag if the id is a part.",
             .before = R"deck(*DEFINE_SPH_TO_SPH_COUPLING
$#    sida      sidb     satyp     sbtyp     iboxa     iboxb     pfact      srad
         1         2         0         0         0         0       1.0       1.0
)deck",
             .after = R"deck(*DEFINE_SPH_TO_SPH_COUPLING
$#    sida      sidb     satyp     sbtyp     iboxa     iboxb     pfact      srad
         1         2         1         1         0         0       1.0       1.0
)deck"}},
};

}  // namespace

std::span<const RuleInfo> ref_rule_rows() { return kRefRules; }

}  // namespace sphdeck::lint::detail
