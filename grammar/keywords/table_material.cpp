// Materials used with SPH (lsdyna-sph-cards.md §17, §19). Defaults are the R16 material manual's.
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

FieldSpec mid() {
    return {.name = "MID", .column = 1, .width = 10, .type = IA, .required = true, .doc = "material id"};
}

FieldSpec density() {
    return {.name = "RO", .column = 11, .width = 10, .type = F, .required = true, .doc = "mass density"};
}

KeywordSchema mat_null() {
    return {
        .name = "*MAT_NULL",
        .aliases = {"*MAT_009"},
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    mid(),
                    density(),
                    {.name = "PC",
                     .column = 21,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "pressure cutoff (<= 0)"},
                    {.name = "MU",
                     .column = 31,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "dynamic viscosity"},
                    {.name = "TEROD",
                     .column = 41,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "relative volume for erosion in tension"},
                    {.name = "CEROD",
                     .column = 51,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "relative volume for erosion in compression"},
                    {.name = "YM",
                     .column = 61,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "Young's modulus (null beams and shells only)"},
                    {.name = "PR",
                     .column = 71,
                     .width = 10,
                     .type = F,
                     .default_value = 0.0,
                     .doc = "Poisson's ratio (null beams and shells only)"},
                },
        }},
        .doc = "no deviatoric strength: the pressure comes from the part's EOS (fluids, bird strike)",
        .options = {title_option()},
    };
}

KeywordSchema mat_elastic() {
    return {
        .name = "*MAT_ELASTIC",
        .aliases = {"*MAT_001"},
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            mid(),
                            density(),
                            {.name = "E",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "Young's modulus; E < 0 activates card 1.1"},
                            {.name = "PR",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "Poisson's ratio"},
                            {.name = "DA",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "axial damping factor"},
                            {.name = "DB",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "bending damping factor"},
                            // In the R16 manual, absent from pydyna (which leaves 61-80 unused).
                            {.name = "K",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "bulk modulus (_FLUID option only)"},
                        },
                },
                {
                    .name = "Card 1.1",
                    .fields =
                        {
                            {.name = "EFUNC",
                             .column = 1,
                             .width = 10,
                             .type = A,
                             .doc = "function of E",
                             .default_text = "P"},
                            {.name = "CNVT",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e-3,
                             .doc = "convergence tolerance"},
                            {.name = "ITERLM",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 3,
                             .doc = "iteration limit"},
                        },
                    .present_if = CardCondition{.field = "E", .compare = Compare::Less, .value = 0.0},
                    .doc = "only when E < 0",
                },
            },
        .doc = "isotropic linear elastic material",
        .options =
            {
                title_option(),
                {
                    .suffix = "FLUID",
                    .cards_after = {{
                        .name = "Card 2",
                        .fields =
                            {
                                {.name = "VC",
                                 .column = 1,
                                 .width = 10,
                                 .type = F,
                                 .doc = "tensor viscosity coefficient"},
                                {.name = "CP", .column = 11, .width = 10, .type = F, .doc = "cavitation pressure"},
                            },
                    }},
                    .doc = "fluid variant: K on card 1 and a second card VC, CP",
                },
            },
    };
}

KeywordSchema mat_plastic_kinematic() {
    return {
        .name = "*MAT_PLASTIC_KINEMATIC",
        .aliases = {"*MAT_003"},
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            mid(),
                            density(),
                            {.name = "E",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "Young's modulus"},
                            {.name = "PR",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "Poisson's ratio"},
                            {.name = "SIGY",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "yield stress"},
                            {.name = "ETAN",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "tangent modulus"},
                            {.name = "BETA",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "hardening parameter (0 kinematic, 1 isotropic)"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "SRC",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "Cowper-Symonds strain-rate parameter C"},
                            {.name = "SRP",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "Cowper-Symonds parameter P"},
                            {.name = "FS",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e20,
                             .doc = "failure strain"},
                            {.name = "VP",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .choices = {{0, "scale the yield stress"}, {1, "viscoplastic"}},
                             .doc = "rate-effect formulation"},
                        },
                },
            },
        .doc = "bilinear elastic-plastic material with Cowper-Symonds rate effects",
        .options = {title_option()},
    };
}

KeywordSchema mat_johnson_cook() {
    return {
        .name = "*MAT_JOHNSON_COOK",
        .aliases = {"*MAT_015"},
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            mid(),
                            density(),
                            {.name = "G",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .required = true,
                             .doc = "shear modulus"},
                            {.name = "E", .column = 31, .width = 10, .type = F, .doc = "Young's modulus"},
                            {.name = "PR", .column = 41, .width = 10, .type = F, .doc = "Poisson's ratio"},
                            {.name = "DTF",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "minimum time step for erosion"},
                            {.name = "VP",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .choices = {{0, "scale the yield stress"}, {1, "viscoplastic"}},
                             .doc = "rate-effect formulation"},
                            {.name = "RATEOP",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .choices = {{0, ""}, {1, ""}, {2, ""}, {3, ""}, {4, ""}, {5, ""}},
                             .doc = "strain-rate law; selects the card 4 layout"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "A", .column = 1, .width = 10, .type = F, .doc = "yield constant"},
                            {.name = "B",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "hardening constant"},
                            {.name = "N",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "hardening exponent"},
                            {.name = "C",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "strain-rate constant"},
                            {.name = "M", .column = 41, .width = 10, .type = F, .doc = "thermal-softening exponent"},
                            {.name = "TM", .column = 51, .width = 10, .type = F, .doc = "melt temperature"},
                            {.name = "TR", .column = 61, .width = 10, .type = F, .doc = "room temperature"},
                            {.name = "EPS0", .column = 71, .width = 10, .type = F, .doc = "reference strain rate"},
                        },
                },
                {
                    .name = "Card 3",
                    .fields =
                        {
                            {.name = "CP", .column = 1, .width = 10, .type = F, .doc = "specific heat"},
                            {.name = "PC",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "pressure cutoff (spall)"},
                            {.name = "SPALL",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 2.0,
                             .zero_is_default = true,  // "EQ.0.0: set to 2.0" (a known Workbench pitfall)
                             .doc = "spall type"},
                            {.name = "IT",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .choices = off_on(),
                             .doc = "plastic strain iteration"},
                            {.name = "D1",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "failure parameter",
                             .aliases = {"BETA"}},
                            {.name = "D2",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "failure parameter",
                             .aliases = {"WC"}},
                            {.name = "D3",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "failure parameter",
                             .aliases = {"DC"}},
                            {.name = "D4",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "failure parameter",
                             .aliases = {"GAMMA"}},
                        },
                },
                // pydyna's merged card 4 (R16 has variants 4a/4b/4c by RATEOP). Optional: older
                // editions stop after card 3.
                {
                    .name = "Card 4",
                    .fields =
                        {
                            {.name = "D5", .column = 1, .width = 10, .type = F, .doc = "failure parameter"},
                            {.name = "C2",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .doc = "rate parameter, meaning depends on RATEOP (C2/P/XNP/D)",
                             .aliases = {"P", "XNP", "D"}},
                            {.name = "EROD", .column = 21, .width = 10, .type = F, .doc = "erosion flag"},
                            {.name = "EFMIN",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0e-6,
                             .doc = "lower bound of the failure strain"},
                            {.name = "NUMINT",
                             .column = 41,
                             .width = 10,
                             .type = F,  // real in pydyna
                             .default_value = 0.0,
                             .doc = "failed integration points before erosion"},
                            {.name = "K", .column = 51, .width = 10, .type = F, .doc = "RATEOP = 5 only"},
                            {.name = "EPS1", .column = 61, .width = 10, .type = F, .doc = "RATEOP = 5 only"},
                            {.name = "DMODEL",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .choices = {{0, ""}, {1, ""}, {2, ""}},
                             .doc = "damage model"},
                        },
                    .repeat = CardRepeat::Optional,
                },
            },
        .doc = "Johnson-Cook plasticity and damage (needs an EOS for the pressure)",
        .options = {title_option()},
    };
}

KeywordSchema mat_add_erosion() {
    return {
        .name = "*MAT_ADD_EROSION",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "MID",
                             .column = 1,
                             .width = 10,
                             .type = IA,
                             .required = true,
                             .doc = "material the criteria apply to"},
                            {.name = "EXCL",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "exclusion value: a criterion equal to EXCL is not used"},
                            {.name = "MXPRES", .column = 21, .width = 10, .type = F, .doc = "maximum pressure"},
                            {.name = "MNEPS", .column = 31, .width = 10, .type = F, .doc = "minimum principal strain"},
                            {.name = "EFFEPS", .column = 41, .width = 10, .type = F, .doc = "maximum effective strain"},
                            {.name = "VOLEPS",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "volumetric strain"},
                            {.name = "NUMFIP",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "number or percentage of failed integration points"},
                            {.name = "NCS",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "number of criteria that must be met"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "MNPRES", .column = 1, .width = 10, .type = F, .doc = "minimum pressure"},
                            {.name = "SIGP1", .column = 11, .width = 10, .type = F, .doc = "maximum principal stress"},
                            {.name = "SIGVM", .column = 21, .width = 10, .type = F, .doc = "equivalent stress"},
                            {.name = "MXEPS", .column = 31, .width = 10, .type = F, .doc = "maximum principal strain"},
                            {.name = "EPSSH", .column = 41, .width = 10, .type = F, .doc = "tensorial shear strain"},
                            {.name = "SIGTH", .column = 51, .width = 10, .type = F, .doc = "threshold stress"},
                            {.name = "IMPULSE", .column = 61, .width = 10, .type = F, .doc = "stress impulse"},
                            {.name = "FAILTM", .column = 71, .width = 10, .type = F, .doc = "failure time"},
                        },
                },
                {
                    .name = "Card 3",
                    .fields =
                        {
                            {.name = "IDAM",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .doc = "damage model selector (A8 in R16)"},
                            unused(11),
                            unused(21),
                            unused(31),
                            unused(41),
                            unused(51),
                            unused(61),
                            {.name = "LCREGD",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .doc = "curve of element-size regularisation factors"},
                        },
                    .repeat = CardRepeat::Optional,
                },
                {
                    .name = "Card 4",
                    .fields =
                        {
                            {.name = "LCFLD", .column = 1, .width = 10, .type = I, .doc = "forming limit curve"},
                            {.name = "NSFF",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 10,
                             .doc = "stress fade-out cycles"},
                            {.name = "EPSTHIN", .column = 21, .width = 10, .type = F, .doc = "thinning strain"},
                            {.name = "ENGCRT",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .doc = "critical energy (nonlocal)"},
                            {.name = "RADCRT",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .doc = "critical radius (nonlocal)"},
                            {.name = "LCEPS12",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .doc = "in-plane shear strain curve"},
                            {.name = "LCEPS13",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .doc = "transverse shear strain curve"},
                            {.name = "LCEPSMX",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .doc = "major principal strain curve"},
                        },
                    .repeat = CardRepeat::Optional,
                },
                {
                    .name = "Card 5",
                    .fields =
                        {
                            {.name = "DTEFLT", .column = 1, .width = 10, .type = F, .doc = "strain-rate filter period"},
                            {.name = "VOLFRAC",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.5,
                             .doc = "failed volume fraction (higher-order solids)"},
                            {.name = "MXTMP", .column = 21, .width = 10, .type = F, .doc = "maximum temperature"},
                            {.name = "DTMIN", .column = 31, .width = 10, .type = F, .doc = "minimum time step"},
                            // The last three only in newer editions (pydyna); types UNVERIFIED.
                            {.name = "FFUNC", .column = 41, .width = 10, .type = I, .doc = "failure function"},
                            {.name = "DIAGR", .column = 51, .width = 10, .type = F, .doc = "diagonal-ratio criterion"},
                            {.name = "EDGER", .column = 61, .width = 10, .type = F, .doc = "edge-ratio criterion"},
                        },
                    .repeat = CardRepeat::Optional,
                },
            },
        .doc = "erosion criteria added to a material; a criterion equal to EXCL (0) is not used",
        .options = {title_option()},
    };
}

}  // namespace

std::vector<KeywordSchema> material_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(mat_null());
    k.push_back(mat_elastic());
    k.push_back(mat_plastic_kinematic());
    k.push_back(mat_johnson_cook());
    k.push_back(mat_add_erosion());
    return k;
}

}  // namespace sphdeck::keywords::tables
