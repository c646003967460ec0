// The particles' initial velocities: *INITIAL_VELOCITY (node set, or all nodes; BOXID, NSIDEX),
// *INITIAL_VELOCITY_GENERATION (part, part set or node set: translation plus rotation about an
// axis) and *INITIAL_VELOCITY_NODE (single nodes).
//
// Linear in the deck: node sets, part sets and particles are indexed once, and each keyword
// touches only the particles it names (a deck may carry one *SET_NODE_LIST + *INITIAL_VELOCITY
// per particle: scanning every set or particle per keyword made that quadratic).
//
// Precedence: *INITIAL_VELOCITY and *INITIAL_VELOCITY_GENERATION in deck order, the later one
// winning on a particle both name; *INITIAL_VELOCITY_NODE last, over both (the LS-DYNA manual,
// *INITIAL_VELOCITY remarks: a node initialised by several sets takes the last one unless it is
// given on *INITIAL_VELOCITY_NODE).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <string_view>
#include <optional>
#include <unordered_map>

#include "grammar/number_cast.hpp"
#include "refsolver/setup.hpp"

namespace sphdeck::refsolver {

namespace {

using Vec3 = std::array<double, 3>;

void note(std::vector<Unsupported>& out, std::string what, grammar::Span span, bool fatal = true,
          bool blocking = false) {
    Unsupported u{std::move(what), span, fatal};
    u.blocking = blocking;
    out.push_back(std::move(u));
}

bool keyword_is(const model::KeywordRecord& r, std::string_view name) {
    return r.schema ? r.schema->name == name : r.keyword == name;
}

grammar::Span span_of(const model::KeywordRecord& r, std::string_view field) {
    const model::FieldRecord* f = record_field(&r, field);
    return f ? f->span : r.span;
}

// The particles by node id, by part id, and the deck's sets by id, each built once.
class Index {
public:
    explicit Index(const model::Model& m) : m_(m) {
        const std::size_t n = m.particles.size();
        by_node_.reserve(n);
        for (std::size_t i = 0; i < n; ++i) by_node_.push_back({m.particles.node[i], static_cast<std::uint32_t>(i)});
        std::sort(by_node_.begin(), by_node_.end());
        for (const model::IdSet& s : m.node_sets) node_sets_[s.id].push_back(&s);
        for (const model::IdSet& s : m.part_sets) part_sets_[s.id].push_back(&s);
    }

    // Calls f(i) for every particle of node `node` (normally one; none when it is no particle).
    template <typename F>
    void for_node(long long node, F&& f) const {
        auto it = std::lower_bound(by_node_.begin(), by_node_.end(), std::pair<long long, std::uint32_t>{node, 0});
        for (; it != by_node_.end() && it->first == node; ++it) f(it->second);
    }
    // The sets of that id (a deck may split one set over several blocks); nullptr when none.
    const std::vector<const model::IdSet*>* node_set(long long id) const { return find(node_sets_, id); }
    const std::vector<const model::IdSet*>* part_set(long long id) const { return find(part_sets_, id); }
    // The particles of a part, grouped on first use.
    const std::vector<std::uint32_t>& part(long long id) {
        if (!parts_built_) {
            for (std::size_t i = 0; i < m_.particles.size(); ++i)
                by_part_[m_.particles.part[i]].push_back(static_cast<std::uint32_t>(i));
            parts_built_ = true;
        }
        static const std::vector<std::uint32_t> none;
        auto it = by_part_.find(id);
        return it == by_part_.end() ? none : it->second;
    }
    // Coordinates of a node (for an axis given by two nodes), or nullopt.
    std::optional<Vec3> node_position(long long id) const {
        const model::Nodes& nodes = m_.nodes;
        for (std::size_t k = 0; k < nodes.id.size(); ++k)
            if (nodes.id[k] == id) return Vec3{nodes.x[k], nodes.y[k], nodes.z[k]};
        return std::nullopt;
    }

private:
    using SetMap = std::unordered_map<std::string, std::vector<const model::IdSet*>>;
    static const std::vector<const model::IdSet*>* find(const SetMap& sets, long long id) {
        auto it = sets.find(std::to_string(id));
        return it == sets.end() ? nullptr : &it->second;
    }

    const model::Model& m_;
    std::vector<std::pair<long long, std::uint32_t>> by_node_;
    SetMap node_sets_, part_sets_;
    std::unordered_map<long long, std::vector<std::uint32_t>> by_part_;
    bool parts_built_ = false;
};

class VelocitySetup {
public:
    VelocitySetup(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out)
        : m_(m), in_(in), out_(out), index_(m), stamp_(in.vx.size(), 0) {}

    void run() {
        for (const model::KeywordRecord& r : m_.records) {
            if (keyword_is(r, "*INITIAL_VELOCITY"))
                initial_velocity(r);
            else if (keyword_is(r, "*INITIAL_VELOCITY_GENERATION"))
                generation(r);
        }
        for (const model::KeywordRecord& r : m_.records)
            if (keyword_is(r, "*INITIAL_VELOCITY_NODE")) node(r);
    }

private:
    void set(std::uint32_t i, const Vec3& v) {
        in_.vx[i] = v[0], in_.vy[i] = v[1], in_.vz[i] = in_.dimension == 2 ? 0.0 : v[2];
    }
    bool in_box(std::uint32_t i, const model::Box* box) const {
        if (!box) return true;
        const auto& b = box->bounds;
        return !(in_.x[i] < b[0] || in_.x[i] > b[1] || in_.y[i] < b[2] || in_.y[i] > b[3] || in_.z[i] < b[4] ||
                 in_.z[i] > b[5]);
    }
    // Calls f(i) for the particles of a node set; false when the set is not defined.
    template <typename F>
    bool for_node_set(long long id, F&& f) const {
        const auto* sets = index_.node_set(id);
        if (!sets) return false;
        for (const model::IdSet* s : *sets)
            for (long long node : s->members) index_.for_node(node, f);
        return true;
    }
    void rotational_note(const model::KeywordRecord& r, const model::FieldRecord& row_field) {
        note(out_,
             fmt::format("{} {} {}: particles have no rotational degrees of freedom", r.keyword, row_field.name,
                         row_field.number),
             row_field.span, false);
    }
    void missing_set(const model::KeywordRecord& r, std::string_view field, std::string_view what, long long id) {
        note(out_, fmt::format("{}: {} {} is not defined", r.keyword, what, id), span_of(r, field), true, true);
    }

    // *INITIAL_VELOCITY: NSID (0: every node), inside BOXID if given; NSIDEX nodes take card 3.
    void initial_velocity(const model::KeywordRecord& r) {
        if (record_number(&r, "ICID") != 0)
            note(out_,
                 fmt::format("*INITIAL_VELOCITY ICID {}: local coordinate systems are not supported",
                             record_number(&r, "ICID")),
                 span_of(r, "ICID"));
        for (const char* name : {"VXR", "VYR", "VZR"})
            if (record_number(&r, name) != 0) rotational_note(r, *record_field(&r, name));
        const auto nsid = record_integer(&r, "NSID");
        const auto nsidex = record_integer(&r, "NSIDEX");
        const long long boxid = record_integer(&r, "BOXID");
        const model::Box* box = boxid != 0 ? m_.box(std::to_string(boxid)) : nullptr;
        const Vec3 v{record_number(&r, "VX"), record_number(&r, "VY"), record_number(&r, "VZ")};
        const Vec3 ve{record_number(&r, "VXE"), record_number(&r, "VYE"), record_number(&r, "VZE")};
        ++record_;
        const auto chosen = [&](std::uint32_t i) {
            if (!in_box(i, box)) return;
            set(i, v);
            stamp_[i] = record_;
        };
        if (nsid == 0) {
            for (std::uint32_t i = 0; i < stamp_.size(); ++i) chosen(i);
        } else if (!for_node_set(nsid, chosen)) {
            missing_set(r, "NSID", "node set", nsid);
            return;
        }
        if (nsidex > 0 && !for_node_set(nsidex, [&](std::uint32_t i) {
                if (stamp_[i] == record_) set(i, ve);
            }))
            missing_set(r, "NSIDEX", "node set", nsidex);
    }

    // *INITIAL_VELOCITY_GENERATION, per card pair (LS-DYNA manual, *INITIAL_VELOCITY_GENERATION):
    // ID with STYP 1 part set, 2 part, 3 node set; velocity (VX, VY, VZ) + OMEGA n x (x - c) with
    // c = (XC, YC, ZC) and n the unit vector of (NX, NY, NZ); NX = -999: the axis runs from node NY
    // to node NZ. PHASE 1 (after dynamic relaxation) has no phase to wait for here.
    void generation(const model::KeywordRecord& r) {
        for (std::size_t k = 0; k < r.rows.size(); k += 2) {
            model::KeywordRecord pair{r.schema, r.keyword, r.options, r.span, {r.rows[k]}};
            if (k + 1 < r.rows.size()) pair.rows.push_back(r.rows[k + 1]);
            generation_pair(pair);
        }
    }
    void generation_pair(const model::KeywordRecord& r) {
        if (record_number(&r, "ICID") != 0)
            note(out_,
                 fmt::format("{} ICID {}: local coordinate systems are not supported", r.keyword,
                             record_number(&r, "ICID")),
                 span_of(r, "ICID"));
        if (record_number(&r, "PHASE") != 0)
            note(out_,
                 fmt::format("{} PHASE {}: there is no dynamic relaxation phase; the velocities are given at "
                             "time 0",
                             r.keyword, record_number(&r, "PHASE")),
                 span_of(r, "PHASE"));
        const auto id = record_integer(&r, "ID");
        const auto styp = record_integer(&r, "STYP", 1);
        const double omega = record_number(&r, "OMEGA");
        const Vec3 v{record_number(&r, "VX"), record_number(&r, "VY"), record_number(&r, "VZ")};
        Vec3 c{record_number(&r, "XC"), record_number(&r, "YC"), record_number(&r, "ZC")};
        Vec3 n{record_number(&r, "NX"), record_number(&r, "NY"), record_number(&r, "NZ")};
        if (omega != 0 && n[0] == -999) {
            // NY and NZ are real fields holding node ids here: 1e20 names no node, and is not converted.
            const auto node_a = grammar::checked_integer<long long>(n[1]),
                       node_b = grammar::checked_integer<long long>(n[2]);
            const auto a = node_a ? index_.node_position(*node_a) : std::nullopt;
            const auto b = node_b ? index_.node_position(*node_b) : std::nullopt;
            if (!a || !b) {
                note(out_,
                     fmt::format("{}: the axis nodes {} and {} (NX -999) are not both defined", r.keyword, n[1], n[2]),
                     span_of(r, "NY"), true, true);
                return;
            }
            c = *a;
            n = {(*b)[0] - (*a)[0], (*b)[1] - (*a)[1], (*b)[2] - (*a)[2]};
        }
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (omega != 0 && !(length > 0)) {
            note(out_, fmt::format("{}: OMEGA {} without a rotation axis (NX NY NZ are 0)", r.keyword, omega),
                 span_of(r, "OMEGA"), true, true);
            return;
        }
        const Vec3 w =
            omega != 0 ? Vec3{omega * n[0] / length, omega * n[1] / length, omega * n[2] / length} : Vec3{0, 0, 0};
        if (in_.dimension == 2 && (w[0] != 0 || w[1] != 0))
            note(out_,
                 fmt::format("{}: the rotation axis ({:.3g}, {:.3g}, {:.3g}) is not the z axis of a 2D model: "
                             "the velocities leave the x-y plane (their z parts are dropped)",
                             r.keyword, n[0], n[1], n[2]),
                 span_of(r, "NX"));
        const auto give = [&](std::uint32_t i) {
            const Vec3 d{in_.x[i] - c[0], in_.y[i] - c[1], in_.z[i] - c[2]};
            set(i,
                {v[0] + w[1] * d[2] - w[2] * d[1], v[1] + w[2] * d[0] - w[0] * d[2], v[2] + w[0] * d[1] - w[1] * d[0]});
        };
        if (styp == 3) {
            if (!for_node_set(id, give)) missing_set(r, "ID", "node set", id);
        } else if (styp == 2) {
            if (!m_.part(std::to_string(id))) return missing_set(r, "ID", "part", id);
            for (std::uint32_t i : index_.part(id)) give(i);
        } else if (styp == 1) {
            const auto* sets = index_.part_set(id);
            if (!sets) return missing_set(r, "ID", "part set", id);
            for (const model::IdSet* s : *sets)
                for (long long part : s->members)
                    for (std::uint32_t i : index_.part(part)) give(i);
        } else {
            note(out_, fmt::format("{}: STYP {} is not 1 (part set), 2 (part) or 3 (node set)", r.keyword, styp),
                 span_of(r, "STYP"), true, true);
        }
    }

    // *INITIAL_VELOCITY_NODE: one node per line (read in place: a deck may list every particle).
    void node(const model::KeywordRecord& r) {
        std::size_t not_particles = 0;
        for (const auto& row : r.rows) {
            const auto field = [&row](std::string_view name) -> const model::FieldRecord* {
                for (const model::FieldRecord& f : row)
                    if (f.name == name && f.valid) return &f;
                return nullptr;
            };
            const auto number = [&field](std::string_view name) {
                const model::FieldRecord* f = field(name);
                return f ? f->number : 0.0;
            };
            if (number("ICID") != 0)
                note(out_,
                     fmt::format("{} ICID {}: local coordinate systems are not supported", r.keyword, number("ICID")),
                     field("ICID")->span);
            for (const char* name : {"VXR", "VYR", "VZR"})
                if (number(name) != 0) rotational_note(r, *field(name));
            const Vec3 v{number("VX"), number("VY"), number("VZ")};
            bool found = false;
            index_.for_node(grammar::saturating_integer<long long>(number("NID")), [&](std::uint32_t i) {
                set(i, v);
                found = true;
            });
            not_particles += !found;
        }
        if (not_particles)
            note(out_,
                 fmt::format("{}: {} node(s) are not SPH particles; their velocities are not used", r.keyword,
                             not_particles),
                 r.span, false);
    }

    const model::Model& m_;
    SolverInput& in_;
    std::vector<Unsupported>& out_;
    Index index_;
    std::vector<std::uint32_t> stamp_;  // the *INITIAL_VELOCITY that last chose each particle (NSIDEX)
    std::uint32_t record_ = 0;
};

}  // namespace

void setup_initial_velocities(const model::Model& m, SolverInput& in, std::vector<Unsupported>& out) {
    VelocitySetup(m, in, out).run();
}

}  // namespace sphdeck::refsolver
