// *CONTROL_* keywords used by SPH decks (lsdyna-sph-cards.md §1, §12, §14-§16).
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

// *CONTROL_SPH FORM (lsdyna-sph-cards.md §1, FORM table). No edition lists 11 or 14.
std::vector<EnumChoice> sph_forms() {
    return {
        {0, "default formulation"},
        {1, "renormalization approximation"},
        {2, "symmetric formulation"},
        {3, "symmetric renormalized approximation"},
        {4, "tensor formulation"},
        {5, "fluid particle approximation"},
        {6, "fluid particle with renormalization"},
        {7, "total Lagrangian formulation"},
        {8, "total Lagrangian with renormalization"},
        {9, "adaptive SPH (ASPH), anisotropic smoothing tensor"},
        {10, "renormalized ASPH"},
        {12, "moving-least-squares (MLS) formulation"},
        // Not in the seed manual edition; pydyna (newer editions) documents it as MPP only.
        {13, "implicit incompressible SPH (ISPH)"},
        {15, "enhanced fluid formulation"},
        {16, "enhanced fluid with renormalization"},
    };
}

KeywordSchema control_sph() {
    return {
        .name = "*CONTROL_SPH",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "NCBS",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 1,
                             .doc = "time steps between particle sorts (neighbour searches)"},
                            {.name = "BOXID",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,  // pydyna: none
                             .doc = "*DEFINE_BOX outside which particles are deactivated; 0 = no box"},
                            {.name = "DT",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e20,
                             .zero_is_default = true,  // inferred: old LS-PrePost decks write 0
                             .doc = "death time: SPH computation stops at this time"},
                            // No default: blank or 0 is a warning raised by the lint rules, not here.
                            {.name = "IDIM",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .zero_is_default = false,
                             .required = false,
                             // 0 (what old LS-PrePost wrote) is accepted here and warned about
                             // as DK008: the manual documents no default (lsdyna-sph-cards.md §1).
                             .choices = {{3, "3D"},
                                         {2, "2D plane strain"},
                                         {-2, "2D axisymmetric"},
                                         {0, "unset: no documented default (warned)"}},
                             .doc = "space dimension"},
                            // Called MEMORY in the manual pages, the CFG files up to R11.1 and Workbench
                            // output; pydyna calls it NMNEIGH (lsdyna-sph-cards.md §1 notes).
                            {.name = "MEMORY",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 150,
                             .zero_is_default = true,  // inferred
                             .doc = "initial neighbours per particle; < 0: |MEMORY| is a fixed maximum",
                             .aliases = {"NMNEIGH"}},
                            {.name = "FORM",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = sph_forms(),
                             .doc = "particle approximation"},
                            {.name = "START",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "time at which the particle approximation starts"},
                            // Sources disagree on MAXV <= 0 (seed: negative switches the check off;
                            // pydyna: 0 = no check, < 0 = limit at |MAXV|): no zero_is_default.
                            {.name = "MAXV",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e15,
                             .doc = "velocity limit: faster particles are deactivated"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "CONT",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "approximation between all SPH parts"},
                                         {1, "no approximation between parts (see _INTERACTION)"}},
                             .doc = "particle approximation between different SPH parts"},
                            {.name = "DERIV",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "dh/dt = (1/d) h div v"}, {1, "dh/dt = (1/d) h (div v)^(1/3)"}},
                             .doc = "time integration of the smoothing length"},
                            {.name = "INI",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "bucket-sort algorithm"},
                                         {1, "global computation over all particles"},
                                         {2, "from the particle mass"}},
                             .doc = "initial smoothing length computation"},
                            {.name = "ISHOW",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("deactivated particles drawn as active ones",
                                               "deactivated particles drawn as points"),
                             .doc = "display of deactivated particles in LS-PrePost",
                             .since = "R6.1"},
                            {.name = "IEROD",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "particles stay active"},
                                         {1, "partly deactivated: stress 0, still integrated"},
                                         {2, "fully deactivated: stress 0, removed from the integration"},
                                         {3, "active with deviatoric stress 0"}},
                             .doc = "what erosion does to SPH particles",
                             .since = "R6.1"},
                            {.name = "ICONT",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("contact stays active for deactivated particles",
                                               "contact off for deactivated particles"),
                             .doc = "contact of deactivated particles",
                             .since = "R6.1"},
                            {.name = "IAVIS",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("Monaghan artificial viscosity", "solid-element bulk viscosity"),
                             .doc = "artificial viscosity formulation",
                             .since = "R6.1"},
                            {.name = "ISYMP",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 100,
                             .doc = "percent of the particle count reserved for symmetry-plane ghosts",
                             .since = "R9.3"},
                        },
                    .repeat = CardRepeat::Optional,
                },
                {
                    .name = "Card 3",
                    .fields =
                        {
                            {.name = "ITHK",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("zero contact thickness", "thickness from the particle volume"),
                             .doc = "contact thickness of particles",
                             .since = "R11.1"},
                            {.name = "ISTAB",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("incremental stabilisation", "total stabilisation (hyperelastic)"),
                             .doc = "MLS stabilisation (FORM = 12 only)",
                             .since = "R11.1"},
                            // The manual gives QL a default of 0.01 and no meaning for 0 (a QL of 0
                            // would switch the quasi-linear term off, which Remark 5 never offers);
                            // a blank reads as 0 in LS-DYNA's fixed columns, so 0 is the default's
                            // zero. Tool-written decks write card 3 as "0 0 0.0".
                            {.name = "QL",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.01,
                             .zero_is_default = true,
                             .doc = "MLS quasi-linear coefficient (FORM = 12 only)",
                             .since = "R11.1"},
                            unused(31),
                            // SPHSORT and ISHIFT come from pydyna, i.e. editions after R13.
                            {.name = "SPHSORT",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on(),
                             .doc = "particle sorting for implicit analyses",
                             .since = "R13.0"},
                            {.name = "ISHIFT",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on(),
                             .doc = "particle shifting",
                             .since = "R13.0"},
                        },
                    .repeat = CardRepeat::Optional,
                    .since = "R11.1",
                },
            },
        .unique = true,
        .doc = "global SPH controls: particle approximation, sorting, smoothing length, erosion",
    };
}

KeywordSchema control_bulk_viscosity() {
    return {
        .name = "*CONTROL_BULK_VISCOSITY",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "Q1",
                     .column = 1,
                     .width = 10,
                     .type = F,
                     .default_value = 1.5,
                     .doc = "quadratic bulk-viscosity coefficient"},
                    {.name = "Q2",
                     .column = 11,
                     .width = 10,
                     .type = F,
                     .default_value = 0.06,
                     .doc = "linear bulk-viscosity coefficient"},
                    {.name = "TYPE",
                     .column = 21,
                     .width = 10,
                     .type = I,
                     .default_value = 1,
                     .choices = {{-2, ""}, {-1, ""}, {1, ""}, {2, ""}},
                     .doc = "bulk viscosity type (meanings not in the sources)"},
                    {.name = "BTYPE",
                     .column = 31,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .choices = {{0, ""}, {1, ""}, {2, ""}},
                     .doc = "beam bulk viscosity type"},
                    {.name = "TSTYPE",
                     .column = 41,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .choices = off_on(),
                     .doc = "thick-shell bulk viscosity type"},
                },
        }},
        .unique = true,
        .doc = "default bulk viscosity; Q1/Q2 also feed the SPH artificial viscosity",
    };
}

KeywordSchema control_timestep() {
    return {
        .name = "*CONTROL_TIMESTEP",
        .aliases = {"*CONTROL_TIME_STEP"},
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "DTINIT",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "initial time step (0 = computed)"},
                            // The manual gives 0.90 (and 0 is read as the default); pydyna's schema
                            // says 0.0. We follow the manual (lsdyna-sph-cards.md §14, §24).
                            {.name = "TSSFAC",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.9,
                             .zero_is_default = true,
                             .doc = "time-step scale factor"},
                            {.name = "ISDO",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "shell time-step basis"},
                            {.name = "TSLIMT",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "shell minimum time step"},
                            {.name = "DT2MS",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "mass-scaling time step"},
                            {.name = "LCTM",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "load curve limiting the maximum time step"},
                            {.name = "ERODE",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, ""},
                                         {1, "erode elements (and SPH particles) below TSMIN"},
                                         {10, ""},
                                         {11, ""},
                                         {100, ""},
                                         {101, ""},
                                         {110, ""},
                                         {111, ""}},
                             .doc = "erosion of elements whose time step falls below TSMIN"},
                            {.name = "MS1ST",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on(),
                             .doc = "mass scaling in the first step only"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "DT2MSF", .column = 1, .width = 10, .type = F, .doc = "mass-scaling factor"},
                            {.name = "DT2MSLC", .column = 11, .width = 10, .type = I, .doc = "DT2MS load curve"},
                            {.name = "IMSCL", .column = 21, .width = 10, .type = I, .doc = "selective mass scaling"},
                            unused(31),
                            unused(41),
                            {.name = "RMSCL",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "selective mass scaling parameter"},
                            {.name = "EMSCL",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "mass-scaling limit"},
                            {.name = "IHDO",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on(),
                             .doc = "solid time-step method"},
                        },
                    .repeat = CardRepeat::Optional,
                },
                {
                    .name = "Card 3",
                    .fields =
                        {
                            // R17 defaults quoted in ansys/pydyna issue #1257.
                            {.name = "RMAVG", .column = 1, .width = 10, .type = F, .default_value = 0.0, .doc = ""},
                            {.name = "IGADO",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on(),
                             .doc = "IGA time-step method"},
                            {.name = "DTUSR",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "user time step"},
                            {.name = "DTDYNV",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "dynamic time-step option"},
                        },
                    .repeat = CardRepeat::Optional,
                },
            },
        .unique = true,
        .doc = "explicit time step: scale factor, mass scaling, erosion on small time steps",
    };
}

KeywordSchema control_termination() {
    return {
        .name = "*CONTROL_TERMINATION",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "ENDTIM",
                     .column = 1,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "termination time (described as mandatory)"},
                    {.name = "ENDCYC",
                     .column = 11,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "termination cycle"},
                    {.name = "DTMIN",
                     .column = 21,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "minimum time-step factor"},
                    {.name = "ENDENG",
                     .column = 31,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "energy-change limit"},
                    {.name = "ENDMAS",
                     .column = 41,
                     .width = 10,
                     .type = F,
                     .default_value = 1.0e8,  // pydyna
                     .doc = "mass-change limit"},
                    {.name = "NOSOL",
                     .column = 51,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .choices = off_on(),
                     .doc = "no-solution flag"},
                },
        }},
        .unique = true,
        .doc = "termination time and other stop criteria",
    };
}

// Layout from pydyna (lsdyna-keyword-layouts.json, *CONTROL_SOLUTION); SOLN's meanings are the
// manual's: 0 structural only, 1 thermal only, 2 coupled thermal-structural. Only SOLN is read by
// the model (a thermal-only deck needs no structural material, REF004); the other fields are
// decoded so the card is not an unknown keyword.
KeywordSchema control_solution() {
    return {
        .name = "*CONTROL_SOLUTION",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "SOLN",
                     .column = 1,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "analysis solution procedure: 0 structural, 1 thermal only, 2 coupled"},
                    {.name = "NLQ", .column = 11, .width = 10, .type = I, .doc = "vector length"},
                    {.name = "ISNAN",
                     .column = 21,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "check for NaN in the force and moment arrays"},
                    {.name = "LCINT",
                     .column = 31,
                     .width = 10,
                     .type = I,
                     .default_value = 100,
                     .doc = "default number of points of a discretized load curve"},
                    {.name = "LCACC",
                     .column = 41,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "truncate load curves to single precision"},
                    {.name = "NCDCF", .column = 51, .width = 10, .type = I, .default_value = 1, .doc = "pydyna"},
                    {.name = "NOCOPY", .column = 61, .width = 10, .type = I, .default_value = 0, .doc = "pydyna"},
                    {.name = "CRVP", .column = 71, .width = 10, .type = I, .default_value = 0, .doc = "pydyna"},
                },
        }},
        .unique = true,
        .doc = "analysis type: structural, thermal only, or coupled",
    };
}

KeywordSchema control_mpp_scale_factor_sph() {
    return {
        .name = "*CONTROL_MPP_DECOMPOSITION_SCALE_FACTOR_SPH",
        .cards = {{
            .name = "Card 1",
            .fields = {{
                // Real in pydyna, %10d in the OpenRadioss R6.1 description: read as real.
                .name = "SF",
                .column = 1,
                .width = 10,
                .type = F,
                .doc = "MPP decomposition weight of SPH particles",
            }},
        }},
        .unique = true,
        .doc = "MPP decomposition weight of SPH particles (MPP only)",
    };
}

KeywordSchema control_mpp_distribute_sph() {
    return {
        .name = "*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS",
        .unique = true,
        .doc = "distribute SPH particles over all MPP processors; keyword line only (MPP only)",
    };
}

}  // namespace

std::vector<KeywordSchema> control_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(control_sph());
    k.push_back(control_bulk_viscosity());
    k.push_back(control_timestep());
    k.push_back(control_termination());
    k.push_back(control_solution());
    k.push_back(control_mpp_scale_factor_sph());
    k.push_back(control_mpp_distribute_sph());
    return k;
}

}  // namespace sphdeck::keywords::tables
