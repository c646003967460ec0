// The run controls (*CONTROL_SPH, *CONTROL_TERMINATION, *CONTROL_TIMESTEP,
// *CONTROL_BULK_VISCOSITY), symmetry planes and body loads (initial velocities: setup_velocities.cpp).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "refsolver/setup.hpp"

namespace sphdeck::refsolver {

namespace {

void control_note(std::vector<Unsupported>& out, std::string what, grammar::Span span, bool fatal = true,
                  bool blocking = false) {
    Unsupported u{std::move(what), span, fatal};
    u.blocking = blocking;
    out.push_back(std::move(u));
}

bool control_keyword_is(const model::KeywordRecord& r, std::string_view name) {
    return r.schema ? r.schema->name == name : r.keyword == name;
}

const model::KeywordRecord* find_curve(const model::Model& m, long long lcid) {
    for (const model::KeywordRecord& r : m.records)
        if (control_keyword_is(r, "*DEFINE_CURVE") && record_integer(&r, "LCID", -1) == lcid) return &r;
    return nullptr;
}

LoadCurve read_curve(const model::KeywordRecord& r) {
    LoadCurve c;
    const double sfa = record_number(&r, "SFA", 1.0), sfo = record_number(&r, "SFO", 1.0);
    const double offa = record_number(&r, "OFFA", 0.0), offo = record_number(&r, "OFFO", 0.0);
    for (const auto& row : r.rows) {
        const model::FieldRecord *a = nullptr, *o = nullptr;
        for (const model::FieldRecord& f : row) {
            if (f.name == "A1" && f.valid) a = &f;
            if (f.name == "O1" && f.valid) o = &f;
        }
        if (!a || !o) continue;
        c.t.push_back((sfa != 0 ? sfa : 1.0) * a->number + offa);
        c.f.push_back((sfo != 0 ? sfo : 1.0) * o->number + offo);
    }
    return c;
}

void setup_loads(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out) {
    for (const model::KeywordRecord& r : m.records) {
        int axis = -1;
        if (control_keyword_is(r, "*LOAD_BODY_X"))
            axis = 0;
        else if (control_keyword_is(r, "*LOAD_BODY_Y"))
            axis = 1;
        else if (control_keyword_is(r, "*LOAD_BODY_Z"))
            axis = 2;
        if (axis < 0) continue;
        if (record_number(&r, "CID") != 0)
            control_note(out,
                         fmt::format("{} CID {}: local coordinate systems are not supported", r.keyword,
                                     record_number(&r, "CID")),
                         record_field(&r, "CID")->span);
        if (record_number(&r, "LCIDDR") != 0)
            control_note(out,
                         fmt::format("{} LCIDDR {}: there is no dynamic relaxation phase; the curve is not used",
                                     r.keyword, record_number(&r, "LCIDDR")),
                         record_field(&r, "LCIDDR")->span, false);
        const long long lcid = record_integer(&r, "LCID");
        const model::KeywordRecord* curve = find_curve(m, lcid);
        if (!curve) {
            const model::FieldRecord* f = record_field(&r, "LCID");
            control_note(out, fmt::format("{}: load curve {} is not defined (*DEFINE_CURVE)", r.keyword, lcid),
                         f ? f->span : r.span, true, true);
            continue;
        }
        BodyLoad load{axis, record_number(&r, "SF", 1.0), read_curve(*curve)};
        if (load.curve.t.empty())
            control_note(out, fmt::format("*DEFINE_CURVE {} has no points", lcid), curve->span, true, true);
        if (record_number(curve, "DATTYP") != 0)
            control_note(out,
                         fmt::format("*DEFINE_CURVE {} DATTYP {} is not supported: points are read as time, value",
                                     lcid, record_number(curve, "DATTYP")),
                         record_field(curve, "DATTYP")->span);
        in.loads.push_back(std::move(load));
    }
}

void setup_planes(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out) {
    for (const model::SymmetryPlane& q : m.symmetry_planes) {
        std::array<double, 3> n{q.head[0] - q.tail[0], q.head[1] - q.tail[1], q.head[2] - q.tail[2]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(length > 0)) {
            control_note(out, "*BOUNDARY_SPH_SYMMETRY_PLANE with tail = head: no normal", q.span, true, true);
            continue;
        }
        for (double& v : n) v /= length;
        if (in.dimension == 2 && std::abs(n[2]) > 1e-12) {
            control_note(
                out,
                fmt::format("*BOUNDARY_SPH_SYMMETRY_PLANE normal ({:.3g}, {:.3g}, {:.3g}) leaves the x-y plane "
                            "of a 2D model",
                            n[0], n[1], n[2]),
                q.span, true, true);
            continue;
        }
        in.planes.push_back({n, n[0] * q.tail[0] + n[1] * q.tail[1] + n[2] * q.tail[2]});
    }
    if (in.planes.size() > 8)
        control_note(out,
                     fmt::format("{} symmetry planes: the solver mirrors across the first 8 only", in.planes.size()),
                     m.symmetry_planes[8].span);
}

}  // namespace

void setup_controls(const model::Model& m, const RunOptions& options, SolverInput& in, std::vector<Unsupported>& out) {
    const model::Controls& c = m.controls;
    const model::ControlSph& sph = c.sph;
    in.renormalise = sph.form.value == model::Form::Renormalized;
    in.h_rule = sph.deriv.value == 1 ? SmoothingLengthRule::CubeRootDivergence : SmoothingLengthRule::Divergence;
    in.q1 = c.q1.value, in.q2 = c.q2.value;
    in.tssfac = c.tssfac.value > 0 ? c.tssfac.value : 0.9;
    in.end_time = options.end_time.value_or(c.endtim.value);
    in.ncbs = std::max<long long>(1, sph.ncbs.value);
    in.sph_start = sph.start.value;
    in.sph_death = sph.dt.value > 0 ? sph.dt.value : 1e20;
    in.maxv = sph.maxv.value;
    for (const model::KeywordRecord& r : m.records)
        if (control_keyword_is(r, "*CONTROL_TERMINATION")) in.end_cycle = record_integer(&r, "ENDCYC");
    if (!(in.end_time > 0))
        control_note(out,
                     fmt::format("end time {} is not positive: give *CONTROL_TERMINATION ENDTIM or --end-time",
                                 in.end_time),
                     c.endtim.span, true, true);
    if (sph.boxid.value != 0) {
        const model::Box* box = m.box(std::to_string(sph.boxid.value));
        if (box)
            in.box = box->bounds;
        else
            control_note(out, fmt::format("*CONTROL_SPH BOXID {} is not defined (*DEFINE_BOX)", sph.boxid.value),
                         sph.boxid.span, true, true);
    }
    setup_planes(m, in, out);
    setup_loads(m, in, out);
}

}  // namespace sphdeck::refsolver
