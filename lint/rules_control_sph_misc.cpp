// SPH050, SPH060, SPH091-SPH094: viscosity coefficients, inter-part interaction, symmetry-plane
// memory, contact thickness and the sort interval of *CONTROL_SPH; SPH122: symmetry planes without a normal.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <set>

#include "grammar/fields.hpp"
#include "grammar/value.hpp"
#include "lint/rules_control_sph.hpp"
#include "model/id_index.hpp"

namespace sphdeck::lint::control_sph {
namespace {

using diag::Severity;

bool is_one(double v) { return std::abs(v - 1.0) < 1e-12; }

// SPH050: with the Monaghan viscosity the manual recommends Q1 = Q2 = 1.0 (Remark 4). Each SPH
// part takes them from its *HOURGLASS when HGID names one, else from *CONTROL_BULK_VISCOSITY.
void check_viscosity(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const model::Controls& ctl = c.model.controls;
    const auto& iavis = ctl.sph.iavis;
    if (iavis.value != model::ArtificialViscosity::Monaghan || parts.empty()) return;  // no SPH part, no advice
    struct Row {
        const model::FieldRecord *q1 = nullptr, *q2 = nullptr;
    };
    std::map<model::Id, Row> hourglasses;
    for (const model::KeywordRecord& r : c.model.records) {
        if (r.schema->name != "*HOURGLASS") continue;
        for (const auto& row : r.rows) {
            Row h;
            model::Id id;
            for (const model::FieldRecord& f : row) {
                if (f.name == "HGID") id = model::normalise_id(f.text);
                if (f.name == "Q1") h.q1 = &f;
                if (f.name == "Q2") h.q2 = &f;
            }
            if (h.q1 && h.q2) hourglasses.emplace(id, h);
        }
    }
    bool bulk = false;
    std::set<model::Id> used;
    for (const model::Part* p : parts) {
        if (!p->hourglass.value.empty() && hourglasses.count(p->hourglass.value))
            used.insert(p->hourglass.value);
        else
            bulk = true;
    }
    if (bulk && !(is_one(ctl.q1.value) && is_one(ctl.q2.value))) {
        if (ctl.bulk_viscosity_present)
            c.report("SPH050", is_one(ctl.q1.value) ? ctl.q2.span : ctl.q1.span,
                     fmt::format(
                         "IAVIS 0 (Monaghan) with Q1 {} and Q2 {} on *CONTROL_BULK_VISCOSITY; expected 1.0 for both",
                         number(ctl.q1.value), number(ctl.q2.value)))
                .notes.push_back({iavis.span, "IAVIS 0 is set here"});
        else
            c.report("SPH050", iavis.span,
                     fmt::format("IAVIS 0 (Monaghan) with the default Q1 {} and Q2 {} (no *CONTROL_BULK_VISCOSITY); "
                                 "expected 1.0 for both",
                                 number(ctl.q1.value), number(ctl.q2.value)));
    }
    for (const model::Id& id : used) {
        const Row& h = hourglasses.at(id);
        const double q1 = h.q1->valid && h.q1->explicit_value ? h.q1->number : 1.5;
        const double q2 = h.q2->valid && h.q2->explicit_value ? h.q2->number : 0.06;
        if (is_one(q1) && is_one(q2)) continue;
        c.report(
             "SPH050", is_one(q1) ? h.q2->span : h.q1->span,
             fmt::format("IAVIS 0 (Monaghan) with Q1 {} and Q2 {} on *HOURGLASS {} of SPH parts; expected 1.0 for both",
                         number(q1), number(q2), id))
            .notes.push_back({iavis.span, "IAVIS 0 is set here"});
    }
}

// SPH060: CONT 1 switches the particle approximation between parts off; without an interaction
// section or an SPH-to-SPH coupling the parts pass through each other (*CONTROL_SPH, CONT).
void check_cont(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const auto& cont = c.model.controls.sph.cont;
    if (cont.value != 1 || parts.size() < 2) return;
    for (const model::Section& s : c.model.sections)
        if (s.interaction) return;
    for (const grammar::Block& b : c.deck.blocks)
        if (b.keyword.rfind("*DEFINE_SPH_TO_SPH_COUPLING", 0) == 0) return;
    c.report("SPH060", cont.span,
             fmt::format("CONT 1 with {} SPH parts and no *SECTION_SPH_INTERACTION or *DEFINE_SPH_TO_SPH_COUPLING: "
                         "the parts do not interact; expected CONT 0 or a coupling",
                         parts.size()));
}

// SPH091, SPH092: ISYMP, the percentage of particles reserved for symmetry-plane ghosts.
void check_isymp(RuleContext& c) {
    const auto& isymp = c.model.controls.sph.isymp;
    const auto& planes = c.model.symmetry_planes;
    if (isymp.explicit_value && (isymp.value < 1 || isymp.value > 100)) {
        c.report("SPH091", Severity::Error, isymp.span,
                 fmt::format("ISYMP {} is a percentage of the particle count; expected 1 to 100", isymp.value));
        return;
    }
    if (isymp.explicit_value && isymp.value != 100 && planes.empty())
        c.report("SPH091", isymp.span,
                 fmt::format("ISYMP {} reserves ghost memory but there is no *BOUNDARY_SPH_SYMMETRY_PLANE; expected "
                             "blank or 100",
                             isymp.value));
    const std::size_t n = c.model.particles.size();
    if (!planes.empty() && n > 1'000'000 && isymp.value == 100)
        c.report("SPH092", isymp.span,
                 fmt::format("ISYMP 100 reserves ghosts for all {} particles; expected 10 to 20 for a large model", n))
            .notes.push_back({planes.front().span, "symmetry plane defined here"});
}

bool has_token(std::string_view keyword, std::string_view token) {
    for (std::size_t pos = 0; pos <= keyword.size();) {
        std::size_t end = keyword.find('_', pos);
        if (end == std::string_view::npos) end = keyword.size();
        if (keyword.substr(pos, end - pos) == token) return true;
        pos = end + 1;
    }
    return false;
}

// Whether the SURFA (slave) side of a contact, given by SSID and SSTYP on card 1, holds particles.
bool holds_particles(const RuleContext& c, const std::vector<const model::Part*>& parts, long long ssid,
                     long long sstyp) {
    auto sph_part = [&](long long pid) {
        for (const model::Part* p : parts)
            if (p->id == std::to_string(pid)) return true;
        return false;
    };
    auto members = [&](const model::IdSet* set) { return set ? &set->members : nullptr; };
    switch (sstyp) {
        case 2:  // part set
            if (const auto* m = members(c.part_set(std::to_string(ssid))))
                for (long long pid : *m)
                    if (sph_part(pid)) return true;
            return false;
        case 3: return sph_part(ssid);
        case 4:  // node set
            if (const auto* m = members(c.node_set(std::to_string(ssid)))) {
                const model::IdIndex& particles = c.particle_index();
                for (long long node : *m)
                    if (particles.find(node)) return true;
            }
            return false;
        case 5:
        case 6: return true;        // all parts, or all but an exempted set
        default: return ssid == 0;  // segment or shell sets hold no particles; 0 = everything
    }
}

// SPH093: ITHK 1 computes the particles' contact thickness, unless the contact card gives a
// non-zero SST (*CONTROL_SPH, ITHK). Contacts are not in the schema, so the blocks are read raw,
// for the contact types whose cards 1-3 share the standard layout (pydyna's
// contact_automatic_nodes_to_surface.py and friends): card 1 SSID SSTYP in columns 1-10 and
// 21-30, card 3 SST (pydyna SAST) in columns 21-30. _ID/_TITLE add an id card before card 1,
// _MPP one card more, and a second one when it starts with '&'.
void check_ithk(RuleContext& c, const std::vector<const model::Part*>& parts) {
    const auto& ithk = c.model.controls.sph.ithk;
    if (ithk.value != 1) return;
    std::vector<grammar::Field> fields;
    for (const grammar::Block& b : c.deck.blocks) {
        const std::string_view k = b.keyword;
        if (k.rfind("*CONTACT_", 0) != 0 || k.rfind("*CONTACT_2D_", 0) == 0) continue;
        if (k.find("NODES_TO_SURFACE") == k.npos && k.find("SURFACE_TO_SURFACE") == k.npos &&
            k.find("SINGLE_SURFACE") == k.npos && k.find("AUTOMATIC_GENERAL") == k.npos)
            continue;
        grammar::CardLinePtr l = c.deck.begin_lines(b);
        grammar::CardLinePtr end = c.deck.end_lines(b);
        if (has_token(k, "ID") || has_token(k, "TITLE")) ++l;
        if (has_token(k, "MPP") && ++l < end) {
            const std::string_view t = c.deck.text(*l);
            const std::size_t first = t.find_first_not_of(' ');
            if (first != t.npos && t[first] == '&') ++l;
        }
        if (end - l < 3) continue;
        const std::uint32_t w = b.format == grammar::CardFormat::Long ? 20 : 10;
        const grammar::FixedField layout[] = {{0, w}, {w, w}, {2 * w, w}};
        grammar::cut_fields(c.deck.text(*l), *l, layout, 8 * w, fields);
        grammar::IntegerValue ssid = grammar::parse_integer(fields[0].text);
        grammar::IntegerValue sstyp = grammar::parse_integer(fields[2].text);
        if (!holds_particles(c, parts, ssid.status == grammar::NumberStatus::Ok ? ssid.value : 0,
                             sstyp.status == grammar::NumberStatus::Ok ? sstyp.value : 0))
            continue;
        grammar::cut_fields(c.deck.text(l[2]), l[2], layout, 8 * w, fields);
        grammar::RealValue sst = grammar::parse_real(fields[2].text);
        if (sst.status != grammar::NumberStatus::Ok || sst.value == 0.0) continue;
        c.report("SPH093", ithk.span,
                 fmt::format("ITHK 1 is ignored where {} gives SST {}; expected SST 0 or ITHK 0", b.keyword,
                             number(sst.value)))
            .notes.push_back({fields[2].span, "SST given here"});
    }
}

}  // namespace

void check_symmetry_planes(RuleContext& c) {
    for (const model::SymmetryPlane& q : c.model.symmetry_planes) {
        if (q.head != q.tail || !q.span.valid()) continue;
        const std::string_view line = c.deck.sources.line_text(q.span.file, q.span.line);
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) {  // a blank line typed among the planes
            c.report("DK034", q.span,
                     "blank line read as a plane of *BOUNDARY_SPH_SYMMETRY_PLANE: LS-DYNA reads a blank line inside "
                     "a keyword as a card of defaults, here a plane whose normal's tail and head are both at the "
                     "origin (no normal)")
                .fixes.push_back(
                    {"make the blank line a comment ('$')", false, {{{q.span.file, q.span.line, 1, 1}, "$"}}});
            continue;
        }
        c.report("SPH122", q.span,
                 fmt::format("symmetry plane with its normal's tail and head at one point ({}, {}, {}): it defines no "
                             "normal; expected the head a distance along the normal, into the particles",
                             q.tail[0], q.tail[1], q.tail[2]));
    }
}

void check_misc(RuleContext& c, const std::vector<const model::Part*>& parts) {
    check_viscosity(c, parts);
    check_cont(c, parts);
    check_isymp(c);
    check_ithk(c, parts);
    const auto& ncbs = c.model.controls.sph.ncbs;
    if (ncbs.value < 1)  // SPH094: cycles between particle sorts
        c.report("SPH094", ncbs.span,
                 fmt::format("NCBS {} is below 1; expected a positive number of cycles", ncbs.value));
}

}  // namespace sphdeck::lint::control_sph
