// SPH110-SPH112: particle positions in 2D models and particle masses (lsdyna-sph-cards.md §3,
// §4; *CONTROL_SPH IDIM). Decks hold millions of particles: each rule makes one finding per
// kind of problem (per part for masses), with a count and the first ids.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "grammar/keywords/schema.hpp"
#include "lint/particle_groups.hpp"
#include "lint/rules.hpp"
#include "model/id_index.hpp"

namespace sphdeck::lint {
namespace {

using ParticleGroupRef = ParticleGroup;

// The columns of `field` on card line `line_index` of a one-card keyword (*NODE, *ELEMENT_SPH),
// cut by the schema in the block's format; the whole line when that fails.
grammar::Span field_span(const grammar::RawDeck& deck, std::uint32_t line_index, std::string_view keyword,
                         std::string_view field, grammar::Span whole) {
    auto block = std::upper_bound(deck.blocks.begin(), deck.blocks.end(), line_index,
                                  [](std::uint32_t i, const grammar::Block& b) { return i < b.first_line; });
    auto match = keywords::find_keyword(keyword);
    if (block == deck.blocks.begin() || !match || match->schema->cards.empty()) return whole;
    --block;
    if (line_index >= block->first_line + block->line_count) return whole;
    const keywords::CardSpec& card = match->schema->cards.front();
    const keywords::FieldSpec* spec = card.field(field);
    if (!spec || line_index >= deck.lines.size()) return whole;
    const auto slots = keywords::layout(card, block->format);
    std::vector<grammar::Field> fields;
    const grammar::CardLine& line = deck.lines[line_index];
    grammar::cut_fields(deck.text(line), line, slots, keywords::significant_width(card, block->format), fields);
    const auto index = static_cast<std::size_t>(spec - card.fields.data());
    return index < fields.size() ? fields[index].span : whole;
}

// The card-line index of a whole-line span inside a block of `keyword`, for field_span.
std::optional<std::uint32_t> line_index(const grammar::RawDeck& deck, std::string_view keyword, grammar::Span at) {
    for (const grammar::Block& b : deck.blocks) {
        if (b.keyword != keyword) continue;
        auto first = deck.begin_lines(b), last = deck.end_lines(b);
        if (first == last || first->file != at.file) continue;
        auto l = std::lower_bound(first, last, at.line,
                                  [](const grammar::CardLine& c, std::uint32_t n) { return c.line < n; });
        if (l != last && l->line == at.line) return l.index();
    }
    return std::nullopt;
}

// The scale of the particle cloud: the largest of its bounding-box extent and its distance from
// the origin, so a lone particle far from z = 0 is still measured against something.
double model_size(const model::Nodes& n, const ParticleNodes& node_of) {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, far = 0;
    for (std::size_t i = 0; i < node_of.size(); ++i) {
        const std::uint32_t k = node_of[i];
        if (k == RuleContext::no_node) continue;
        const double x[3] = {n.x[k], n.y[k], n.z[k]};
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], x[a]), hi[a] = std::max(hi[a], x[a]);
            far = std::max(far, std::abs(x[a]));
        }
    }
    double extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
    return std::max(extent, far);
}

// SPH110 and SPH111: 2D models lie in the x-y plane; axisymmetric ones have x = radius >= 0.
// Coordinates within 1e-9 of the model size count as on the plane or the axis (round-off).
void check_planar(RuleContext& c) {
    const model::ControlSph& sph = c.model.controls.sph;
    if (!sph.present || !model::is_two_dimensional(sph.idim.value)) return;
    const model::Particles& p = c.model.particles;
    const model::Nodes& n = c.model.nodes;
    const ParticleNodes& node_of = c.particle_nodes();
    const double tol = 1e-9 * model_size(n, node_of);
    const bool axisymmetric = sph.idim.value == model::Dimension::Axisymmetric;
    ParticleGroupRef off_plane, negative_x;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::uint32_t k = node_of[i];
        if (k == RuleContext::no_node) continue;  // REF001
        if (std::abs(n.z[k]) > tol) off_plane.add(i);
        if (axisymmetric && n.x[k] < -tol) negative_x.add(i);
    }
    const int idim = static_cast<int>(sph.idim.value);
    // The node's coordinate field, found by scanning the *NODE lines (once per finding).
    auto node_note = [&](std::size_t i, std::string_view field, double value) {
        const long long id = n.id[node_of[i]];
        grammar::Span at;
        auto lines = c.node_lines({id});
        if (!lines[id].empty()) at = lines[id].front();
        if (auto where = line_index(c.deck, "*NODE", at)) at = field_span(c.deck, *where, "*NODE", field, at);
        return diag::Note{at, fmt::format("node {} has {} = {:g}", id, field == "Z" ? "z" : "x", value)};
    };
    if (off_plane.count) {
        // At the z a person typed (the first off-plane node's Z field), the particle in a note: the value
        // to edit is the node's, not the *ELEMENT_SPH line's.
        const std::size_t i = off_plane.first.front();
        diag::Note node = node_note(i, "Z", n.z[node_of[i]]);
        const grammar::Span particle = c.particle_span(i);
        const bool at_node = node.span.valid();
        auto& d = c.report("SPH110", at_node ? node.span : particle,
                           fmt::format("{} particle{} off the z = 0 plane with IDIM {}: {}; expected z = 0",
                                       off_plane.count, off_plane.count == 1 ? "" : "s", idim, off_plane.ids(p)));
        if (at_node)
            d.notes.push_back({particle, fmt::format("the particle of node {} ({})", n.id[node_of[i]], node.message)});
        else
            d.notes.push_back(std::move(node));
        d.notes.push_back({sph.idim.span, fmt::format("IDIM {} here", idim)});
    }
    if (negative_x.count) {
        const std::size_t i = negative_x.first.front();
        auto& d = c.report("SPH111", c.particle_span(i),
                           fmt::format("{} particle{} at x < 0 with IDIM -2 (x is the radius): {}; expected x >= 0",
                                       negative_x.count, negative_x.count == 1 ? "" : "s", negative_x.ids(p)));
        d.notes.push_back(node_note(i, "X", n.x[node_of[i]]));
        d.notes.push_back({sph.idim.span, "IDIM -2 here"});
    }
}

// SPH112: MASS 0 (or blank) is a massless particle: an error, grouped per part. A negative MASS
// (or *ELEMENT_SPH_VOLUME) is a volume, the mass following from the density: said once per part
// as information, since a volume where a mass was meant is a common unit slip. When more than a
// few parts have them (a mesh fragment whose particles each name their own part), one finding
// covers them all.
void check_particle_mass(RuleContext& c) {
    const model::Particles& p = c.model.particles;
    struct MassGroups {  // massless particles and volumes by part: a fact of the particles alone (lint/bulk_facts.hpp)
        PartGroups zero, volume;
    };
    const auto groups = c.bulk_facts().get<MassGroups>([&] {
        MassGroups out;
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (p.mass[i] == 0.0)
                out.zero.add(p.part[i], i);
            else if (p.mass[i] < 0.0 && !p.volume[i])
                out.volume.add(p.part[i], i);
        }
        return out;
    });
    const PartGroups &zero = groups->zero, &volume = groups->volume;
    auto mass_span = [&](std::size_t i) {
        return field_span(c.deck, p.line[i], "*ELEMENT_SPH", "MASS", c.particle_span(i));
    };
    // "particle 7 of part 1", "12 particles of part 1 (7, 8, ...)".
    auto who = [&](const ParticleGroupRef& g) {
        const std::size_t i = g.first.front();
        return g.count == 1 ? fmt::format("particle {} of part {}", p.node[i], p.part[i])
                            : fmt::format("{} particles of part {} ({})", g.count, p.part[i], g.ids(p));
    };
    auto each = [&](const PartGroups& groups, auto&& report_one) {
        if (!groups.flood()) {
            for (const auto& [part, g] : groups.by_part) report_one(g, who(g), false);
            return;
        }
        const ParticleGroupRef all = groups.merged();
        report_one(all,
                   fmt::format("{} particles of {} parts (parts {}; particles {})", all.count, groups.by_part.size(),
                               groups.part_list(), all.ids(p)),
                   true);
    };
    each(zero, [&](const ParticleGroupRef& g, const std::string& text, bool merged) {
        auto& d = c.report("SPH112", diag::Severity::Error, mass_span(g.first.front()),
                           fmt::format("MASS 0 or blank on {}; expected a mass > 0, or a volume < 0", text));
        if (merged)
            add_line_notes(c, d, g,
                           [&](std::size_t i) { return fmt::format("particle {} has MASS 0 or blank", p.node[i]); });
    });
    each(volume, [&](const ParticleGroupRef& g, const std::string& text, bool merged) {
        auto& d = c.report("SPH112", diag::Severity::Info, mass_span(g.first.front()),
                           fmt::format("negative MASS {:g} on {} is read as a volume: the mass follows from the "
                                       "material density",
                                       p.mass[g.first.front()], text));
        if (merged)
            add_line_notes(c, d, g, [&](std::size_t i) {
                return fmt::format("particle {} has MASS {:g}", p.node[i], p.mass[i]);
            });
    });
}

}  // namespace

void check_sph_particles(RuleContext& c) {
    check_planar(c);
    check_particle_mass(c);
}

}  // namespace sphdeck::lint
