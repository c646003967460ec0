// RadiossBuilder: properties, materials, EOS and the SPH cards, with the defaults the starter
// applies (radioss-format.md §5: hm_read_prop34.F, hm_read_sphglo.F, hm_read_spcnd.F, ...).
#include <cctype>
#include <fmt/format.h>
#include <map>
#include <set>

#include "grammar/number_cast.hpp"
#include "grammar/value.hpp"
#include "model/radioss_builder.hpp"

namespace sphdeck::model {

namespace {

template <typename T>
void zero_means(StarterValue<T>& v, T fallback) {
    if (v.value == T{}) v.value = fallback;
}

Setting<double> setting_of(const StarterValue<double>& v) { return {v.value, v.explicit_value, v.span}; }

}  // namespace

int radioss_law(std::string_view name) {
    if (name.rfind("LAW", 0) == 0) {
        // The starter's laws have at most three digits; a longer number names none (and would overflow an int).
        const std::string_view digits = name.substr(3);
        if (digits.empty() || digits.size() > 6) return -1;
        int law = 0;
        for (char c : digits) {
            if (c < '0' || c > '9') return -1;
            law = law * 10 + (c - '0');
        }
        return law;
    }
    static const std::map<std::string_view, int> names = {
        {"VOID", 0},      {"ELAST", 1},      {"PLAS_JOHNS", 2}, {"PLAS_ZERIL", 2}, {"HYDPLA", 3},     {"HYD_JCOOK", 4},
        {"JWL", 5},       {"HYD_VISC", 6},   {"HYDRO", 6},      {"K-EPS", 6},      {"DPRAG1", 10},    {"BOUND", 11},
        {"3D_COMP", 12},  {"RIGID", 13},     {"COMPSO", 14},    {"DPRAG", 21},     {"DAMA", 22},      {"PLAS_DAM", 23},
        {"CONC", 24},     {"COMPSH", 25},    {"PLAS_BRIT", 27}, {"HONEYCOMB", 28}, {"HILL", 32},      {"VISC_FOAM", 33},
        {"BOLTZMAN", 34}, {"FOAM_PLAS", 35}, {"PLAS_TAB", 36},  {"VISC_TAB", 38},  {"KELVINMAX", 40}, {"OGDEN", 42},
        {"COWPER", 44},   {"STEINB", 49},    {"FOAM_TAB", 70}};
    auto it = names.find(name);
    return it == names.end() ? -1 : it->second;
}

void RadiossBuilder::add_particle(const RadiossBlock&, std::uint32_t line, const std::vector<RadiossValue>& v) {
    if (!block_id_ || v.size() < 3 || !v[0].valid) return;
    Particles& p = model_.particles;
    p.node.push_back(grammar::saturating_integer<long long>(v[0].number));
    p.part.push_back(*block_id_);
    p.mass.push_back(v[2].valid ? v[2].number : 0.0);  // resolved in finish: the property mp may apply
    p.volume.push_back(0);
    p.line.push_back(line);
    facts_.cells.type.push_back(
        static_cast<std::uint8_t>(v[1].valid && v[1].number >= 0 && v[1].number < 256 ? v[1].number : 255));
    facts_.cells.mass.push_back(v[2].valid ? v[2].number : 0.0);
    facts_.cells.from_property.push_back(0);
}

void RadiossBuilder::end_sph_property(const RadiossBlock& b) {
    auto id = header_id(b, 0, "a property id");
    if (!id) return;
    RadiossSphProperty p;
    p.id = *id;
    p.keyword = b.block->keyword.substr(0, b.block->keyword.rfind('/'));
    p.title = b.title;
    p.span = b.block->span;
    p.format = b.format;
    p.mp = starter<double>("mp", b);
    if (p.mp.value <= 0) p.mp.value = 1.0;  // warning 138: mp set to 1
    p.qa = starter<double>("qa", b);
    zero_means(p.qa, 2.0);
    p.qb = starter<double>("qb", b);
    zero_means(p.qb, 1.0);
    p.alpha_cs = starter<double>("alpha_cs", b);
    p.skew_id = starter<long long>("skew_ID", b);
    p.h_1d = starter<long long>("h_1D", b);
    p.order = starter<long long>("Order", b);  // blank reads as 0 (CFG DEFAULT ORDER=0)
    p.h = starter<double>("h", b);
    p.xi_stab = starter<double>("Xi_Stab", b);
    p.hmin = starter<double>("hmin", b);
    zero_means(p.hmin, 0.2);
    p.hmax = starter<double>("hmax", b);
    zero_means(p.hmax, 2.0);
    p.hcst = starter<double>("hcst", b);
    zero_means(p.hcst, 1.2);
    p.hmin_hmax_hcst_read = b.format >= 2026;

    Section s;
    s.id = std::to_string(*id);
    s.keyword = p.keyword;
    s.sph = true;
    s.span = b.arg_spans.empty() ? b.block->span : b.arg_spans[0];
    if (p.h.value > 0) s.sphini = setting_of(p.h);  // an explicit smoothing length, as SPHINI
    model_.sections.push_back(std::move(s));
    facts_.sph_properties.push_back(std::move(p));
}

void RadiossBuilder::end_solid_property(const RadiossBlock& b, int type) {
    auto id = header_id(b, 0, "a property id");
    if (!id) return;
    RadiossSolidProperty p;
    p.id = *id;
    p.type = type;
    p.keyword = b.block->keyword.substr(0, b.block->keyword.rfind('/'));
    p.span = b.block->span;
    p.isolid = starter<long long>("Isolid", b);
    p.iframe = starter<long long>("Iframe", b);
    p.ndir = starter<long long>("Ndir", b);
    p.sph_part = starter<long long>("sphpartID", b);
    const std::size_t sol2sph_card = type == 14 ? 3 : 5;
    p.sol2sph_card = cards_.size() > sol2sph_card && !cards_[sol2sph_card].empty();
    facts_.solid_properties.push_back(std::move(p));

    Section s;
    s.id = std::to_string(*id);
    s.keyword = facts_.solid_properties.back().keyword;
    s.span = b.arg_spans[0];
    model_.sections.push_back(std::move(s));
}

// Any other /PROP/<type>/<id>: known by id, so parts that name it resolve.
void RadiossBuilder::end_other_property(const RadiossBlock& b) {
    if (b.args.size() < 2) return;
    auto id = header_id(b, 1, "a property id");
    if (!id) return;
    Section s;
    s.id = std::to_string(*id);
    s.keyword = b.block->keyword.substr(0, b.block->keyword.rfind('/'));
    s.span = b.arg_spans[1];
    model_.sections.push_back(std::move(s));
}

void RadiossBuilder::end_material(const RadiossBlock& b) {
    // /MAT/<law>/<id>; a gas names its kind first: /MAT/GAS/<MASS|MOLE|PREDEF>/<id> (mat_gas.cfg).
    const std::size_t id_arg = b.spec->name == "/MAT/GAS" ? 2 : 1;
    if (b.args.size() < id_arg + 1) {
        report("DK008", diag::Severity::Error,
               id_arg == 2 ? "/MAT/GAS needs a kind and a material id: /MAT/GAS/<MASS|MOLE|PREDEF>/<mat_ID>"
                           : "/MAT needs a law and a material id: /MAT/<law>/<mat_ID>",
               b.block->span);
        return;
    }
    auto id = header_id(b, id_arg, "a material id");
    if (!id) return;
    RadiossMaterial m;
    m.id = *id;
    m.law = radioss_law(b.args[0]);
    m.keyword = "/MAT/" + b.args[0];
    m.span = b.block->span;
    m.law_span = b.arg_spans[0];
    // The hand-written cards' names, then the CFG files' (a law read by its generated cards).
    const std::string_view rho_name = first_named({"RHO_I", "MAT_RHO", "Rho"});
    StarterValue<double> rho = starter<double>(rho_name, b);
    m.density = rho.value;
    m.young = starter<double>(first_named({"E", "MAT_E"}), b).value;
    m.poisson = starter<double>(first_named({"nu", "MAT_NU", "Nu"}), b).value;
    if (const RadiossValue* c1 = value("C1"); c1 && c1->valid) m.bulk = c1->number;  // LAW3, LAW6 before 2018
    Material mat;
    mat.id = std::to_string(*id);
    mat.keyword = m.keyword;
    mat.span = b.arg_spans[id_arg];
    mat.density = setting_of(rho);
    // The starter requires RHO_I > 0 of every law but these (hm_read_mat.F90, message 683 'DENSITY').
    static const std::set<std::string_view> no_density_check = {"VOID",       "LAW0",   "BIMAT",    "LAW20",
                                                                "MULTIMAT",   "LAW51",  "SPR_GENE", "LAW108",
                                                                "MULTIFLUID", "LAW151", "GAS"};
    mat.has_density = value(rho_name) != nullptr && !no_density_check.count(b.args[0]);
    model_.materials.push_back(std::move(mat));
    facts_.materials.push_back(std::move(m));
}

void RadiossBuilder::end_eos(const RadiossBlock& b) {
    auto id = header_id(b, 0, "a material id");
    if (!id) return;
    RadiossEos e;
    e.material = *id;
    e.keyword = "/EOS/POLYNOMIAL";
    e.span = b.block->span;
    const char* names[] = {"C0", "C1", "C2", "C3", "C4", "C5"};
    for (int k = 0; k < 6; ++k) e.c[k] = starter<double>(names[k], b).value;
    e.e0 = starter<double>("E0", b).value;
    e.psh = starter<double>("Psh", b).value;
    e.rho0 = starter<double>("RHO_0", b).value;
    Eos eos;
    eos.id = std::to_string(*id);
    eos.keyword = e.keyword;
    eos.span = b.arg_spans[0];
    model_.equations_of_state.push_back(std::move(eos));
    facts_.eos.push_back(std::move(e));
}

// §5.4: only the first /SPHGLO counts; Alpha_sort 0 → 0.25; Nneigh at least 120; Lneigh 0 →
// Nneigh; Nneigh at least Lneigh. Without one: Lneigh 120, Nneigh 120 (Invers < 130) or 240.
// /INISPHCEL/FULL cards (hm_read_inistate_d00.F); the starter reads no other kind (CASE DEFAULT).
void RadiossBuilder::add_initial_state(const RadiossBlock& b, std::size_t card, std::uint32_t line,
                                       const std::vector<RadiossValue>& v) {
    if (b.args.empty() || b.args[0] != "FULL") return;
    auto num = [&](std::size_t k) { return k < v.size() && v[k].valid ? v[k].number : 0.0; };
    auto& states = facts_.initial_states;
    if (card == 0) {
        if (v.empty()) return;
        RadiossInitialState s;  // kept when the id is unreadable (reported), so its cards stay with it
        s.cell = grammar::saturating_integer<long long>(num(0));
        s.span = v[0].span;
        s.line = line;
        s.nvar = grammar::saturating_integer<long long>(num(1));
        states.push_back(s);
        return;
    }
    if (states.empty() || states.back().line > line) return;
    RadiossInitialState& s = states.back();
    if (card == 1)
        s.eint = num(0), s.rho = num(1), s.h = num(2);
    else if (card == 2)
        s.sigma = {num(0), num(1), num(2)};
    else if (card == 3)
        s.epsp = num(0);
}

void RadiossBuilder::end_sphglo(const RadiossBlock& b) {
    RadiossSphGlobal& g = facts_.sph_global;
    if (g.present) {
        g.ignored.push_back(b.block->span);
        return;
    }
    g.present = true;
    g.span = b.block->span;
    g.alpha_sort = starter<double>("Alpha_sort", b);
    zero_means(g.alpha_sort, 0.25);
    g.maxsph = starter<long long>("Maxsph", b);
    g.lneigh = starter<long long>("Lneigh", b);
    g.nneigh = starter<long long>("Nneigh", b);
    g.isol2sph = starter<long long>("Isol2sph", b);
    zero_means(g.isol2sph, 1LL);  // hm_read_sphglo.F: ITSOL2SPH 0 → 1
    g.nneigh.value = std::max<long long>(g.nneigh.value, 120);
    if (g.lneigh.value == 0) g.lneigh.value = g.nneigh.value;
    g.nneigh.value = std::max(g.nneigh.value, g.lneigh.value);
}

void RadiossBuilder::end_sphbcs(const RadiossBlock& b) {
    if (b.args.empty()) {
        report("DK008", diag::Severity::Error, "/SPHBCS needs a type and an id: /SPHBCS/SLIDE|TIED/<id>",
               b.block->span);
        return;
    }
    RadiossSymmetry s;
    s.span = b.block->span;
    s.type_text = b.written[0];
    s.type_span = b.arg_spans[0];
    if (b.args.size() >= 2) {
        auto id = header_id(b, 1, "an id");
        if (!id) return;
        s.id = *id;
    }
    // The starter compares the first five letters with SLIDE and the first four with TIED.
    const std::string& t = b.args[0];
    s.kind = t.rfind("SLIDE", 0) == 0  ? SymmetryKind::Slide
             : t.rfind("TIED", 0) == 0 ? SymmetryKind::Tied
                                       : SymmetryKind::Invalid;
    s.dir = text("Dir", b);
    if (!s.dir.explicit_value) s.dir.value = "X";
    const char axis =
        s.dir.value.empty() ? 'X' : static_cast<char>(std::toupper(static_cast<unsigned char>(s.dir.value[0])));
    s.axis = s.dir.value.size() == 1 && axis >= 'X' && axis <= 'Z' ? axis - 'X' : -1;
    s.frame_id = starter<long long>("frame_ID", b);
    s.grnod_id = starter<long long>("grnod_ID", b);
    s.ilev = starter<long long>("Ilev", b);
    facts_.symmetries.push_back(std::move(s));
}

void RadiossBuilder::end_inout(const RadiossBlock& b) {
    auto id = header_id(b, 0, "an id");
    if (!id) return;
    RadiossInout io;
    io.id = *id;
    io.span = b.block->span;
    io.itype = starter<long long>("Itype", b);
    io.part = starter<long long>("part_ID", b);
    io.surface = starter<long long>("surf_ID", b);
    io.dist = starter<double>("Dist", b);
    io.nodes = {starter<long long>("node_ID1", b), starter<long long>("node_ID2", b),
                starter<long long>("node_ID3", b)};
    io.fcut = starter<double>("Fcut", b);
    io.density_function = starter<long long>("fct_IDr", b);
    io.energy_function = starter<long long>("fct_IDE", b);
    io.velocity_function = starter<long long>("fct_IDVn", b);
    io.pressure_function = starter<long long>("fct_IDP", b);
    io.density_scale = starter<double>("Fscaler", b);
    io.energy_scale = starter<double>("FscaleE", b);
    io.pressure_scale = starter<double>("FscaleP", b);
    io.length = starter<double>("Lc", b);
    // hm_read_sphio.F: a scale left 0 with a function given is 1 (in the deck's units).
    if (io.density_function.value != 0) zero_means(io.density_scale, 1.0);
    if (io.energy_function.value != 0) zero_means(io.energy_scale, 1.0);
    if (io.pressure_function.value != 0) zero_means(io.pressure_scale, 1.0);
    static constexpr std::array<std::array<std::string_view, 3>, 3> kPoints{
        {{"XM", "YM", "ZM"}, {"XM1", "YM1", "ZM1"}, {"XM2", "YM2", "ZM2"}}};
    for (std::size_t p = 0; p < 3; ++p)
        for (std::size_t k = 0; k < 3; ++k) {
            io.points[p][k] = starter<double>(kPoints[p][k], b);
            io.by_points = io.by_points || value(kPoints[p][k]) != nullptr;
        }
    facts_.inouts.push_back(std::move(io));
}

void RadiossBuilder::end_reserve(const RadiossBlock& b) {
    auto id = header_id(b, 0, "a part id");
    if (!id) return;
    facts_.reserves.push_back(RadiossReserve{*id, b.block->span, starter<long long>("Np", b)});
}

// Engine /DT cards (§5.7): /DT/SPHCEL/<Keyword3>, /DT/NODA/<Keyword3>[/Iflag], /DT/BRICK/..., /DT.
void RadiossBuilder::end_dt(const RadiossBlock& b) {
    facts_.engine_deck = true;
    RadiossDt d;
    const std::string& k = b.block->keyword;
    d.kind = b.spec->name == "/DT/SPHCEL"  ? DtKind::SphCell
             : b.spec->name == "/DT/NODA"  ? DtKind::Nodal
             : b.spec->name == "/DT/BRICK" ? DtKind::Brick
             : b.args.empty()              ? DtKind::Global
                                           : DtKind::Other;
    d.keyword = k;
    d.span = b.block->span;
    if (!b.args.empty() && d.kind != DtKind::Global && d.kind != DtKind::Other) d.keyword3 = b.args[0];
    if (b.args.size() >= 2) {
        grammar::IntegerValue flag = grammar::parse_integer(b.args[1]);
        if (flag.status == grammar::NumberStatus::Ok) d.iflag = flag.value;
    }
    d.dtsca = starter<double>("DTsca", b);
    d.dtmin = starter<double>("DTmin", b);
    facts_.time_steps.push_back(std::move(d));
}

}  // namespace sphdeck::model
