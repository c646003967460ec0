// compute_preview: positions, per-part nearest neighbours and h0, neighbour counts on one grid,
// sound speeds and time steps. A pure function of the Model (design.md, preproc/).
#include "preproc/preview.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>
#include <fmt/format.h>

#include "model/id_index.hpp"
#include "preproc/particle_positions.hpp"
#include "preproc/nearest_neighbours.hpp"
#include "preproc/radioss_preview.hpp"
#include "preproc/smoothing_length.hpp"
#include "preproc/sound_speed.hpp"
#include "preproc/stats_of.hpp"
#include "preproc/time_step.hpp"

namespace sphdeck::preproc {
namespace {

void add_preview_note(std::string& notes, const std::string& note) {
    if (note.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += note;
}

// The index in `ids` (sorted) of every particle's part.
std::vector<std::uint32_t> part_indices(const model::IdColumn& part, const std::vector<long long>& ids) {
    std::vector<std::uint32_t> out(part.size());
    long long last = 0;
    std::uint32_t last_index = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        if (i == 0 || part[i] != last) {
            last = part[i];
            last_index = static_cast<std::uint32_t>(std::lower_bound(ids.begin(), ids.end(), last) - ids.begin());
        }
        out[i] = last_index;
    }
    return out;
}

// Particles grouped by part: parts sorted by id, members in model order.
struct PartGroups {
    std::vector<long long> ids;
    std::vector<std::size_t> begin;      // ids.size() + 1 offsets into members
    std::vector<std::uint32_t> members;  // empty: one part, member k is particle k
    std::uint32_t member(std::size_t k) const { return members.empty() ? static_cast<std::uint32_t>(k) : members[k]; }
};

// `members` stays empty when there is one part and `always_members` is false: member k is then k.
PartGroups group_by_part(const model::IdColumn& part, bool always_members) {
    PartGroups g;
    // One id per run of equal parts (particles come grouped by part in decks), then sorted: not a
    // copy of every particle's part, nor a sort of a million equal values.
    for (std::size_t i = 0; i < part.size(); ++i)
        if (i == 0 || part[i] != part[i - 1]) g.ids.push_back(part[i]);
    std::sort(g.ids.begin(), g.ids.end());
    g.ids.erase(std::unique(g.ids.begin(), g.ids.end()), g.ids.end());
    g.ids.shrink_to_fit();
    g.begin.assign(g.ids.size() + 1, 0);
    if (g.ids.size() == 1 && !always_members) {
        g.begin[1] = part.size();
        return g;
    }
    const std::vector<std::uint32_t> of_particle = part_indices(part, g.ids);
    for (const std::uint32_t q : of_particle) ++g.begin[q + 1];
    for (std::size_t q = 0; q < g.ids.size(); ++q) g.begin[q + 1] += g.begin[q];
    std::vector<std::size_t> next(g.begin.begin(), g.begin.end() - 1);
    g.members.resize(part.size());
    for (std::size_t i = 0; i < part.size(); ++i) g.members[next[of_particle[i]]++] = static_cast<std::uint32_t>(i);
    return g;
}

struct PartModel {
    const model::Part* part = nullptr;
    const model::Section* section = nullptr;
    const model::Material* material = nullptr;
    const model::Eos* eos = nullptr;
};

PartModel resolve(const model::Model& m, long long id, std::string& notes) {
    PartModel r;
    r.part = m.part(std::to_string(id));
    if (!r.part) {
        add_preview_note(notes, fmt::format("part {} is not defined: *SECTION_SPH defaults used", id));
        return r;
    }
    r.section = m.section(r.part->section.value);
    if (!r.section || !r.section->sph) {
        add_preview_note(notes,
                         fmt::format("section {} is not a *SECTION_SPH: its defaults used", r.part->section.value));
        r.section = nullptr;
    }
    r.material = m.material(r.part->material.value);
    if (!r.part->eos.value.empty()) r.eos = m.eos(r.part->eos.value);
    return r;
}

// Nearest neighbours, h0, sound speed and time steps of one part. `known`: the nearest distances of
// every particle (model order) when they are known already (the places did not change): no search.
void preview_part(const model::Model& m, const ParticlePositions& at, const PartGroups& groups, std::size_t q,
                  model::IniMode mode, Preview& out, const std::function<void(double)>& progress,
                  std::span<const double> known) {
    PartPreview& pv = out.parts[q];
    ParticlePreview& pp = out.particles;
    const model::Particles& particles = m.particles;
    pv.part = groups.ids[q];
    pv.ini = mode;
    pv.memory = m.controls.sph.memory.value;
    const PartModel pm = resolve(m, pv.part, pv.notes);
    pv.density = pm.material ? pm.material->density.value : 0.0;

    const std::size_t n = pp.located.size();
    const bool arrays = !pp.mass.empty();
    std::size_t count = 0;  // the part's located particles
    std::vector<double> masses, volumes;
    masses.reserve(groups.begin[q + 1] - groups.begin[q]);
    for (std::size_t k = groups.begin[q]; k < groups.begin[q + 1]; ++k) {
        const std::uint32_t i = groups.member(k);
        ++pv.particles;
        const bool volume_flag = particles.volume[i] != 0;
        const double mass = particle_mass(particles.mass[i], volume_flag, pv.density);
        if (arrays) pp.mass[i] = mass;
        pv.mass_total += mass;
        if (!pp.located[i]) continue;
        ++count;
        masses.push_back(mass);
        if (mode == model::IniMode::FromMass)
            volumes.push_back(particle_volume(particles.mass[i], volume_flag, pv.density));
    }
    if (count < pv.particles)
        add_preview_note(pv.notes, fmt::format("{} particles without a *NODE left out", pv.particles - count));
    pv.mass_median = stats_of(std::move(masses)).median;

    // Model indices of the located particles; none kept when they are every particle of the model
    // in order (one part, every node found): 4 bytes a particle less at the preview's peak.
    const bool whole = count == n;
    std::vector<std::uint32_t> located;
    if (!whole) {
        located.reserve(count);
        for (std::size_t k = groups.begin[q]; k < groups.begin[q + 1]; ++k)
            if (pp.located[groups.member(k)]) located.push_back(groups.member(k));
    }
    const auto model_index = [&](std::size_t k) { return whole ? static_cast<std::uint32_t>(k) : located[k]; };

    // Positions: the model's own arrays when the part is every particle in node order, else a
    // copy of the part's located ones.
    NearestNeighbours nn;
    if (!known.empty()) {  // nn.index stays empty: the coincident pairs are known too
        nn.distance.resize(count);
        for (std::size_t k = 0; k < count; ++k) nn.distance[k] = known[model_index(k)];
    } else {
        PointCopy copy;
        if (!whole)
            copy = at.gather(located);
        else if (!at.in_place())
            copy = at.gather_all();
        const PointSpans points = whole && at.in_place() ? at.all() : copy.spans();
        nn = mode == model::IniMode::Global ? nearest_neighbours_all_pairs(points.x, points.y, points.z, progress)
                                            : nearest_neighbours_grid(points.x, points.y, points.z);
    }
    pv.nn_distance = stats_of(nn.distance);
    pv.spacing = pv.nn_distance.median;

    // The distances: the preview's own array when the part is every particle (no copy).
    std::span<const double> distance = nn.distance;
    if (whole) {
        pp.nn_distance = std::move(nn.distance);
        distance = pp.nn_distance;
    } else if (pp.nn_distance.size() != n) {
        pp.nn_distance.assign(n, 0.0);
    }
    const double tolerance = 1e-9 * pv.spacing;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = model_index(k);
        if (!whole) pp.nn_distance[i] = distance[k];
        if (!nn.index.empty() && nn.index[k] != NearestNeighbours::none && distance[k] <= tolerance) {
            const std::uint32_t j = model_index(nn.index[k]);
            out.coincident.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    if (m.radioss) {  // h, masses and time steps as the OpenRadioss starter computes them
        const std::span<const std::uint32_t> members(groups.members.data() + groups.begin[q],  // always kept
                                                     groups.begin[q + 1] - groups.begin[q]);
        radioss_preview_part(m, members, q, out);
        return;
    }

    const SmoothingLength h = initial_smoothing_length({pm.section, mode, distance, volumes, out.dimension});
    pv.h0 = h.h0;
    pv.sphini_given = h.from_sphini;
    add_preview_note(pv.notes, h.note);
    if (h.mode == model::IniMode::FromMass && !h.from_sphini && out.dimension == 2 &&
        m.controls.sph.idim.value == model::Dimension::Axisymmetric)
        add_preview_note(pv.notes, "INI 2 in axisymmetry: mass taken per unit thickness (not verified)");
    const model::Section defaults;
    const model::Section& section = pm.section ? *pm.section : defaults;
    pv.h_min = section.hmin.value * pv.h0;
    pv.h_max = section.hmax.value * pv.h0;
    pv.support = kernel_support_factor(section.kernel.value) * pv.h0;
    if (section.kernel.value == model::Kernel::Quadratic || section.kernel.value == model::Kernel::QuarticBSpline)
        add_preview_note(pv.notes, "kernel support assumed 2h (SPHKERN 2 and 3 are not documented)");

    if (arrays)
        for (std::size_t k = 0; k < count; ++k) pp.h[model_index(k)] = pv.h0;

    const SoundSpeed c = sound_speed(m, pm.material, pm.eos);
    pv.sound_speed = c.c;
    pv.sound_source = c.source;
    add_preview_note(pv.notes, c.note);
    const double tssfac = m.controls.tssfac.value > 0 ? m.controls.tssfac.value : 0.9;
    pv.dt_estimate = cfl_time_step(pv.h0, c.c, tssfac);
    pv.dt_radioss = radioss_particle_time_step(pv.h0, c.c, tssfac);
}

// The coincident pairs found so far (each part's nearest neighbours within the tolerance, or a kept
// preview's pairs) merged with the counts' (model indices; all counted, the first kept): the pairs so far
// that the counts' check does not hold for (or all, when there were no counts) are the ones added to
// theirs, each pair once. Then the first coincident_pairs_kept kept.
void merge_coincident(const ParticlePositions& at, Preview& out,
                      const std::vector<std::pair<std::uint32_t, std::uint32_t>>& counted, std::uint64_t total,
                      bool checked) {
    auto& found = out.coincident;
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    const auto tolerance = [&](std::uint32_t i) { return 1e-9 * out.parts[out.particles.part[i]].spacing; };
    for (auto [a, b] : found)
        if (!checked ||
            !coincident_at(at.x(a), at.y(a), at.z(a), at.x(b), at.y(b), at.z(b), std::max(tolerance(a), tolerance(b))))
            ++total;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> merged;
    merged.reserve(std::min(coincident_pairs_kept, found.size() + counted.size()));
    std::set_union(found.begin(), found.end(), counted.begin(), counted.end(), std::back_inserter(merged));
    if (merged.size() > coincident_pairs_kept) merged.resize(coincident_pairs_kept);
    merged.shrink_to_fit();
    out.coincident = std::move(merged);
    out.coincident_pairs = total;
}

// Neighbour counts of every located particle, all parts on one grid. Support and tolerance are
// the part's (per particle on Radioss decks, where h is per particle).
void count_all_neighbours(const ParticlePositions& at, Preview& out) {
    ParticlePreview& pp = out.particles;
    const std::size_t n = pp.located.size();
    // model indices of the located particles; left empty when every particle is located. None located
    // (no *NODE read: a misspelt keyword, a missing include) counts nothing: the particles would all
    // stand at the origin, one cell of n^2 pairs.
    const bool all_located = std::find(pp.located.begin(), pp.located.end(), 0) == pp.located.end();
    std::vector<std::uint32_t> located;
    if (!all_located)
        for (std::size_t i = 0; i < n; ++i)
            if (pp.located[i]) located.push_back(static_cast<std::uint32_t>(i));
    if (!all_located && located.empty()) return merge_coincident(at, out, {}, 0, false);
    const std::size_t m = all_located ? n : located.size();
    const auto model_index = [&](std::size_t k) { return all_located ? k : std::size_t{located[k]}; };
    // Positions: the model's own arrays when every particle has a node and they come in node
    // order (the usual case, and 24 bytes a particle less at the peak), else a copy.
    PointCopy copy;
    if (!all_located)
        copy = at.gather(located);
    else if (!at.in_place())
        copy = at.gather_all();
    const PointSpans points = all_located && at.in_place() ? at.all() : copy.spans();
    // Groups: the parts (pp.part itself when every particle is located), or every particle its
    // own group on Radioss decks.
    std::vector<std::uint32_t> group;
    std::vector<double> support, tolerance;
    if (out.radioss) {
        group.resize(m), support.resize(m), tolerance.resize(m);
        for (std::size_t k = 0; k < m; ++k) {
            const std::size_t i = model_index(k);
            group[k] = static_cast<std::uint32_t>(k);
            support[k] = 2.0 * pp.h[i];
            tolerance[k] = 1e-9 * out.parts[pp.part[i]].spacing;
        }
    } else {
        for (const PartPreview& pv : out.parts) support.push_back(pv.support), tolerance.push_back(1e-9 * pv.spacing);
        if (!all_located) {
            group.resize(m);
            for (std::size_t k = 0; k < m; ++k) group[k] = pp.part[located[k]];
        }
    }
    const std::span<const std::uint32_t> groups = group.empty() ? std::span<const std::uint32_t>(pp.part) : group;
    NeighbourCounts counts = count_neighbours(points.x, points.y, points.z, GroupedRadii{groups, support, tolerance});
    copy = PointCopy{};
    out.neighbour_sample_stride = counts.sample_stride;
    if (!pp.neighbours.empty())
        for (std::size_t k = 0; k < m; ++k) pp.neighbours[model_index(k)] = counts.count[k];
    std::vector<std::vector<std::uint32_t>> per_part(out.parts.size());
    if (out.parts.size() == 1) {
        per_part[0] = std::move(counts.count);
    } else {
        for (std::size_t k = 0; k < m; ++k) per_part[pp.part[model_index(k)]].push_back(counts.count[k]);
    }
    for (std::size_t q = 0; q < out.parts.size(); ++q) {
        out.parts[q].neighbours = stats_of(std::move(per_part[q]));
        if (counts.sample_stride > 1)
            add_preview_note(out.parts[q].notes,
                             fmt::format("neighbours counted for every {}th particle only (too many per particle)",
                                         counts.sample_stride));
    }
    // Model indices grow with the located ones: the pairs stay in order.
    for (auto& [a, b] : counts.coincident)
        a = static_cast<std::uint32_t>(model_index(a)), b = static_cast<std::uint32_t>(model_index(b));
    merge_coincident(at, out, counts.coincident, counts.coincident_pairs, true);
}

}  // namespace

namespace {
// compute_preview; `old` set: the preview of the same particles at the same places (recompute_settings).
Preview compute(const model::Model& m, const PreviewOptions& options, const Preview* old) {
    const auto progress = [&](double f) {
        if (options.progress) options.progress(std::clamp(f, 0.0, 1.0));
    };
    progress(0.0);
    Preview out;
    out.dimension = model::is_two_dimensional(m.controls.sph.idim.value) ? 2 : 3;
    const model::Particles& particles = m.particles;
    const std::size_t n = particles.size();
    ParticlePreview& pp = out.particles;
    const ParticlePositions at(m);  // where each particle's node is: read in place, no copy
    pp.located = at.located();
    if (options.particle_arrays || m.radioss) {
        pp.x.assign(n, 0.0), pp.y.assign(n, 0.0), pp.z.assign(n, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            if (pp.located[i]) pp.x[i] = at.x(i), pp.y[i] = at.y(i), pp.z[i] = at.z(i);
        pp.mass.assign(n, 0.0), pp.h.assign(n, 0.0), pp.neighbours.assign(n, 0);
    } else if (options.neighbour_counts) {
        pp.neighbours.assign(n, 0);
    }
    PartGroups groups = group_by_part(particles.part, m.radioss.has_value());
    out.parts.resize(groups.ids.size());
    progress(0.05);

    if (m.radioss) out.radioss = radioss_preview_setup(m);
    const model::IniMode mode = options.ini.value_or(m.controls.sph.ini.value);
    // Nearest neighbours take about half the work (all of it with INI 1): 0.05 .. 0.6 (0.9).
    const double nn_share = mode == model::IniMode::Global ? 0.85 : 0.55;
    std::size_t done = 0;
    for (std::size_t q = 0; q < groups.ids.size(); ++q) {
        const std::size_t size = groups.begin[q + 1] - groups.begin[q];
        const double start = 0.05 + nn_share * static_cast<double>(done) / std::max<std::size_t>(n, 1);
        const double share = nn_share * static_cast<double>(size) / std::max<std::size_t>(n, 1);
        preview_part(
            m, at, groups, q, mode, out, [&](double f) { progress(start + share * f); },
            old ? std::span<const double>(old->particles.nn_distance) : std::span<const double>());
        done += size;
        progress(start + share);
    }
    // The counts need neither the groups nor the node index: both go before the counts' grid is
    // built, which is the preview's peak of memory.
    // Every particle's part index: made only now, so that it is not beside the searches' grids
    // (4 bytes a particle less at the peak of memory, issue 40 item 2).
    pp.part = part_indices(particles.part, groups.ids);
    groups = PartGroups{};
    if (pp.nn_distance.size() != n) pp.nn_distance.assign(n, 0.0);  // no part had a located particle
    if (out.radioss) radioss_count_ghosts(out);
    if (old) out.coincident = old->coincident, out.coincident_pairs = old->coincident_pairs;  // the same places
    const auto same_supports = [&] {
        for (std::size_t q = 0; q < out.parts.size(); ++q)
            if (out.parts[q].support != old->parts[q].support) return false;
        return old->particles.neighbours.size() == pp.neighbours.size();
    };
    if (old && same_supports()) {  // the counts stand
        pp.neighbours = old->particles.neighbours;
        out.neighbour_sample_stride = old->neighbour_sample_stride;
        for (std::size_t q = 0; q < out.parts.size(); ++q) {
            out.parts[q].neighbours = old->parts[q].neighbours;
            if (old->neighbour_sample_stride > 1)
                add_preview_note(out.parts[q].notes,
                                 fmt::format("neighbours counted for every {}th particle only (too many per particle)",
                                             old->neighbour_sample_stride));
        }
    } else {
        count_all_neighbours(at, out);  // merges the pairs so far with the counts'
    }
    progress(1.0);
    return out;
}
}  // namespace

Preview compute_preview(const model::Model& m, const PreviewOptions& options) { return compute(m, options, nullptr); }

std::optional<Preview> recompute_settings(const model::Model& m, const Preview& old, const PreviewOptions& options) {
    if (m.radioss || old.radioss || old.particles.nn_distance.size() != m.particles.size() || options.ini ||
        old.coincident.size() != old.coincident_pairs)
        return std::nullopt;
    return compute(m, options, &old);
}

}  // namespace sphdeck::preproc
