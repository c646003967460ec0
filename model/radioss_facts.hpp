// What a Radioss deck says beyond the format-neutral model (design.md: format-only facts stay
// beside the shared types). Held as Model::radioss, set only for Radioss decks. Every value is
// the one the OpenRadioss starter (or engine) uses, defaults applied (radioss-format.md §5), with
// what the deck wrote and where, so rules can tell "0 written" from "left blank".
//
// What the shared Model gets from a Radioss deck (model/radioss_decoder.hpp):
// - nodes from /NODE; particles from /SPHCEL (particle id = node id, part from the header, mass
//   as the starter takes it: the cell's MASS for Type 1 or Type 0 with MASS > 0, the property mp
//   otherwise; Type 2 cells carry a volume with Particles::volume = 1);
// - parts (/PART: section = prop_ID, material = mat_ID, eos = mat_ID when an /EOS names it);
// - sections, one per /PROP (sph = true for /PROP/SPH, TYPE34; sphini = the property h when > 0);
// - materials (/MAT: density); equations_of_state (/EOS/POLYNOMIAL, id = its mat_ID);
// - symmetry_planes, one per /SPHBCS whose frame and direction are known (tail = frame origin,
//   head = origin + unit normal, pointing to the side the particles must lie on);
// - node_sets from /GRNOD/NODE and /GRNOD/PART;
// - controls.tssfac = the SPH time-step scale of the engine deck (/DT/NODA, else /DT/SPHCEL,
//   else 0.9); controls.sph.present stays false and controls.sph.memory is 0 (MEMORY has no
//   Radioss counterpart: neighbour arrays are sized by the starter), idim is 3D.
#pragma once

#include <array>
#include <map>
#include <set>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "text/source_map.hpp"

namespace sphdeck::model {

// A field as the starter uses it: `value` after its defaults (a 0 qa becomes 2.0), `written` as
// in the deck (0 when blank), whether it was written, and where (the header when it was not).
template <typename T>
struct StarterValue {
    T value{};
    T written{};
    bool explicit_value = false;
    grammar::Span span;
};

// /PROP/SPH (/PROP/TYPE34), radioss-format.md §5.1.
struct RadiossSphProperty {
    long long id = 0;
    std::string keyword;  // "/PROP/SPH" or "/PROP/TYPE34" as written (upper case)
    std::string title;
    grammar::Span span;  // the header
    int format = 0;      // the card format read (2026, 2019, 130, 51 or 44)
    StarterValue<double> mp, qa, qb, alpha_cs, h, xi_stab, hmin, hmax, hcst;
    StarterValue<long long> skew_id, h_1d, order;
    bool hmin_hmax_hcst_read = false;  // false when the format has no such fields (before 2026)
};

// /PROP/TYPE14 (SOLID) and /PROP/TYPE6 (SOL_ORTH) with their SOL2SPH fields (§5.8).
struct RadiossSolidProperty {
    long long id = 0;
    int type = 14;  // 14 or 6
    std::string keyword;
    grammar::Span span;
    StarterValue<long long> isolid, iframe;           // value: 0 resolved through /DEF_SOLID (else 1)
    StarterValue<long long> ndir, sph_part;           // SOL2SPH: particles per direction, the SPH part
    bool sol2sph_card = false;                        // the Ndir card is present
    bool sol2sph() const { return ndir.value != 0; }  // the starter's pre-read switches SOL2SPH on
};

// /SPHCEL cells, parallel to Model::particles (same index).
struct RadiossCells {
    std::vector<std::uint8_t> type;           // Type as written: 0, 1, 2 (other values kept)
    std::vector<double> mass;                 // MASS as written (mass for Type 1, volume for Type 2)
    std::vector<std::uint8_t> from_property;  // 1: the particle takes mp from its property
};

enum class SymmetryKind : std::uint8_t { Slide, Tied, Invalid };

// /SPHBCS/<type>/<id> (§5.3).
struct RadiossSymmetry {
    long long id = 0;
    grammar::Span span;  // the header
    SymmetryKind kind = SymmetryKind::Invalid;
    std::string type_text;          // the word after /SPHBCS/ as written
    grammar::Span type_span;        // its columns on the header line
    int axis = -1;                  // 0, 1, 2 for X, Y, Z; -1 when Dir is not one of them
    StarterValue<std::string> dir;  // value "X" when blank (CFG default)
    StarterValue<long long> frame_id, grnod_id, ilev;
    std::optional<std::size_t> plane;  // index into Model::symmetry_planes when the plane is known
};

// /SPHGLO (§5.4): the first one of the deck; later ones are ignored by the starter.
struct RadiossSphGlobal {
    bool present = false;
    grammar::Span span;
    StarterValue<double> alpha_sort;                    // 0 → 0.25
    StarterValue<long long> maxsph, lneigh, nneigh;     // lneigh, nneigh: the starter's values
    StarterValue<long long> isol2sph{1, 0, false, {}};  // 1 without a /SPHGLO or when 0 (hm_read_sphglo.F)
    std::vector<grammar::Span> ignored;                 // headers of the later /SPHGLO blocks
};

// /SKEW and /FRAME (ids; fixed ones with their axes, moving ones with their nodes).
struct RadiossFrame {
    long long id = 0;
    bool skew = false;    // /SKEW (else /FRAME)
    bool moving = false;  // anything but /FIX: not a fixed system
    std::string keyword;
    grammar::Span span;
    bool geometry = false;  // origin and axes known (fixed, or moving with located nodes)
    std::array<double, 3> origin{};
    std::array<std::array<double, 3>, 3> axes{};  // unit X', Y', Z'
    std::array<long long, 3> nodes{};             // moving: node_ID1-3
    int dir = 0;                                  // moving: the axis along N1N2 (Dir X 0, Y 1, Z 2)
};

// A /GRNOD of any kind; members are in Model::node_sets when `resolved`.
struct RadiossNodeGroup {
    long long id = 0;
    std::string keyword;
    grammar::Span span;
    bool resolved = false;
};

// /MAT/<law>/<id>: the law and what the sound speed needs.
struct RadiossMaterial {
    long long id = 0;
    int law = -1;         // -1 when the name is not known
    std::string keyword;  // "/MAT/LAW6", "/MAT/HYD_VISC"...
    grammar::Span span;
    grammar::Span law_span;         // the law segment of the header
    double density = 0;             // RHO_I
    double young = 0, poisson = 0;  // elastic laws (card 2), 0 when not read
    double bulk = 0;                // C1 of a law's own polynomial (LAW3/4/6 long forms), 0 when absent
};

// /EOS/POLYNOMIAL/mat_ID.
struct RadiossEos {
    long long material = 0;
    std::string keyword;
    grammar::Span span;
    std::array<double, 6> c{};  // C0-C5
    double e0 = 0, psh = 0, rho0 = 0;
};

// Solid elements by kind; nodes flattened, `nodes_per_element` per element.
struct RadiossSolids {
    int nodes_per_element = 8;
    std::vector<long long> id, part, nodes;
    std::vector<std::uint32_t> line;  // index into RawDeck::lines (the element's first line)
    std::size_t size() const { return id.size(); }
};

// /SPH/INOUT (§5.6) and /SPH/RESERVE (§5.5).
struct RadiossInout {
    long long id = 0;
    grammar::Span span;
    StarterValue<long long> itype, part, surface;
    StarterValue<double> dist;                     // Dist: particle control distance from the surface
    std::array<StarterValue<long long>, 3> nodes;  // node_ID1-3 (format 140 on): the frontier by nodes
    StarterValue<double> fcut;                     // Fcut (format 140 on): Butterworth corner frequency
    // The cards of its Itype (hm_read_sphio.F): functions of time and their scales (a scale 0
    // with a function is 1), the frontier's characteristic length (Itype 3), and from format 140
    // the three points M, M1, M2 of a frontier given by coordinates.
    StarterValue<long long> density_function, energy_function, velocity_function, pressure_function;
    StarterValue<double> density_scale, energy_scale, pressure_scale, length;
    std::array<std::array<StarterValue<double>, 3>, 3> points;
    bool by_points = false;  // the M cards were read
};
// A surface a /SURF/<kind>/.../id block defines: every kind names its id in the header.
struct RadiossSurface {
    long long id = 0;
    grammar::Span span;  // the header
};
struct RadiossReserve {
    long long part = 0;
    grammar::Span span;
    StarterValue<long long> count;
};

// /INISPHCEL/FULL (hm_read_inistate_d00.F): the initial state of one particle, named by its
// /SPHCEL node id; the starter skips ids it does not find (warning 3045).
struct RadiossInitialState {
    long long cell = 0;      // sphcel_ID
    grammar::Span span;      // its cell
    std::uint32_t line = 0;  // index into RawDeck::lines
    long long nvar = 0;      // nvarsph: auxiliary values that follow
    double eint = 0, rho = 0, h = 0, epsp = 0;
    std::array<double, 3> sigma{};  // Sigma1-3 (the starter sets the shear stresses to 0)
};

enum class DtKind : std::uint8_t { SphCell, Nodal, Brick, Global, Other };

// An engine /DT card (§5.7), from the engine deck <run>_0001.rad.
struct RadiossDt {
    DtKind kind = DtKind::Other;
    std::string keyword;   // "/DT/SPHCEL/STOP"
    std::string keyword3;  // "STOP", "DEL", "CST", ... ("" for /DT)
    long long iflag = 0;   // /DT/NODA/CST/1, /DT/BRICK/DEL/1
    grammar::Span span;
    StarterValue<double> dtsca, dtmin;  // dtsca.value: 0 → the global /DT factor (0.9 in 3D)
    bool in_starter = false;            // written in the starter deck, where the starter ignores it
};

// An id a generated card's cell names (FieldSpec::link), for the REF rules.
struct RadiossIdUse {
    char kind = 0;  // FieldSpec::link
    long long id = 0;
    grammar::Span span;
    std::string field, keyword;  // "grnd_ID1", "/RWALL/PLANE"
};

struct RadiossFacts {
    // Declared here and defaulted in model/radioss_facts.cpp: the special members of this large aggregate are compiled
    // once, not in every room that copies, moves or drops one (issue 42).
    RadiossFacts();
    RadiossFacts(const RadiossFacts&);
    RadiossFacts(RadiossFacts&&) noexcept;
    RadiossFacts& operator=(const RadiossFacts&);
    RadiossFacts& operator=(RadiossFacts&&) noexcept;
    ~RadiossFacts();

    int version = 2026;  // Invers of /BEGIN (the latest when absent)
    bool begin_present = false;
    grammar::Span version_span;
    std::string run_name;
    std::array<std::string, 3> input_units{"kg", "m", "s"}, work_units{"kg", "m", "s"};
    long long analysis = 0;  // /ANALY N2D3D: 0 3D, 1 axisymmetric, 2 plane strain
    grammar::Span analysis_span;
    long long def_isolid = 0, def_iframe = 0;  // /DEF_SOLID (0 when absent)

    std::vector<RadiossSphProperty> sph_properties;
    std::vector<RadiossSolidProperty> solid_properties;
    RadiossCells cells;
    std::vector<RadiossSymmetry> symmetries;
    RadiossSphGlobal sph_global;
    std::vector<RadiossFrame> frames;
    std::vector<RadiossNodeGroup> node_groups;
    std::vector<RadiossMaterial> materials;
    std::vector<RadiossEos> eos;
    RadiossSolids bricks{8, {}, {}, {}, {}}, tetra4{4, {}, {}, {}, {}}, tetra10{10, {}, {}, {}, {}},
        penta6{6, {}, {}, {}, {}};
    std::vector<RadiossInout> inouts;
    std::vector<RadiossSurface> surfaces;
    bool surfaces_known = true;  // false: a /SURF header without a readable id (ids unchecked)
    std::vector<RadiossReserve> reserves;
    std::vector<RadiossInitialState> initial_states;
    std::vector<RadiossDt> time_steps;
    bool engine_deck = false;  // an engine deck was read
    // Ids named by generated cards, and the ids the headers of the starter deck define per kind
    // (the integer segments after the name: /FUNCT/12, /GRNOD/NODE/5); a //SUBMODEL offsets ids,
    // so then none is judged.
    std::vector<RadiossIdUse> id_uses;
    std::map<char, std::set<long long>> header_ids;
    bool submodels = false;

    const RadiossSphProperty* sph_property(long long id) const;
    const RadiossSolidProperty* solid_property(long long id) const;
    const RadiossMaterial* material(long long id) const;
    const RadiossEos* eos_of(long long material) const;
    const RadiossFrame* frame(long long id, bool skew_allowed = false) const;
    const RadiossDt* time_step(DtKind kind) const;  // the last card of that kind
    bool has_surface(long long id) const;
};

}  // namespace sphdeck::model
