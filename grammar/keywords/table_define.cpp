// *DEFINE_* keywords of SPH decks (lsdyna-sph-cards.md §9-§11) and *DEFINE_CURVE.
#include "grammar/keywords/tables.hpp"

namespace sphdeck::keywords::tables {

namespace {

std::vector<FieldSpec> box_fields() {
    return {
        {.name = "XMN", .column = 11, .width = 10, .type = F, .default_value = 0.0, .doc = "minimum x"},
        {.name = "XMX", .column = 21, .width = 10, .type = F, .default_value = 0.0, .doc = "maximum x"},
        {.name = "YMN", .column = 31, .width = 10, .type = F, .default_value = 0.0, .doc = "minimum y"},
        {.name = "YMX", .column = 41, .width = 10, .type = F, .default_value = 0.0, .doc = "maximum y"},
        {.name = "ZMN", .column = 51, .width = 10, .type = F, .default_value = 0.0, .doc = "minimum z"},
        {.name = "ZMX", .column = 61, .width = 10, .type = F, .default_value = 0.0, .doc = "maximum z"},
    };
}

// pydyna gives BOXID a default of 0 on *DEFINE_BOX, none on *DEFINE_BOX_SPH; a box is only
// useful when something can reference it, so we require it on both.
FieldSpec box_id() { return {.name = "BOXID", .column = 1, .width = 10, .type = I, .required = true, .doc = "box id"}; }

// `_LOCAL` (pydyna define_box_local.py, define_box_sph_local.py): the box is given in a local
// system defined by two more cards after the base cards.
OptionSpec define_local_option() {
    return {
        .suffix = "LOCAL",
        .cards_after =
            {
                {
                    .name = "Local axes",
                    .fields =
                        {
                            {.name = "XX",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "x of a point on the local x-axis"},
                            {.name = "YX",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "y of a point on the local x-axis"},
                            {.name = "ZX",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "z of a point on the local x-axis"},
                            {.name = "XV",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "x of the local x-y vector"},
                            {.name = "YV",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "y of the local x-y vector"},
                            {.name = "ZV",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "z of the local x-y vector"},
                        },
                },
                {
                    .name = "Local origin",
                    .fields =
                        {
                            {.name = "CX",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "x of the local origin"},
                            {.name = "CY",
                             .column = 11,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "y of the local origin"},
                            {.name = "CZ",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "z of the local origin"},
                        },
                },
            },
        .doc = "box given in a local coordinate system (two more cards)",
    };
}

KeywordSchema define_box() {
    std::vector<FieldSpec> fields{box_id()};
    for (FieldSpec& f : box_fields()) fields.push_back(std::move(f));
    return {
        .name = "*DEFINE_BOX",
        .cards = {{.name = "Card 1", .fields = std::move(fields)}},
        .doc = "axis-aligned box (e.g. BOXID of *CONTROL_SPH)",
        .options = {title_option(), define_local_option()},
    };
}

KeywordSchema define_box_sph() {
    std::vector<FieldSpec> fields{box_id()};
    for (FieldSpec& f : box_fields()) fields.push_back(std::move(f));
    fields.push_back({.name = "VID",
                      .column = 71,
                      .width = 10,
                      .type = I,
                      .default_value = 0,
                      .doc = "*DEFINE_VECTOR of the box motion"});
    return {
        .name = "*DEFINE_BOX_SPH",
        .cards =
            {
                {.name = "Card 1", .fields = std::move(fields)},
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "LCID",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "load curve of the box motion"},
                            {.name = "VD",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "velocity"}, {1, "displacement"}, {2, "follow reference node NID"}},
                             .doc = "meaning of LCID"},
                            {.name = "NID",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "reference node (VD = 2)"},
                            {.name = "IREACT",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("particles leaving the box stay deactivated",
                                               "particles entering the box are reactivated"),
                             .doc = "reactivation of particles"},
                            {.name = "IBUFF",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("no buffer zone", "particles on the box edge are frozen neighbours"),
                             .doc = "buffer zone at the box edge"},
                            {.name = "ISHOW",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = off_on("no dummy part", "dummy part shows the box"),
                             .doc = "visualise the box"},
                            {.name = "PID",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "part id of the ISHOW dummy part; 0 = automatic"},
                        },
                },
            },
        .doc = "moving SPH activation box",
        .options = {title_option(), define_local_option()},
    };
}

KeywordSchema sph_to_sph_coupling() {
    return {
        .name = "*DEFINE_SPH_TO_SPH_COUPLING",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            // Older pydyna names: SSID, MSID, SSTYP, MSTYP, IBOX1, IBOX2.
                            {.name = "SIDA",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .doc = "first (slave-side) part or part set",
                             .aliases = {"SSID"}},
                            {.name = "SIDB",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .doc = "second part or part set",
                             .aliases = {"MSID"}},
                            {.name = "SATYP",
                             .column = 21,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "part set"}, {1, "part"}},
                             .doc = "type of SIDA",
                             .aliases = {"SSTYP"}},
                            {.name = "SBTYP",
                             .column = 31,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "part set"}, {1, "part"}},
                             .doc = "type of SIDB",
                             .aliases = {"MSTYP"}},
                            {.name = "IBOXA",
                             .column = 41,
                             .width = 10,
                             .type = I,
                             .doc = "box limiting side A",
                             .aliases = {"IBOX1"}},
                            {.name = "IBOXB",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .doc = "box limiting side B",
                             .aliases = {"IBOX2"}},
                            {.name = "PFACT",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "penalty scale factor"},
                            {.name = "SRAD",
                             .column = 71,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .doc = "interaction-radius factor"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "DFACT",
                             .column = 1,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "contact damping factor"},
                            {.name = "ISOFT",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices = {{0, "penalty"}, {1, "soft constraint"}},
                             .doc = "contact formulation"},
                        },
                    // All defaults; older decks stop after card 1.
                    .repeat = CardRepeat::Optional,
                },
            },
        .doc = "penalty coupling between SPH parts (alternative to CONT = 1 of *CONTROL_SPH)",
        // pydyna's _ID class has no id card, which is suspicious (lsdyna-sph-cards.md §10, §24):
        // we expect the usual id card; UNVERIFIED.
        .options = {title_option(), id_option("DID", "coupling definition id")},
    };
}

KeywordSchema adaptive_solid_to_sph() {
    return {
        .name = "*DEFINE_ADAPTIVE_SOLID_TO_SPH",
        .cards = {{
            .name = "Card 1",
            .fields =
                {
                    {.name = "IPID",
                     .column = 1,
                     .width = 10,
                     .type = I,
                     .required = true,
                     .doc = "solid part (ITYPE = 0) or part set"},
                    {.name = "ITYPE",
                     .column = 11,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .doc = "0 = IPID is a part; non-zero = a part set"},
                    {.name = "NQ",
                     .column = 21,
                     .width = 10,
                     .type = I,
                     .default_value = 1,
                     .choices = {{1, "one particle per solid"}, {2, "8 per hexahedron"}, {3, "27 per hexahedron"}},
                     .doc = "particles per solid element"},
                    {.name = "IPSPH", .column = 31, .width = 10, .type = I, .doc = "part id of the new particles"},
                    {.name = "ISSPH", .column = 41, .width = 10, .type = I, .doc = "section id of the new particles"},
                    {.name = "ICPL",
                     .column = 51,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .choices = {{0, "debris only"}, {1, "coupled to the solid"}, {3, "thermal coupling only"}},
                     .doc = "coupling of particles and solid"},
                    {.name = "IOPT",
                     .column = 61,
                     .width = 10,
                     .type = I,
                     .default_value = 0,
                     .choices = {{0, "particles from the start"},
                                 {1, "particles when the solid fails"},
                                 {2, "(accepted by pydyna)"}},
                     .doc = "when particles are generated"},
                    {.name = "CPCD", .column = 71, .width = 10, .type = F, .doc = "(not described in the sources)"},
                },
        }},
        .doc = "converts failing solid elements into SPH particles",
        // pydyna puts the DID + HEADING card in both the plain and the _ID class; in the manual an
        // id card normally belongs to _ID only. We follow the manual pattern (UNVERIFIED, §11, §24).
        // _TITLE: pydyna lists it (define_adaptive_solid_to_sph.py, an A80 line first) as for the other
        // *DEFINE_ keywords; without it here _TITLE fell back to pydyna's layout, whose DID card took the
        // data line, and the keyword was not read (its ISSPH section was then unused: REF007).
        .options = {title_option(), id_option("DID", "definition id")},
    };
}

KeywordSchema sph_mesh_box() {
    // Layout from pydyna (define_sph_mesh_box.py) and its field texts; read into the model so that
    // `sphdeck smooth` can preview the particles the box generates (preproc/sph_mesh_box.hpp).
    // No manual default is known: only IPID is required; blanks read as 0 and generate nothing.
    return {
        .name = "*DEFINE_SPH_MESH_BOX",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "XMIN", .column = 1, .width = 10, .type = F, .doc = "minimum x-coordinate"},
                            {.name = "YMIN", .column = 11, .width = 10, .type = F, .doc = "minimum y-coordinate"},
                            {.name = "ZMIN", .column = 21, .width = 10, .type = F, .doc = "minimum z-coordinate"},
                            {.name = "XLEN", .column = 31, .width = 10, .type = F, .doc = "box length in x"},
                            {.name = "YLEN", .column = 41, .width = 10, .type = F, .doc = "box length in y"},
                            {.name = "ZLEN", .column = 51, .width = 10, .type = F, .doc = "box length in z"},
                        },
                },
                {
                    .name = "Card 2",
                    .fields =
                        {
                            {.name = "IPID",
                             .column = 1,
                             .width = 10,
                             .type = I,
                             .required = true,
                             .doc = "part of the generated SPH elements",
                             .refers_to = "PART"},
                            {.name = "NX", .column = 11, .width = 10, .type = I, .doc = "particles along x"},
                            {.name = "NY", .column = 21, .width = 10, .type = I, .doc = "particles along y"},
                            {.name = "NZ", .column = 31, .width = 10, .type = I, .doc = "particles along z"},
                            unused(41),
                            {.name = "IDSEG",
                             .column = 51,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc =
                                 "segment set splitting the box; its sign says which side keeps particles (0: none removed)",
                             .refers_to = "SET_SEGMENT"},
                            {.name = "SFSP",
                             .column = 61,
                             .width = 10,
                             .type = F,
                             .doc = "scale of the smoothing length below which particles near IDSEG are removed"},
                        },
                },
            },
        .doc = "fills a box with NX x NY x NZ SPH particles of part IPID",
        .options = {title_option()},
    };
}

KeywordSchema define_curve() {
    return {
        .name = "*DEFINE_CURVE",
        .cards =
            {
                {
                    .name = "Card 1",
                    .fields =
                        {
                            {.name = "LCID", .column = 1, .width = 10, .type = I, .required = true, .doc = "curve id"},
                            {.name = "SIDR",
                             .column = 11,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .choices =
                                 {{0, "transient analysis only"}, {1, "stress initialisation only"}, {2, "both"}},
                             .doc = "use in dynamic relaxation"},
                            {.name = "SFA",
                             .column = 21,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .zero_is_default = true,  // "EQ.0.0: default set to 1.0" (pydyna docstring)
                             .doc = "abscissa scale factor"},
                            {.name = "SFO",
                             .column = 31,
                             .width = 10,
                             .type = F,
                             .default_value = 1.0,
                             .zero_is_default = true,  // "EQ.0.0: default set to 1.0"
                             .doc = "ordinate scale factor"},
                            {.name = "OFFA",
                             .column = 41,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "abscissa offset"},
                            {.name = "OFFO",
                             .column = 51,
                             .width = 10,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "ordinate offset"},
                            {.name = "DATTYP",
                             .column = 61,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "data type (how offsets apply)"},
                            // pydyna define_curve.py: 0 = use LCINT of *CONTROL_SOLUTION.
                            {.name = "LCINT",
                             .column = 71,
                             .width = 10,
                             .type = I,
                             .default_value = 0,
                             .doc = "discretisation intervals of the curve"},
                        },
                },
                {
                    .name = "Point",
                    .fields =
                        {
                            {.name = "A1",
                             .column = 1,
                             .width = 20,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "abscissa"},
                            {.name = "O1",
                             .column = 21,
                             .width = 20,
                             .type = F,
                             .default_value = 0.0,
                             .doc = "ordinate"},
                        },
                    .repeat = CardRepeat::Repeated,
                    .doc = "one point per line",
                },
            },
        .doc = "load curve: abscissa/ordinate pairs with scale factors and offsets",
        .options = {title_option()},
    };
}

}  // namespace

std::vector<KeywordSchema> define_keywords() {
    std::vector<KeywordSchema> k;
    k.push_back(define_box());
    k.push_back(define_box_sph());
    k.push_back(sph_to_sph_coupling());
    k.push_back(adaptive_solid_to_sph());
    k.push_back(sph_mesh_box());
    k.push_back(define_curve());
    return k;
}

}  // namespace sphdeck::keywords::tables
