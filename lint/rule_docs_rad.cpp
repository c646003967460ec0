// RAD rules: OpenRadioss SPH options (/SPHBCS, SOL2SPH, /PROP/SPH, /SPHCEL, /SPHGLO, /DT).
// One row per rule: code, name, default severity, since-version, source, summary and the
// documentation `sphdeck rule CODE` prints (what / why / fix / before / after).
// The deck snippets are column-exact: keep fields aligned when editing them.
#include "lint/registry.hpp"

namespace sphdeck::lint::detail {
namespace {

constexpr RuleInfo kRadRules[] = {
    // RAD001 missing-starter-header
    {.code = "RAD001",
     .name = "missing-starter-header",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reader",
     .summary = "the first line is not #RADIOSS STARTER",
     .doc = {.what = "Reports a Radioss starter deck (`*_0000.rad`) whose first line is not "
                     "`#RADIOSS STARTER`.",
             .why = "OpenRadioss refuses a starter deck that does not begin with this line "
                    "(OpenRadioss reader, message 100201: mandatory first card missing).",
             .fix = "Make `#RADIOSS STARTER` the very first line; move comments below it.",
             .before = R"deck(# bird strike on a slat, starter deck
/BEGIN
bird_strike
#   Invers
      2024
#         Input_mass        Input_length          Input_time
                  kg                  mm                  ms
#          Work_mass         Work_length           Work_time
                  kg                  mm                  ms
)deck",
             .after = R"deck(#RADIOSS STARTER
# bird strike on a slat, starter deck
/BEGIN
bird_strike
#   Invers
      2024
#         Input_mass        Input_length          Input_time
                  kg                  mm                  ms
#          Work_mass         Work_length           Work_time
                  kg                  mm                  ms
)deck"}},

    // RAD002 sphbcs-type
    {.code = "RAD002",
     .name = "sphbcs-type",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "/SPHBCS type neither SLIDE nor TIED",
     .doc = {.what = "Reports a /SPHBCS header whose type, the word after /SPHBCS/, is neither "
                     "SLIDE nor TIED.",
             .why = "The type selects the kinematic condition: SLIDE fixes the velocity normal to "
                    "the plane, TIED all of it; the starter rejects anything else as an undefined "
                    "keyword (Radioss SPH symmetry conditions, Kinematic Boundary Condition; "
                    "starter error 398).",
             .fix = "Write SLIDE (material slides along the plane) or TIED (it does not).",
             .before = R"deck(/SPHBCS/SLIP/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
)deck"}},

    // RAD003 sphbcs-ilev
    {.code = "RAD003",
     .name = "sphbcs-ilev",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "/SPHBCS Ilev neither 0 nor 1",
     .doc = {.what = "Reports a /SPHBCS formulation level Ilev other than 0 or 1.",
             .why = "Ilev says what happens to particles that cross the symmetry plane: with 0 "
                    "they, and their mirror images, progressively stop counting; with 1 they "
                    "bounce back elastically (Radioss SPH symmetry conditions, Formulation "
                    "Level). Other values are rejected by the starter (error 399).",
             .fix = "Use 0, or 1 together with a kinematic condition on the particles lying on "
                    "the plane (see RAD006).",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   2
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   1
)deck"}},

    // RAD004 sphbcs-frame
    {.code = "RAD004",
     .name = "sphbcs-frame",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "/SPHBCS frame unknown (error) or moving (warning: the kinematic condition needs "
                "a fixed skew)",
     .doc = {.what = "Reports a /SPHBCS frame_ID that names no frame (error) or a moving frame "
                     "(warning). 0 means the global frame.",
             .why = "The symmetry plane passes through the frame's origin with its normal along "
                    "the chosen axis. An unknown frame is rejected by the starter (error 400). A "
                    "kinematic condition from /SPHBCS can be combined with other boundary "
                    "conditions only in a fixed or the global skew system (Radioss SPH symmetry "
                    "conditions, Kinematic Boundary Condition), and the starter does not check "
                    "that the frame is fixed.",
             .fix = "Point frame_ID at a fixed frame (/FRAME/FIX), or use 0 when the plane "
                    "contains the global origin.",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         7        10                   0
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
)deck"}},

    // RAD005 sphbcs-dir
    {.code = "RAD005",
     .name = "sphbcs-dir",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "/SPHBCS Dir is not X, Y or Z",
     .doc = {.what = "Reports a /SPHBCS direction Dir other than X, Y or Z.",
             .why = "Dir names the frame axis normal to the plane. The starter looks only at the "
                    "first letter and accepts any other value without a message, leaving the "
                    "plane's normal undefined (OpenRadioss starter, hm_read_spcnd.F; Radioss "
                    "/SPHBCS).",
             .fix = "Write X, Y or Z.",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         1         0        10                   0
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
)deck"}},

    // RAD006 ilev1-without-kinematic
    {.code = "RAD006",
     .name = "ilev1-without-kinematic",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "Ilev 1 while particles on the plane carry no kinematic condition",
     .doc = {.what = "Reports a /SPHBCS with Ilev 1 whose particles lying on the plane at time "
                     "zero are not all in its node group grnod_ID (or grnod_ID is 0).",
             .why = "With Ilev 1 the documentation strongly recommends a kinematic condition on "
                    "every particle that lies on the plane at time zero, for computing-time "
                    "reasons (Radioss SPH symmetry conditions, Formulation Level).",
             .fix = "Put the particles lying on the plane into a node group and give its id as "
                    "grnod_ID.",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0         0                   1
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   1
/GRNOD/NODE/10
particles on x = 0
#  node_ID   node_ID   node_ID
      1001      1002      1003
)deck"}},

    // RAD007 particle-on-many-planes
    {.code = "RAD007",
     .name = "particle-on-many-planes",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "SPHBCS Part Mass",
     .summary = "a particle on more than two symmetry planes: mass and energy output will be off",
     .doc = {.what = "Reports particles that lie on more than two /SPHBCS planes at time zero, "
                     "typically a particle at the corner of three planes.",
             .why = "A particle lying on symmetry planes at time zero shares its mass and volume "
                    "with its own mirror images; the documentation warns that with more than two "
                    "planes this split can make the part's mass and energy output differ from the "
                    "physical model (Radioss SPH symmetry conditions, Part Mass).",
             .fix = "Offset the particle lattice by half a pitch so that no particle lies on a "
                    "plane, or model the geometry with fewer symmetry planes.",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0         0                   0
/SPHBCS/SLIDE/2
symmetry y = 0
#      Dir  frame_ID  grnod_ID                Ilev
         Y         0         0                   0
/SPHBCS/SLIDE/3
symmetry z = 0
#      Dir  frame_ID  grnod_ID                Ilev
         Z         0         0                   0
/NODE
#  node_ID                   X                   Y                   Z
      1001                 0.0                 0.0                 0.0
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0         0                   0
/SPHBCS/SLIDE/2
symmetry y = 0
#      Dir  frame_ID  grnod_ID                Ilev
         Y         0         0                   0
/SPHBCS/SLIDE/3
symmetry z = 0
#      Dir  frame_ID  grnod_ID                Ilev
         Z         0         0                   0
# lattice offset by half a pitch (2 mm particles)
/NODE
#  node_ID                   X                   Y                   Z
      1001                 1.0                 1.0                 1.0
)deck"}},

    // RAD008 particle-wrong-side
    {.code = "RAD008",
     .name = "particle-wrong-side",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SPHBCS",
     .summary = "a particle starts on the wrong side of a symmetry plane",
     .doc = {.what = "Reports particles that start on the negative side of a /SPHBCS plane, i.e. "
                     "behind it when looking along the frame axis.",
             .why = "The symmetry treatment assumes all real particles lie on one side of the "
                    "plane: only then do the mirrored particles give every particle its missing "
                    "neighbours (Radioss SPH symmetry conditions, Maximum Created Number of Ghost "
                    "Particles). The starter does not check this, and even counts particles "
                    "behind the plane as lying on it when it splits masses.",
             .fix = "Move the particles to the positive side of the plane, or flip the plane with "
                    "another frame.",
             .before = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
/NODE
#  node_ID                   X                   Y                   Z
      1001                -2.0                 0.0                 0.0
)deck",
             .after = R"deck(/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
/NODE
#  node_ID                   X                   Y                   Z
      1001                 2.0                 0.0                 0.0
)deck"}},

    // RAD010 sol2sph-incompatible
    {.code = "RAD010",
     .name = "sol2sph-incompatible",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SOL2SPH Limitations",
     .summary = "SOL2SPH parts together with /SPHBCS or /SPH/INOUT",
     .doc = {.what = "Reports SOL2SPH (a solid property with Ndir > 0) in a deck that also has "
                     "/SPHBCS symmetry conditions or /SPH/INOUT inlets or outlets.",
             .why = "SOL2SPH is not compatible with SPH symmetry conditions nor with inlet and "
                    "outlet options (Radioss Sol2SPH option, Limitations), and the starter does "
                    "not stop such a deck.",
             .fix = "Model the full geometry without /SPHBCS (and without /SPH/INOUT), or do "
                    "without SOL2SPH.",
             .before = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         2         2         0
/SPHBCS/SLIDE/1
symmetry plane x = 0
#      Dir  frame_ID  grnod_ID                Ilev
         X         0        10                   0
)deck",
             .after = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         2         2         0
# full geometry: no /SPHBCS
)deck"}},

    // RAD011 sol2sph-ndir
    {.code = "RAD011",
     .name = "sol2sph-ndir",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "SOL2SPH Ndir outside 1-9",
     .doc = {.what = "Reports a SOL2SPH solid property whose Ndir, the number of particles per "
                     "direction in each solid, is outside 1-9 while an SPH part is given.",
             .why = "Ndir is limited to 9 (Radioss Sol2SPH option); a brick gives Ndir^3 "
                    "particles. The starter does not check the range, and larger or negative "
                    "values read past the end of its particle position tables.",
             .fix = "Use Ndir between 1 and 9; 2 or 3 is usual.",
             .before = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
        12         2         0
)deck",
             .after = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         3         2         0
)deck"}},

    // RAD012 sol2sph-element
    {.code = "RAD012",
     .name = "sol2sph-element",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "SOL2SPH on 10-node tetras or other unsupported elements",
     .doc = {.what = "Reports SOL2SPH on elements it does not support: 10-node tetras, and 6-node "
                     "pentas, for which OpenRadioss has no particle generator.",
             .why = "SOL2SPH turns 8-node bricks (degenerate ones included) and 4-node tetras "
                    "into particles, but not 10-node tetras (Radioss Sol2SPH option).",
             .fix = "Mesh the SOL2SPH part with 8-node bricks or 4-node tetras.",
             .before = R"deck(# part 3 uses the SOL2SPH property
/TETRA10/3
#  tetra_ID
       501
# node_ID1  node_ID2  node_ID3  node_ID4  node_ID5  node_ID6  node_ID7  node_ID8  node_ID9 node_ID10
         1         2         3         4         5         6         7         8         9        10
)deck",
             .after = R"deck(# part 3 uses the SOL2SPH property
/TETRA4/3
# tetra_ID  node_ID1  node_ID2  node_ID3  node_ID4
       501         1         2         3         4
)deck"}},

    // RAD013 sol2sph-isolid-iframe
    {.code = "RAD013",
     .name = "sol2sph-isolid-iframe",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "SOL2SPH with Isolid not 1, 2 or 24, or Iframe not 1 or 2",
     .doc = {.what = "Reports a SOL2SPH solid property whose Isolid is not 1, 2 or 24, or whose "
                     "Iframe is not 1 or 2 (0 is resolved through /DEF_SOLID when present).",
             .why = "SOL2SPH is limited to the solid formulations Isolid 1, 2 and 24 with Iframe "
                    "1 or 2 (Radioss Sol2SPH option).",
             .fix = "Use Isolid 24 (or 1, 2) and Iframe 1 or 2 on the solid property.",
             .before = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        14         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         2         2         0
)deck",
             .after = R"deck(/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         2         2         0
)deck"}},

    // RAD014 sol2sph-material
    {.code = "RAD014",
     .name = "sol2sph-material",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "material law not in {2, 3, 4, 6, 21, 24, 36, 81}, or solid and SPH parts of "
                "different laws",
     .doc = {.what = "Reports a SOL2SPH solid or SPH part whose material law is not 2, 3, 4, 6, "
                     "21, 24, 36 or 81, and a solid part whose SPH part uses a different law.",
             .why = "SOL2SPH supports only these laws, and the solid and its particles must use "
                    "the same type of law; the documentation advises keeping the same parameters "
                    "and changing only the failure values (Radioss Sol2SPH option, Particle "
                    "Material and Property; starter error 1911).",
             .fix = "Give the SPH part a material of the same supported law as the solid, usually "
                    "a copy with its own failure values.",
             .before = R"deck(# material 1 is /MAT/LAW2 (Johnson-Cook), defined elsewhere
/PART/1
bumper solid
#  prop_ID    mat_ID subset_ID
         1         1         0
/PART/2
bumper particles
#  prop_ID    mat_ID subset_ID
         2         2         0
/MAT/LAW1/2
elastic for the particles
#              RHO_I
              7.8E-6
#                  E                  Nu
               210.0                 0.3
)deck",
             .after = R"deck(# material 1 is /MAT/LAW2 (Johnson-Cook), defined elsewhere
/PART/1
bumper solid
#  prop_ID    mat_ID subset_ID
         1         1         0
/PART/2
bumper particles
#  prop_ID    mat_ID subset_ID
         2         1         0
)deck"}},

    // RAD015 sol2sph-pitch
    {.code = "RAD015",
     .name = "sol2sph-pitch",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "SOL2SPH guidelines",
     .summary = "SPH and SOL2SPH parts with different particle pitch",
     .doc = {.what = "Reports a SOL2SPH part whose particle pitch (brick size divided by Ndir) "
                     "differs from the pitch of the genuine SPH parts, or of other SOL2SPH parts.",
             .why = "The guidelines ask for the same pitch in all SPH and SOL2SPH parts, and for "
                    "a cubic net in the SPH parts since SOL2SPH particles form one (Radioss "
                    "Sol2SPH option, Other Modeling Guidelines). Particles of different spacing "
                    "interact through mismatched smoothing lengths.",
             .fix = "Choose Ndir (or the brick size) so that brick size / Ndir equals the pitch "
                    "of the SPH parts.",
             .before = R"deck(# bricks are 6 mm; the SPH part is a 2 mm cubic net
/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         2         2         0
)deck",
             .after = R"deck(# bricks are 6 mm; the SPH part is a 2 mm cubic net
/PROP/TYPE14/1
bumper solid
#   Isolid    Ismstr      Iale     Icpre  Itetra10     Inpts   Itetra4    Iframe                  Dn
        24         0         0         0         0         0         0         2                 0.1
#                 qa                  qb                   h              Lambda                  Mu
                 1.1                0.05                 0.1                 0.0                 0.0
#         deltaT_min            vdef_min            vdef_max             ASP_max             COL_min
                 0.0                 0.0                 0.0                 0.0                 0.0
#     Ndir sphpartID  Icontrol
         3         2         0
)deck"}},

    // RAD016 sol2sph-smoothing
    {.code = "RAD016",
     .name = "sol2sph-smoothing",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "SOL2SPH part smoothing length far from the pitch-based guidance",
     .doc = {.what = "Reports the SPH property of a SOL2SPH part whose smoothing length h is 0 or "
                     "far from about 1.25-1.5 times the particle pitch (brick size / Ndir).",
             .why = "SOL2SPH particles take their mass from the solid, but their smoothing length "
                    "must be given, and the documentation relates it to the brick size and Ndir "
                    "(Radioss Sol2SPH option, Particle Material and Property). With h = 0 and mp "
                    "= 0 the automatic value is derived from a unit mass and is meaningless.",
             .fix = "Set h to about 1.25-1.5 times brick size / Ndir, or use h_1D 3 so that "
                    "OpenRadioss derives h from the particle distance.",
             .before = R"deck(# 6 mm bricks, Ndir 2: pitch 3 mm
/PROP/SPH/2
bumper particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
                 0.0                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 0.0                 0.0
)deck",
             .after = R"deck(# 6 mm bricks, Ndir 2: pitch 3 mm
/PROP/SPH/2
bumper particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
                 0.0                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 4.0                 0.0
)deck"}},

    // RAD020 dt-scale-advice
    {.code = "RAD020",
     .name = "dt-scale-advice",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "SPHBCS Time Step",
     .summary = "/DT/SPHCEL scale factor not 0.3, or /DT/NODA scale factor not 0.67",
     .doc = {.what = "Reports, in the engine deck, a /DT/SPHCEL scale factor other than 0.3 or a "
                     "/DT/NODA scale factor other than 0.67. A /DT/SPHCEL factor of 0 takes the "
                     "global /DT factor (0.9 in 3D).",
             .why = "The documentation recommends 0.3 for the particle time step and 0.67 for the "
                    "nodal time step (Radioss SPH, Time Step).",
             .fix = "Set DTsca to 0.3 on /DT/SPHCEL, or 0.67 on /DT/NODA.",
             .before = R"deck(# engine deck bird_strike_0001.rad
/DT/SPHCEL/STOP
#    DTsca     DTmin
       0.9    1.0E-7
)deck",
             .after = R"deck(# engine deck bird_strike_0001.rad
/DT/SPHCEL/STOP
#    DTsca     DTmin
       0.3    1.0E-7
)deck"}},

    // RAD021 brick-del-step
    {.code = "RAD021",
     .name = "brick-del-step",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "SOL2SPH",
     .summary = "/DT/BRICK/DEL minimum step not 20-30 % below the natural brick step",
     .doc = {.what = "Reports a /DT/BRICK/DEL minimum time step that is not about 20-30 % below "
                     "the natural time step sphdeck estimates for the SOL2SPH bricks.",
             .why = "/DT/BRICK/DEL is the most efficient way to release SOL2SPH particles, and "
                    "the guidelines advise a minimum step around 20-30 % below the natural one "
                    "(Radioss Sol2SPH option, /DT/BRICK/DEL). Too close, and bricks are deleted "
                    "under ordinary loading; far below, they distort badly before release.",
             .fix = "Set DTmin to 0.7-0.8 times the natural brick time step given in the message.",
             .before = R"deck(# engine deck; natural brick step about 1.1E-3 ms
/DT/BRICK/DEL
#    DTsca     DTmin
       0.9    1.0E-5
)deck",
             .after = R"deck(# engine deck; natural brick step about 1.1E-3 ms
/DT/BRICK/DEL
#    DTsca     DTmin
       0.9    8.5E-4
)deck"}},

    // RAD022 alpha-sort-range
    {.code = "RAD022",
     .name = "alpha-sort-range",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "SPHBCS ghosts",
     .summary = "/SPHGLO alpha_sort outside (0, 0.5]",
     .doc = {.what = "Reports a /SPHGLO Alpha_sort that is negative, above 0.5, or written as 0 "
                     "(which silently means 0.25).",
             .why = "Alpha_sort is the safety margin of the neighbour search, and it also decides "
                    "which particles get symmetry ghosts (Radioss SPH symmetry conditions, "
                    "Maximum Created Number of Ghost Particles). The documentation gives 0.25 as "
                    "default and 0.5 as maximum; the starter does not enforce the maximum.",
             .fix = "Use a value in (0, 0.5], usually 0.25.",
             .before = R"deck(/SPHGLO
#         Alpha_sort    Maxsph    Lneigh    Nneigh  Isol2sph
                 0.8         0         0         0         0
)deck",
             .after = R"deck(/SPHGLO
#         Alpha_sort    Maxsph    Lneigh    Nneigh  Isol2sph
                0.25         0         0         0         0
)deck"}},

    // RAD023 prop-sph-mass
    {.code = "RAD023",
     .name = "prop-sph-mass",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reference",
     .summary = "/PROP/SPH mp <= 0 (the starter replaces it by 1)",
     .doc = {.what = "Reports a /PROP/SPH particle mass mp of 0 or less on a property used by "
                     "genuine particles (SOL2SPH particles take their mass from the solid and are "
                     "not reported).",
             .why = "The starter only warns (message 138) and sets mp to 1.0 in model units, "
                    "which is almost never the intended mass: 1 kg per particle in kg-mm-ms "
                    "(Radioss /PROP/SPH; OpenRadioss starter, hm_read_prop34.F). With h = 0 the "
                    "automatic smoothing length is then derived from that mass too.",
             .fix = "Give mp as density times particle volume (water, 2 mm pitch, kg-mm-ms: "
                    "1.0E-6 * 8 = 8.0E-6), or give per-particle masses on /SPHCEL.",
             .before = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
                 0.0                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck",
             .after = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck"}},

    // RAD024 prop-sph-q-zero
    {.code = "RAD024",
     .name = "prop-sph-q-zero",
     .severity = diag::Severity::Info,
     .since = "0.1.0",
     .source = "reference",
     .summary = "/PROP/SPH qa or qb written as 0: silently replaced by 2 and 1",
     .doc = {.what = "Reports a /PROP/SPH viscosity coefficient qa or qb written as 0.",
             .why = "The starter replaces 0 by the defaults, 2.0 for qa and 1.0 for qb, without a "
                    "message, so a zero does not switch the artificial viscosity off (Radioss "
                    "/PROP/SPH). Switching it off takes a tiny value such as 1E-30.",
             .fix = "Write the coefficients you mean: 2.0 and 1.0 (or leave them blank) for the "
                    "defaults, a tiny value to switch a term off.",
             .before = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 0.0                 0.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck",
             .after = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck"}},

    // RAD025 glued-values
    {.code = "RAD025",
     .name = "glued-values",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reference",
     .summary = "two numbers in one fixed field (the starter silently keeps the first)",
     .doc = {.what = "Reports two numbers inside one fixed-width field, typically a line written "
                     "with 10-character columns under a 20-character real field.",
             .why = "The reader keeps the first number of the field and drops the rest without a "
                    "warning, so the second value is lost and every following field is read from "
                    "the wrong columns (OpenRadioss reader, lenient field parsing).",
             .fix = "Realign the line to the card's field widths (here Alpha_sort is 20 "
                    "characters wide).",
             .before = R"deck(/SPHGLO
#         Alpha_sort    Maxsph    Lneigh    Nneigh
       0.1     15000       120       240
)deck",
             .after = R"deck(/SPHGLO
#         Alpha_sort    Maxsph    Lneigh    Nneigh
                 0.1     15000       120       240
)deck"}},

    // RAD026 sphcel-mass
    {.code = "RAD026",
     .name = "sphcel-mass",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reference",
     .summary = "/SPHCEL Type 1 or 2 with mass <= 0",
     .doc = {.what = "Reports a /SPHCEL particle with Type 1 (mass) or 2 (volume) whose MASS is 0 "
                     "or negative.",
             .why = "The starter accepts it, but the particle gets no mass or volume and hence a "
                    "zero smoothing length, and the engine later stops with \"null diameter for "
                    "SPH particle\" (Radioss /SPHCEL; OpenRadioss engine message 174).",
             .fix = "Give the mass (Type 1) or volume (Type 2) as a positive number, or use Type "
                    "0 to take mp from the property.",
             .before = R"deck(/SPHCEL/2
#  node_ID      Type                MASS
      1001         1                 0.0
)deck",
             .after = R"deck(/SPHCEL/2
#  node_ID      Type                MASS
      1001         1              8.0E-6
)deck"}},

    // RAD027 h1d-invalid
    {.code = "RAD027",
     .name = "h1d-invalid",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reference",
     .summary = "/PROP/SPH h_1D outside 0-3 (acts as 0)",
     .doc = {.what = "Reports a /PROP/SPH h_1D other than 0, 1, 2 or 3.",
             .why = "h_1D selects how the smoothing length evolves: 0 with the 3D dilatation, 1 "
                    "the 1D form, 2 constant, 3 bounded between hmin and hmax; any other value "
                    "silently behaves like 0 (Radioss /PROP/SPH; OpenRadioss engine).",
             .fix = "Use one of 0, 1, 2 or 3.",
             .before = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         4
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck",
             .after = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         3
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck"}},

    // RAD028 order-unsupported
    {.code = "RAD028",
     .name = "order-unsupported",
     .severity = diag::Severity::Warning,
     .since = "0.1.0",
     .source = "reference",
     .summary = "/PROP/SPH Order outside -1, 0, 1 (the engine ignores it)",
     .doc = {.what = "Reports a /PROP/SPH kernel correction Order other than -1, 0 or 1. LS-DYNA "
                     "decks converted with SPHKERN 2 produce Order 2.",
             .why = "The engine implements only -1 (no correction), 0 and 1; with any other value "
                    "the particle ends up in no correction list, without a message (Radioss "
                    "/PROP/SPH; OpenRadioss engine, spcompl.F).",
             .fix = "Use -1, 0 or 1.",
             .before = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         2                 2.4                 0.0
)deck",
             .after = R"deck(/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
)deck"}},

    // RAD029 radioss-2d
    {.code = "RAD029",
     .name = "radioss-2d",
     .severity = diag::Severity::Error,
     .since = "0.1.0",
     .source = "reference",
     .summary = "a 2D SPH model: Radioss SPH is 3D only",
     .doc = {.what = "Reports a 2D SPH model meant for OpenRadioss, such as an LS-DYNA deck with "
                     "IDIM 2 or -2 that is to run in OpenRadioss.",
             .why = "Radioss SPH works in 3D only (Altair Radioss, SPH); OpenRadioss has no 2D "
                    "kernel, and its LS-DYNA reader drops *CONTROL_SPH, so IDIM is silently "
                    "ignored and the 2D layer is computed as a thin 3D slab.",
             .fix = "Model the problem in 3D, e.g. several particle layers between two symmetry "
                    "planes for plane strain.",
             .before = R"deck($ LS-DYNA deck to be run with OpenRadioss
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         2       150         1       0.0     1e+15
)deck",
             .after = R"deck($ LS-DYNA deck to be run with OpenRadioss
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0     1e+20         3       150         1       0.0     1e+15
)deck"}},
};

}  // namespace

std::span<const RuleInfo> rad_rule_rows() { return kRadRules; }

}  // namespace sphdeck::lint::detail
