// SPH rules: LS-DYNA SPH controls, sections and particles (*CONTROL_SPH manual page and friends).
// One row per rule: code, name, default severity, since-version, source, summary and the
// documentation `sphdeck rule CODE` prints (what / why / fix / before / after).
// The deck snippets are column-exact: keep fields aligned when editing them.
#include "lint/registry.hpp"

namespace sphdeck::lint::detail {
namespace {

constexpr RuleInfo kSphRules[] = {
    // SPH010 form12-requires-mpp
    {.code = "SPH010",
     .name = "form12-requires-mpp",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "CONTROL_SPH R2e",
     .summary = "FORM 12 (or 13) on a run that is SMP (error) or not known to be MPP (warning)",
     .doc = {.what = "Reports FORM 12 (moving least squares) or 13 (incompressible SPH) when the "
                     "run is SMP, given by `--solver smp` or the configuration (error), or when "
                     "nothing says it is MPP (warning). MPP is known from `--solver mpp`, the "
                     "configuration file, any *CONTROL_MPP_ keyword, or `memory2=` on the "
                     "*KEYWORD line.",
             .why = "The moving-least-squares formulation exists only in MPP LS-DYNA "
                    "(*CONTROL_SPH, Remark 2e); newer editions restrict FORM 13 to MPP as well. "
                    "An SMP run cannot use them.",
             .fix = "Run MPP LS-DYNA and say so (`--solver mpp`, or an MPP keyword in the deck), "
                    "or choose a formulation SMP offers: FORM 1 for solids, 15 or 16 for fluids.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
)deck",
             .after = R"deck($ run with MPP LS-DYNA (sphdeck --solver mpp)
*CONTROL_MPP_DECOMPOSITION_DISTRIBUTE_SPH_ELEMENTS
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
)deck"}},

    // SPH011 form12-constant-h
    {.code = "SPH011",
     .name = "form12-constant-h",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "R2e",
     .summary = "FORM 12 and an SPH section with HMIN or HMAX other than 1.0",
     .doc = {.what = "Reports FORM 12 together with an SPH section whose HMIN or HMAX is not 1.0. "
                     "Blank or zero fields count as their defaults, 0.2 and 2.0.",
             .why = "For the moving-least-squares formulation the manual strongly advises a "
                    "constant smoothing length, obtained with HMIN = HMAX = 1.0 on *SECTION_SPH "
                    "(*CONTROL_SPH, Remark 2e).",
             .fix = "Set HMIN and HMAX to 1.0 on every section used by SPH parts.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       1.0       1.0       0.0     1e+20       0.0         0
)deck"}},

    // SPH012 form12-only-fields
    {.code = "SPH012",
     .name = "form12-only-fields",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "card 3",
     .summary = "ISTAB or QL set to a non-default value while FORM is not 12",
     .doc = {.what = "Reports ISTAB or QL on card 3 of *CONTROL_SPH set to something other than "
                     "their defaults (0 and 0.01) while FORM is not 12.",
             .why = "ISTAB, the stabilisation type, and QL, the quasi-linear coefficient, serve "
                    "only the moving-least-squares formulation FORM 12 (*CONTROL_SPH, card 3). "
                    "With any other FORM they are ignored, so the tuning does nothing; often FORM "
                    "12 was meant.",
             .fix = "Set FORM 12 if moving least squares was intended (see SPH010); otherwise "
                    "leave ISTAB and QL blank.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0         1       0.1
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0
)deck"}},

    // SPH013 ql-range
    {.code = "SPH013",
     .name = "ql-range",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R5",
     .summary = "FORM 12 and QL outside 0.001-0.1",
     .doc = {.what = "Reports FORM 12 with a quasi-linear coefficient QL below 0.001 or above 0.1.",
             .why = "QL trades accuracy for stability in the moving-least-squares formulation. "
                    "The default 0.01 suits most cases; the manual suggests going down to 0.001 "
                    "for small deformations and up to 0.1 for extreme ones that turn unstable "
                    "(*CONTROL_SPH, Remark 5). Values outside that span have no guidance.",
             .fix = "Keep QL between 0.001 and 0.1, starting from the default 0.01.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0         0       0.5
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        12       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         0         0       0.1
)deck"}},

    // SPH020 asph-requires-ellipse
    {.code = "SPH020",
     .name = "asph-requires-ellipse",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "R2g",
     .summary = "FORM 9 or 10 and an SPH part whose section is not *SECTION_SPH_ELLIPSE",
     .doc = {.what = "Reports FORM 9 or 10 (adaptive SPH) while an SPH part uses a section other "
                     "than *SECTION_SPH_ELLIPSE.",
             .why = "The adaptive formulations use an anisotropic smoothing tensor whose axes "
                    "follow the particle spacing; the manual requires them to be used with "
                    "*SECTION_SPH_ELLIPSE, which supplies the per-axis constants (*CONTROL_SPH, "
                    "Remark 2g).",
             .fix = "Give every SPH part a *SECTION_SPH_ELLIPSE (its second card sets HXCSLH, "
                    "HYCSLH, HZCSLH), or choose a FORM that is not adaptive.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         9       0.0     1e+15
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         9       0.0     1e+15
*SECTION_SPH_ELLIPSE
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
$#  hxcslh    hycslh    hzcslh     hxini     hyini     hzini
       1.2       1.2       1.2
)deck"}},

    // SPH021 asph-3d-only
    {.code = "SPH021",
     .name = "asph-3d-only",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "R2g",
     .summary = "FORM 9 or 10 with IDIM other than 3",
     .doc = {.what = "Reports FORM 9 or 10 (adaptive SPH) with IDIM 2 or -2.",
             .why = "The adaptive formulations are available for 3D problems only (*CONTROL_SPH, "
                    "Remark 2g).",
             .fix = "Use FORM 1 (or 0, 15, 16) for a 2D model, or model the problem in 3D.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         9       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
)deck"}},

    // SPH022 asph-smp-only
    {.code = "SPH022",
     .name = "asph-smp-only",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "R2g",
     .summary = "FORM 9 or 10 on an MPP run",
     .doc = {.what = "Reports FORM 9 or 10 (adaptive SPH) when the run is known to be MPP. MPP is "
                     "known from `--solver mpp`, the configuration file, any *CONTROL_MPP_ "
                     "keyword, or `memory2=` on the *KEYWORD line.",
             .why = "The adaptive formulations are available in SMP LS-DYNA only (*CONTROL_SPH, "
                    "Remark 2g).",
             .fix = "Run SMP LS-DYNA (and remove the MPP-only settings), or pick a formulation "
                    "MPP offers, such as FORM 1 or 12.",
             .before = R"deck(*KEYWORD memory=200m memory2=100m
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         9       0.0     1e+15
)deck",
             .after = R"deck(*KEYWORD memory=200m
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         9       0.0     1e+15
)deck"}},

    // SPH023 ellipse-without-asph
    {.code = "SPH023",
     .name = "ellipse-without-asph",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "R2g",
     .summary = "*SECTION_SPH_ELLIPSE while FORM is neither 9 nor 10",
     .doc = {.what = "Reports a *SECTION_SPH_ELLIPSE while FORM is neither 9 nor 10.",
             .why = "The ellipse section carries the anisotropic smoothing constants of the "
                    "adaptive formulations FORM 9 and 10 (*CONTROL_SPH, Remark 2g). With another "
                    "FORM the deck does not say how its per-axis values are used; most likely "
                    "FORM 9 or 10 was intended.",
             .fix = "Set FORM 9 or 10 (3D, SMP), or use a plain *SECTION_SPH.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
*SECTION_SPH_ELLIPSE
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
$#  hxcslh    hycslh    hzcslh     hxini     hyini     hzini
       1.2       1.2       1.2
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         9       0.0     1e+15
*SECTION_SPH_ELLIPSE
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
$#  hxcslh    hycslh    hzcslh     hxini     hyini     hzini
       1.2       1.2       1.2
)deck"}},

    // SPH030 iavis-solid-in-2d
    {.code = "SPH030",
     .name = "iavis-solid-in-2d",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "IAVIS",
     .summary = "IAVIS 1 with IDIM 2 or -2",
     .doc = {.what = "Reports IAVIS 1, the solid-element artificial viscosity, in a 2D model "
                     "(IDIM 2 or -2).",
             .why = "The solid-element viscosity is not supported for plane-strain or "
                    "axisymmetric SPH (*CONTROL_SPH, IAVIS).",
             .fix = "Use IAVIS 0, the Monaghan viscosity, which the manual recommends for SPH in "
                    "general (Remark 4).",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         1       100
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
)deck"}},

    // SPH031 axisymmetric-form
    {.code = "SPH031",
     .name = "axisymmetric-form",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "R2f",
     .summary = "IDIM -2 and FORM not in {0, 1, 15, 16}",
     .doc = {.what = "Reports an axisymmetric model (IDIM -2) whose FORM is not 0, 1, 15 or 16.",
             .why = "Only formulations 0, 1, 15 and 16 are implemented for 2D axisymmetric "
                    "problems (*CONTROL_SPH, Remark 2f).",
             .fix = "Use FORM 1 for solids, 15 or 16 for fluids.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20        -2       150         5       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20        -2       150        15       0.0     1e+15
)deck"}},

    // SPH032 form-not-recommended
    {.code = "SPH032",
     .name = "form-not-recommended",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "R2c",
     .summary = "FORM 2 or 3",
     .doc = {.what = "Reports FORM 2 (symmetric formulation) or 3 (symmetric renormalised "
                     "formulation).",
             .why = "The manual advises against the symmetric formulations in every application "
                    "(*CONTROL_SPH, Remark 2c).",
             .fix = "Use FORM 1 for solid structures, 15 or 16 for fluids (Remarks 2a and 2b).",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         2       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // SPH033 fluid-form-with-failure
    {.code = "SPH033",
     .name = "fluid-form-with-failure",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "R2b",
     .summary = "FORM 15 or 16 and an SPH material with failure or erosion criteria",
     .doc = {.what = "Reports FORM 15 or 16 while a material used by SPH parts has failure or "
                     "erosion criteria: a failure strain in the material, a *MAT_ADD_EROSION for "
                     "it, or similar.",
             .why = "The enhanced fluid formulations smooth the pressure field, so the manual "
                    "does not recommend them for materials that fail or for problems with strong "
                    "strain localisation (*CONTROL_SPH, Remark 2b).",
             .fix = "Use FORM 1 for solids that fail; keep FORM 15 or 16 for genuine fluids "
                    "without failure.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        15       0.0     1e+15
*MAT_PLASTIC_KINEMATIC
$#     mid        ro         e        pr      sigy      etan      beta
         1    7.8e-9  210000.0       0.3     250.0    1000.0       0.0
$#     src       srp        fs        vp
       0.0       0.0       0.3       0.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
*MAT_PLASTIC_KINEMATIC
$#     mid        ro         e        pr      sigy      etan      beta
         1    7.8e-9  210000.0       0.3     250.0    1000.0       0.0
$#     src       srp        fs        vp
       0.0       0.0       0.3       0.0
)deck"}},

    // SPH034 form-advice
    {.code = "SPH034",
     .name = "form-advice",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R2a, R2b",
     .summary = "FORM 0 on solid parts (1 is recommended) or on fluid parts (15 or 16 are "
                "recommended)",
     .doc = {.what = "Reports the default FORM 0 when the SPH parts are solids, for which FORM 1 "
                     "is recommended, or fluids (such as *MAT_NULL with an equation of state), "
                     "for which FORM 15 or 16 are recommended.",
             .why = "For most solid structures the renormalised FORM 1 gives more accurate "
                    "results near boundaries (*CONTROL_SPH, Remark 2a). For fluids and fluid-like "
                    "materials the enhanced fluid formulations are recommended, FORM 16 being "
                    "more accurate and more expensive (Remark 2b).",
             .fix = "Set FORM 1 for solid parts, or 15/16 for fluid parts.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         0       0.0     1e+15
*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1    1.0e-9   -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150        15       0.0     1e+15
*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         1         0         0         0         0
*MAT_NULL
$#     mid        ro        pc        mu     terod     cerod        ym        pr
         1    1.0e-9   -1.0e-3       0.0       0.0       0.0       0.0       0.0
)deck"}},

    // SPH035 lagrangian-large-deformation
    {.code = "SPH035",
     .name = "lagrangian-large-deformation",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R2d",
     .summary = "FORM 7 or 8: tensile-stable, but not suited to very large deformation",
     .doc = {.what = "Reports FORM 7 or 8, the total Lagrangian formulations.",
             .why = "A Lagrangian kernel avoids the tensile instability of the Eulerian forms, "
                    "but cannot follow very large deformations (*CONTROL_SPH, Remark 2d). "
                    "Penetration, fragmentation or flow need an Eulerian-kernel form (such as 1, "
                    "15 or 16) or the moving-least-squares FORM 12 (Remarks 2c and 2e).",
             .fix = "Keep FORM 7 or 8 only if the deformation stays moderate; otherwise use FORM "
                    "1 or, in MPP, FORM 12.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         7       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // SPH040 ierod-zero-with-erosion
    {.code = "SPH040",
     .name = "ierod-zero-with-erosion",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "R3a",
     .summary = "IEROD 0 while erosion criteria exist (material, *MAT_ADD_EROSION or ERODE)",
     .doc = {.what = "Reports IEROD 0 while an erosion criterion applies to SPH particles: a "
                     "failure criterion of their material, a *MAT_ADD_EROSION, or ERODE on "
                     "*CONTROL_TIMESTEP.",
             .why = "With IEROD 0 particles stay active, which the manual does not recommend when "
                    "materials erode: many material models still reset the stress to zero from "
                    "time to time. If an unaltered stress field is wanted, the erosion criteria "
                    "should be removed instead (*CONTROL_SPH, Remark 3a).",
             .fix = "Set IEROD 1, 2 or 3 to deactivate eroded particles, or remove the erosion "
                    "criteria.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
*MAT_ADD_EROSION
$#     mid      excl    mxpres     mneps    effeps    voleps    numfip       ncs
         1       0.0       0.0       0.0       0.8       0.0       1.0       1.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         1         0         0       100
*MAT_ADD_EROSION
$#     mid      excl    mxpres     mneps    effeps    voleps    numfip       ncs
         1       0.0       0.0       0.0       0.8       0.0       1.0       1.0
)deck"}},

    // SPH041 ierod-without-erosion
    {.code = "SPH041",
     .name = "ierod-without-erosion",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R3",
     .summary = "IEROD not 0 while no erosion criterion exists anywhere",
     .doc = {.what = "Reports IEROD 1, 2 or 3 while no erosion criterion exists: no failure in "
                     "the SPH materials, no *MAT_ADD_EROSION, no ERODE on *CONTROL_TIMESTEP.",
             .why = "IEROD decides what happens to a particle once an erosion criterion is met, "
                    "and those criteria come from the material, *MAT_ADD_EROSION or ERODE "
                    "(*CONTROL_SPH, Remark 3). Without any, IEROD has nothing to act on; perhaps "
                    "a criterion was forgotten.",
             .fix = "Add the intended erosion criterion, or set IEROD back to 0.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         2         0         0       100
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
)deck"}},

    // SPH042 icont-without-deactivation
    {.code = "SPH042",
     .name = "icont-without-deactivation",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R3f",
     .summary = "ICONT 1 while nothing can deactivate particles",
     .doc = {.what = "Reports ICONT 1 while no particle can be deactivated. Particles can be "
                     "deactivated by erosion (IEROD 1-3 with a criterion), by leaving the BOXID "
                     "box, or by exceeding MAXV.",
             .why = "ICONT 1 switches contact off for deactivated particles (*CONTROL_SPH, Remark "
                    "3f). If no particle can be deactivated the flag does nothing, which may mean "
                    "a deactivation setting is missing.",
             .fix = "Leave ICONT at 0, or add the deactivation it was meant for.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         1         0       100
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
)deck"}},

    // SPH043 ishow-without-deactivation
    {.code = "SPH043",
     .name = "ishow-without-deactivation",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R3e",
     .summary = "ISHOW 1 while nothing can deactivate particles",
     .doc = {.what = "Reports ISHOW 1 while no particle can be deactivated. Particles can be "
                     "deactivated by erosion (IEROD 1-3 with a criterion), by leaving the BOXID "
                     "box, or by exceeding MAXV.",
             .why = "ISHOW 1 makes LS-PrePost draw deactivated particles differently from active "
                    "ones (*CONTROL_SPH, Remark 3e); with nothing to deactivate it has no effect.",
             .fix = "Leave ISHOW at 0, or add the deactivation it was meant to show.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         1         0         0         0       100
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
)deck"}},

    // SPH050 monaghan-coefficients
    {.code = "SPH050",
     .name = "monaghan-coefficients",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "R4",
     .summary = "IAVIS 0 and the Q1/Q2 acting on SPH parts not both 1.0",
     .doc = {.what = "Reports the Monaghan viscosity (IAVIS 0) while the coefficients that apply "
                     "to SPH parts, from *CONTROL_BULK_VISCOSITY or the parts' *HOURGLASS, are "
                     "not both 1.0; the defaults 1.5 and 0.06 count.",
             .why = "With the Monaghan form the manual recommends Q1 = Q2 = 1.0, set on "
                    "*CONTROL_BULK_VISCOSITY or *HOURGLASS (*CONTROL_SPH, Remark 4). The defaults "
                    "1.5 and 0.06 are the values meant for solid elements.",
             .fix = "Set Q1 = Q2 = 1.0 on an *HOURGLASS used by the SPH parts (this leaves solid "
                    "elements at their defaults), or on *CONTROL_BULK_VISCOSITY in an SPH-only "
                    "model.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
*CONTROL_BULK_VISCOSITY
$#      q1        q2      type     btype    tstype
       1.5      0.06         1         0         0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
*CONTROL_BULK_VISCOSITY
$#      q1        q2      type     btype    tstype
       1.0       1.0         1         0         0
)deck"}},

    // SPH060 cont-without-coupling
    {.code = "SPH060",
     .name = "cont-without-coupling",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "CONT",
     .summary = "CONT 1 with two or more SPH parts and no interaction section or SPH-to-SPH "
                "coupling",
     .doc = {.what = "Reports CONT 1 in a model with two or more SPH parts and neither a "
                     "*SECTION_SPH_INTERACTION nor a *DEFINE_SPH_TO_SPH_COUPLING.",
             .why = "CONT 1 turns off the particle approximation between different SPH parts, "
                    "except where the INTERACTION option of *SECTION_SPH asks for it; "
                    "*DEFINE_SPH_TO_SPH_COUPLING is the other way to make parts interact "
                    "(*CONTROL_SPH, CONT). With neither, the parts pass through each other.",
             .fix = "Set CONT 0, give the interacting parts *SECTION_SPH_INTERACTION, or couple "
                    "them with *DEFINE_SPH_TO_SPH_COUPLING.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         1         0         0         0         0         0         0       100
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         1         0         0         0         0         0         0       100
*DEFINE_SPH_TO_SPH_COUPLING
$#    sida      sidb     satyp     sbtyp     iboxa     iboxb     pfact      srad
         1         2         1         1         0         0       1.0       1.0
)deck"}},

    // SPH070 box-undefined
    {.code = "SPH070",
     .name = "box-undefined",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "BOXID",
     .summary = "BOXID names no *DEFINE_BOX",
     .doc = {.what = "Reports a non-zero BOXID on *CONTROL_SPH that matches no *DEFINE_BOX.",
             .why = "SPH approximations are computed only inside the box BOXID names, and "
                    "particles leaving it are deactivated (*CONTROL_SPH, BOXID); without the box "
                    "the setting cannot be applied and the solver stops at input.",
             .fix = "Point BOXID at an existing box, define the box, or set BOXID 0 for no box.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         5     1e+20         3       150         1       0.0     1e+15
*DEFINE_BOX
$#   boxid       xmn       xmx       ymn       ymx       zmn       zmx
         1    -100.0     100.0    -100.0     100.0    -100.0     100.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         1     1e+20         3       150         1       0.0     1e+15
*DEFINE_BOX
$#   boxid       xmn       xmx       ymn       ymx       zmn       zmx
         1    -100.0     100.0    -100.0     100.0    -100.0     100.0
)deck"}},

    // SPH071 particles-outside-box
    {.code = "SPH071",
     .name = "particles-outside-box",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "BOXID",
     .summary = "particles that start outside the BOXID box and are deactivated at once",
     .doc = {.what = "Reports particles whose initial position lies outside the box named by "
                     "BOXID, with their count and the first ids.",
             .why = "A particle outside the box is deactivated (*CONTROL_SPH, BOXID), so "
                    "particles that start there never take part in the computation. The box was "
                    "probably sized for another model or unit system.",
             .fix = "Enlarge the box to contain every particle at the start, with room for their "
                    "motion, or remove the particles.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         1     1e+20         3       150         1       0.0     1e+15
*DEFINE_BOX
$#   boxid       xmn       xmx       ymn       ymx       zmn       zmx
         1    -100.0     100.0    -100.0     100.0    -100.0     100.0
*NODE
$#   nid               x               y               z      tc      rc
     101            50.0             0.0             0.0       0       0
     102           150.0             0.0             0.0       0       0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         1     1e+20         3       150         1       0.0     1e+15
*DEFINE_BOX
$#   boxid       xmn       xmx       ymn       ymx       zmn       zmx
         1    -100.0     200.0    -100.0     100.0    -100.0     100.0
*NODE
$#   nid               x               y               z      tc      rc
     101            50.0             0.0             0.0       0       0
     102           150.0             0.0             0.0       0       0
)deck"}},

    // SPH072 maxv-below-initial-speed
    {.code = "SPH072",
     .name = "maxv-below-initial-speed",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "MAXV",
     .summary = "an initial particle speed above MAXV",
     .doc = {.what = "Reports particles whose initial speed, from *INITIAL_VELOCITY keywords, "
                     "exceeds MAXV.",
             .why = "Particles faster than MAXV are deactivated (*CONTROL_SPH, MAXV), so these "
                    "are lost in the first cycle. MAXV is often left in another unit system: "
                    "1.0e5 is 100 m/s in mm/s.",
             .fix = "Raise MAXV well above the largest speed expected during the run, or leave it "
                    "blank for the default 1.0e15.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0    1.0e+5
*INITIAL_VELOCITY_NODE
$#     nid        vx        vy        vz       vxr       vyr       vzr
       101 -150000.0       0.0       0.0       0.0       0.0       0.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0    1.0e+6
*INITIAL_VELOCITY_NODE
$#     nid        vx        vy        vz       vxr       vyr       vzr
       101 -150000.0       0.0       0.0       0.0       0.0       0.0
)deck"}},

    // SPH073 maxv-check-off
    {.code = "SPH073",
     .name = "maxv-check-off",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "MAXV",
     .summary = "MAXV negative: the velocity check is off",
     .doc = {.what = "Reports a negative MAXV.",
             .why = "On the manual page sphdeck follows, a negative MAXV switches the velocity "
                    "check off (*CONTROL_SPH, MAXV); newer manual text reads it as a limit at "
                    "|MAXV| instead, so the value means different things to different LS-DYNA "
                    "versions.",
             .fix = "Leave MAXV blank for the default limit of 1.0e15, or write the limit you "
                    "want as a positive number; if the check should really be off, suppress this "
                    "finding.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0      -1.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // SPH080 death-before-start
    {.code = "SPH080",
     .name = "death-before-start",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "DT, START",
     .summary = "DT <= START, so SPH is never computed; warning if START >= ENDTIM, info if DT < "
                "ENDTIM",
     .doc = {.what = "Reports a death time DT at or before the start time START of *CONTROL_SPH "
                     "(error). Also reports START at or after ENDTIM of *CONTROL_TERMINATION "
                     "(warning: SPH starts after the run ends) and DT before ENDTIM (info: SPH "
                     "stops before the run ends). DT blank or 0 means 1.0e20.",
             .why = "Particle approximations are computed from START until DT (*CONTROL_SPH, DT "
                    "and START); with DT <= START the window is empty and the particles never "
                    "interact.",
             .fix = "Make DT later than START; leave DT blank unless SPH must stop early.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     0.001         3       150         1     0.002     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1     0.002     1e+15
)deck"}},

    // SPH081 section-death-before-start
    {.code = "SPH081",
     .name = "section-death-before-start",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SECTION_SPH",
     .summary = "*SECTION_SPH DEATH <= START",
     .doc = {.what = "Reports an SPH section whose DEATH time is at or before its START time. "
                     "DEATH blank or 0 means 1.0e20.",
             .why = "Each SPH section computes its particles from START until DEATH "
                    "(*SECTION_SPH, DEATH and START); with DEATH <= START the particles of that "
                    "section are never computed.",
             .fix = "Make DEATH later than START, or leave it blank.",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     0.001     0.005         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20     0.005         0
)deck"}},

    // SPH090 memory-static-too-small
    {.code = "SPH090",
     .name = "memory-static-too-small",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "R1",
     .summary = "MEMORY < 0 and the estimated neighbour count exceeds |MEMORY|; info when a "
                "positive MEMORY is exceeded",
     .doc = {.what = "Compares the largest neighbour count sphdeck estimates from the particle "
                     "layout and smoothing lengths with MEMORY of *CONTROL_SPH. Error when MEMORY "
                     "is negative and the estimate exceeds |MEMORY|; info when a positive MEMORY "
                     "is exceeded (the arrays then grow).",
             .why = "A positive MEMORY is only the initial neighbour-array size and may grow "
                    "during the run; a negative MEMORY fixes the arrays, making |MEMORY| the hard "
                    "maximum number of neighbours per particle for the whole run (*CONTROL_SPH, "
                    "Remark 1). A cap below the actual count is reached from the first cycle, and "
                    "compression during the run only adds neighbours.",
             .fix = "Make |MEMORY| comfortably larger than the estimate in the message, or use a "
                    "positive value.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       -30         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3      -120         1       0.0     1e+15
)deck"}},

    // SPH091 isymp-without-planes
    {.code = "SPH091",
     .name = "isymp-without-planes",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "ISYMP",
     .summary = "ISYMP set while no *BOUNDARY_SPH_SYMMETRY_PLANE exists; error when outside 1-100",
     .doc = {.what = "Reports ISYMP set to a non-default value while the model has no "
                     "*BOUNDARY_SPH_SYMMETRY_PLANE (info), and ISYMP outside 1-100 (error, since "
                     "it is a percentage).",
             .why = "ISYMP is the percentage of the particle count reserved in memory for the "
                    "ghost particles of symmetry planes (*CONTROL_SPH, ISYMP). Without planes it "
                    "has no use; a setting here may mean the planes were left out.",
             .fix = "Add the intended symmetry planes, or leave ISYMP blank.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0        20
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
)deck"}},

    // SPH092 isymp-large-model
    {.code = "SPH092",
     .name = "isymp-large-model",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "ISYMP",
     .summary = "symmetry planes, over a million particles and ISYMP 100 (10-20 is recommended)",
     .doc = {.what = "Reports ISYMP 100 (the default) in a model with symmetry planes and more "
                     "than one million particles.",
             .why = "By default memory for ghost particles is reserved for all particles; for "
                    "large models the manual recommends 10-20 %, since only particles near a "
                    "plane are mirrored (*CONTROL_SPH, ISYMP).",
             .fix = "Set ISYMP between 10 and 20, more if a large share of the particles lies "
                    "near the planes.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
*BOUNDARY_SPH_SYMMETRY_PLANE
$#     vtx       vty       vtz       vhx       vhy       vhz
       0.0       0.0       0.0       0.0       0.0       1.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0        20
*BOUNDARY_SPH_SYMMETRY_PLANE
$#     vtx       vty       vtz       vhx       vhy       vhz
       0.0       0.0       0.0       0.0       0.0       1.0
)deck"}},

    // SPH093 ithk-with-sst
    {.code = "SPH093",
     .name = "ithk-with-sst",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "ITHK",
     .summary = "ITHK 1 while a contact gives an explicit slave thickness SST (ITHK is then "
                "ignored)",
     .doc = {.what = "Reports ITHK 1 while a contact involving SPH particles gives a non-zero "
                     "slave thickness SST.",
             .why = "ITHK 1 derives the contact thickness from each particle's volume, but that "
                    "calculation is skipped when the contact card provides a non-zero SST "
                    "(*CONTROL_SPH, ITHK). One of the two settings has no effect.",
             .fix = "Set SST to 0 so that ITHK applies, or set ITHK 0 and keep the explicit "
                    "thickness.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         1         0      0.01
*CONTACT_AUTOMATIC_NODES_TO_SURFACE
$#    ssid      msid     sstyp     mstyp    sboxid    mboxid       spr       mpr
         1         2         4         3         0         0         0         0
$#      fs        fd        dc        vc       vdc    penchk        bt        dt
       0.0       0.0       0.0       0.0       0.0         0       0.0     1e+20
$#     sfs       sfm       sst       mst      sfst      sfmt       fsf       vsf
       1.0       1.0       0.5       0.0       1.0       1.0       1.0       1.0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
$#    cont     deriv       ini     ishow     ierod     icont     iavis     isymp
         0         0         0         0         0         0         0       100
$#    ithk     istab        ql
         1         0      0.01
*CONTACT_AUTOMATIC_NODES_TO_SURFACE
$#    ssid      msid     sstyp     mstyp    sboxid    mboxid       spr       mpr
         1         2         4         3         0         0         0         0
$#      fs        fd        dc        vc       vdc    penchk        bt        dt
       0.0       0.0       0.0       0.0       0.0         0       0.0     1e+20
$#     sfs       sfm       sst       mst      sfst      sfmt       fsf       vsf
       1.0       1.0       0.0       0.0       1.0       1.0       1.0       1.0
)deck"}},

    // SPH094 ncbs-invalid
    {.code = "SPH094",
     .name = "ncbs-invalid",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "NCBS",
     .summary = "NCBS < 1",
     .doc = {.what = "Reports NCBS, the number of cycles between particle sorts, below 1.",
             .why = "NCBS sets how many time steps pass between two sorts of the particles, i.e. "
                    "neighbour searches (*CONTROL_SPH, NCBS); a count below one has no meaning.",
             .fix = "Use NCBS 1 (the default, a sort every cycle) or a small positive count.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         0         0     1e+20         3       150         1       0.0     1e+15
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},

    // SPH100 cslh-range
    {.code = "SPH100",
     .name = "cslh-range",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SECTION_SPH",
     .summary = "CSLH below 1 is inadmissible (error); outside 1.05-1.3 (warning)",
     .doc = {.what = "Reports CSLH of an SPH section below 1.0 (error) or outside 1.05-1.3 "
                     "(warning). Blank or 0 means the default 1.2.",
             .why = "CSLH scales the initial smoothing length from the particle spacing. The "
                    "manual gives 1.05-1.3 as the acceptable range, calls values below 1 "
                    "inadmissible and notes that larger values only add computing time "
                    "(*SECTION_SPH, CSLH).",
             .fix = "Use a value between 1.05 and 1.3, usually the default 1.2.",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       0.8       0.2       2.0       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // SPH101 hmin-hmax
    {.code = "SPH101",
     .name = "hmin-hmax",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SECTION_SPH",
     .summary = "HMIN > 1, HMAX < 1, or HMIN > HMAX",
     .doc = {.what = "Reports an SPH section with HMIN above 1, HMAX below 1, or HMIN above HMAX.",
             .why = "HMIN and HMAX multiply the initial smoothing length to give the lower and "
                    "upper bounds of h during the run (*SECTION_SPH, HMIN and HMAX). The bounds "
                    "must bracket the initial value, HMIN <= 1 <= HMAX; HMIN = HMAX = 1 keeps h "
                    "constant.",
             .fix = "Choose HMIN <= 1 <= HMAX; the defaults are 0.2 and 2.0.",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       2.0       0.2       0.0     1e+20       0.0         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // SPH102 sphini-overrides-cslh
    {.code = "SPH102",
     .name = "sphini-overrides-cslh",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "SECTION_SPH",
     .summary = "SPHINI > 0 and CSLH given explicitly (CSLH is then ignored)",
     .doc = {.what = "Reports an SPH section that gives both SPHINI > 0 and an explicit CSLH.",
             .why = "When SPHINI sets the initial smoothing length, LS-DYNA skips its own "
                    "computation and CSLH does not apply (*SECTION_SPH, SPHINI).",
             .fix = "Leave CSLH blank when SPHINI is given, or drop SPHINI to let CSLH scale the "
                    "computed spacing.",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.3       0.2       2.0       2.4     1e+20       0.0         0
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1                 0.2       2.0       2.4     1e+20       0.0         0
)deck"}},

    // SPH103 quintic-kernel
    {.code = "SPH103",
     .name = "quintic-kernel",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SECTION_SPH",
     .summary = "SPHKERN 1 with HMAX < 3 or FORM not in {0, 1, 9, 10}",
     .doc = {.what = "Reports the quintic kernel (SPHKERN 1) on a section whose HMAX is below "
                     "3.0, or while FORM is not 0, 1, 9 or 10.",
             .why = "The quintic spline is meant to be used with HMAX of at least 3.0 and only "
                    "with FORM 0, 1, 9 and 10 (*SECTION_SPH, SPHKERN).",
             .fix = "Set HMAX to 3.0 or more and use one of those formulations, or go back to the "
                    "cubic spline (SPHKERN 0).",
             .before = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       2.0       0.0     1e+20       0.0         1
)deck",
             .after = R"deck(*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1       1.2       0.2       3.0       0.0     1e+20       0.0         1
)deck"}},

    // SPH104 section-not-sph
    {.code = "SPH104",
     .name = "section-not-sph",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "references",
     .summary = "an SPH particle's part has a section that is not *SECTION_SPH*",
     .doc = {.what = "Reports a part that holds SPH particles while its SECID names a section "
                     "other than *SECTION_SPH, *SECTION_SPH_ELLIPSE, *SECTION_SPH_INTERACTION or "
                     "*SECTION_SPH_USER.",
             .why = "SPH particles take their smoothing-length constants, kernel and life span "
                    "from an SPH section (*ELEMENT_SPH, PID; *SECTION_SPH). A solid or shell "
                    "section carries none of these, and the element type of the part does not "
                    "match its section.",
             .fix = "Give the part a *SECTION_SPH, or move the particles to a part that has one.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         2         1         1         0         0         0         0
*SECTION_SOLID
$#   secid    elform       aet
         2         1         0
)deck",
             .after = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         2         1         1         0         0         0         0
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         2       1.2       0.2       2.0       0.0     1e+20       0.0         0
)deck"}},

    // SPH110 planar-z
    {.code = "SPH110",
     .name = "planar-z",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "IDIM",
     .summary = "IDIM 2 or -2 and particles off the z = 0 plane",
     .doc = {.what = "Reports particles with a non-zero z coordinate in a 2D model (IDIM 2 or -2).",
             .why = "LS-DYNA 2D models, plane strain and axisymmetric alike, lie in the x-y plane "
                    "with z unused (*CONTROL_SPH, IDIM 2 and -2; LS-DYNA 2D conventions). A "
                    "particle with z not 0 shows a 3D layout read as 2D, or a model built in the "
                    "wrong plane.",
             .fix = "Place the particles in the x-y plane (z = 0), or set IDIM 3 for a 3D model.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
*NODE
$#   nid               x               y               z      tc      rc
     101             1.0             1.0             5.0       0       0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
*NODE
$#   nid               x               y               z      tc      rc
     101             1.0             1.0             0.0       0       0
)deck"}},

    // SPH111 axisymmetric-negative-radius
    {.code = "SPH111",
     .name = "axisymmetric-negative-radius",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "IDIM",
     .summary = "IDIM -2 and particles with x < 0",
     .doc = {.what = "Reports particles with a negative x coordinate in an axisymmetric model "
                     "(IDIM -2).",
             .why = "In a 2D axisymmetric model x is the radius measured from the axis of "
                    "symmetry (*CONTROL_SPH, IDIM -2), so a negative x has no physical meaning.",
             .fix = "Mirror the model to x >= 0, with the symmetry axis along y.",
             .before = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20        -2       150         1       0.0     1e+15
*NODE
$#   nid               x               y               z      tc      rc
     101            -1.0             4.0             0.0       0       0
)deck",
             .after = R"deck(*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20        -2       150         1       0.0     1e+15
*NODE
$#   nid               x               y               z      tc      rc
     101             1.0             4.0             0.0       0       0
)deck"}},

    // SPH112 particle-mass
    {.code = "SPH112",
     .name = "particle-mass",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "ELEMENT_SPH",
     .summary = "MASS 0 on a particle (a negative value is a volume: info)",
     .doc = {.what = "Reports an *ELEMENT_SPH particle whose MASS is 0 or blank (error). A "
                     "negative MASS is reported as information: it is read as a volume, the mass "
                     "following from the material density.",
             .why = "A positive MASS is the particle's mass and a negative one its volume "
                    "(*ELEMENT_SPH, MASS); with zero the particle is massless and cannot carry "
                    "momentum or density.",
             .fix = "Give the particle its mass, or its volume as a negative number.",
             .before = R"deck(*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1
)deck",
             .after = R"deck(*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
)deck"}},

    // SPH113 mass-spacing-mismatch
    {.code = "SPH113",
     .name = "mass-spacing-mismatch",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "preview",
     .summary = "particle mass differs from rho * spacing^d by more than a factor 2 (often a unit "
                "mistake)",
     .doc = {.what = "Compares each part's particle mass with its material density times the "
                     "particle spacing to the power of the dimension (rho * dx^3 in 3D) and "
                     "reports a ratio beyond a factor 2. Ratios near 1e3 or 1e9 point to a unit "
                     "mistake.",
             .why = "A particle stands for the volume around it, so its mass should be the "
                    "density times that volume (*ELEMENT_SPH, MASS; the material's RO). Otherwise "
                    "the particles start denser or lighter than the material, and the equation of "
                    "state turns the difference into a pressure jump at time zero.",
             .fix = "Recompute the masses in the deck's unit system (2 mm spacing of water in "
                    "t-mm-s: 1.0e-9 * 2^3 = 8.0e-9), or give volumes as negative masses.",
             .before = R"deck($ part 1: *MAT_NULL, RO = 1.0e-9 (t/mm^3)
*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
     102             2.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-6
     102       1          8.0e-6
)deck",
             .after = R"deck($ part 1: *MAT_NULL, RO = 1.0e-9 (t/mm^3)
*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
     102             2.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
     102       1          8.0e-9
)deck"}},

    // SPH114 coincident-particles
    {.code = "SPH114",
     .name = "coincident-particles",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "preview",
     .summary = "two particles at the same position",
     .doc = {.what = "Reports particles that share a position with another particle.",
             .why = "Two particles at one point have no distance between them: their mutual "
                    "kernel gradient has no direction and they act as one particle of double mass "
                    "(*ELEMENT_SPH; SPH particle approximation). The usual cause is a mesh read "
                    "twice, through two includes or a generator run twice.",
             .fix = "Remove the duplicate particles (and their nodes).",
             .before = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
     102             0.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
     102       1          8.0e-9
)deck",
             .after = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
*ELEMENT_SPH
$#   nid     pid            mass    nend
     101       1          8.0e-9
)deck"}},

    // SPH115 stray-particle
    {.code = "SPH115",
     .name = "stray-particle",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "preview",
     .summary = "a particle whose nearest-neighbour distance is over 3 times its part's median, "
                "inflating h0",
     .doc = {.what = "Reports a particle whose distance to its nearest neighbour in the same part "
                     "is more than three times the part's median nearest-neighbour distance, with "
                     "the smoothing length it causes.",
             .why = "LS-DYNA derives a part's initial smoothing length from the largest of its "
                    "particles' nearest-neighbour distances, times CSLH (*SECTION_SPH, CSLH; "
                    "d3view, \"Smooth length in SPH\"). One isolated particle therefore raises h "
                    "for the whole part, multiplying neighbour counts and cost and smearing the "
                    "solution.",
             .fix = "Delete or move the stray particle, give it a part of its own, or set SPHINI "
                    "explicitly.",
             .before = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
     102             2.0             0.0             0.0       0       0
     103           100.0             0.0             0.0       0       0
)deck",
             .after = R"deck(*NODE
$#   nid               x               y               z      tc      rc
     101             0.0             0.0             0.0       0       0
     102             2.0             0.0             0.0       0       0
)deck"}},

    // SPH116 fluid-without-eos
    {.code = "SPH116",
     .name = "fluid-without-eos",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "materials",
     .summary = "an SPH part with *MAT_NULL and no equation of state",
     .doc = {.what = "Reports an SPH part whose material is *MAT_NULL while its EOSID is 0 or "
                     "blank.",
             .why = "*MAT_NULL has no strength of its own and gets its pressure from an equation "
                    "of state; without one the fluid has no pressure response at all (*MAT_NULL, "
                    "R16 material manual).",
             .fix = "Give the part an equation of state, e.g. *EOS_MURNAGHAN or *EOS_GRUNEISEN "
                    "for water.",
             .before = R"deck(*PART
$#                                                               title
water
$#     pid     secid       mid     eosid      hgid      grav    adpopt      tmid
         1         1         1         0         0         0         0         0
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
*EOS_MURNAGHAN
$#   eosid     gamma        k0        v0
         1       7.0     320.0       1.0
)deck"}},

    // SPH117 murnaghan-sound-speed
    {.code = "SPH117",
     .name = "murnaghan-sound-speed",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "EOS_MURNAGHAN",
     .summary = "*EOS_MURNAGHAN with c0 = sqrt(gamma k0 / rho0) below 10 times the largest "
                "initial speed",
     .doc = {.what = "Reports an *EOS_MURNAGHAN whose reference sound speed c0 = sqrt(gamma * k0 "
                     "/ rho0) is below ten times the largest initial particle speed of the parts "
                     "that use it.",
             .why = "The manual advises choosing k0 so that c0 is at least ten times the largest "
                    "velocity (*EOS_MURNAGHAN, R16 material manual); density then varies by about "
                    "1 % and the fluid stays nearly incompressible. With a slower sound speed it "
                    "compresses visibly.",
             .fix = "Raise K0 to at least rho0 * (10 * vmax)^2 / gamma.",
             .before = R"deck($ part 1: *MAT_NULL, RO = 1.0e-9 (t/mm^3); 10 m/s = 1.0e4 mm/s
*EOS_MURNAGHAN
$#   eosid     gamma        k0        v0
         1       7.0       0.3       1.0
*INITIAL_VELOCITY_NODE
$#     nid        vx        vy        vz       vxr       vyr       vzr
       101  -10000.0       0.0       0.0       0.0       0.0       0.0
)deck",
             .after = R"deck($ part 1: *MAT_NULL, RO = 1.0e-9 (t/mm^3); 10 m/s = 1.0e4 mm/s
*EOS_MURNAGHAN
$#   eosid     gamma        k0        v0
         1       7.0       2.0       1.0
*INITIAL_VELOCITY_NODE
$#     nid        vx        vy        vz       vxr       vyr       vzr
       101  -10000.0       0.0       0.0       0.0       0.0       0.0
)deck"}},

    // SPH118 few-neighbours
    {.code = "SPH118",
     .name = "few-neighbours",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "preview",
     .summary = "estimated neighbours per particle below 20 in 3D or 8 in 2D",
     .doc = {.what = "Reports parts whose estimated neighbour count per particle, from the "
                     "spacing and the initial smoothing length, is below 20 in 3D or 8 in 2D.",
             .why = "An SPH value is a weighted sum over the particles inside the kernel support "
                    "(twice the smoothing length); with too few of them interpolation and "
                    "gradients are poor (*SECTION_SPH, CSLH and SPHINI). A cubic fill at the "
                    "default CSLH 1.2 gives about 56 neighbours in 3D and 20 in 2D.",
             .fix = "Raise CSLH within 1.05-1.3, or make SPHINI about 1.2 times the particle "
                    "spacing.",
             .before = R"deck($ particles on a 2 mm cubic grid
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1                 0.2       2.0       1.5     1e+20       0.0         0
)deck",
             .after = R"deck($ particles on a 2 mm cubic grid
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start   sphkern
         1                 0.2       2.0       2.4     1e+20       0.0         0
)deck"}},
};

}  // namespace

std::span<const RuleInfo> sph_rule_rows() { return kSphRules; }

}  // namespace sphdeck::lint::detail
