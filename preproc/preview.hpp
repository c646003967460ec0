// The preview of an SPH model (design.md, preproc/): per part the particle spacing, the initial
// smoothing length h0 by INI mode, neighbour counts within the kernel support, the sound speed
// and stable time-step estimates; per particle the same values in model order. A pure function
// of the Model: no printing, no files. Formulas: docs/preview.md and
// /work/shared/reference/sph-algorithms.md §1, §2, §7, §10, §12.
//
// - Parts are listed by id; a part is any PID that particles name (defined or not).
// - Nearest neighbours are searched within the same part (the h0 rule of *SECTION_SPH); with
//   INI 1 over all pairs, otherwise on the grid; both give the same distances (nearest_neighbours.hpp).
// - Neighbour counts take every particle of every part, within (support_i + support_j) / 2.
// - ParticlePreview::mass is the mass a particle carries: RO * |volume| for a volume.
// - Radioss decks (Model::radioss): h per particle as the starter computes it, h0 the part's
//   median h, masses after the symmetry split, and the `radioss` members (docs/radioss.md).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "model/model.hpp"
#include "preproc/radioss_preview_types.hpp"
namespace sphdeck::preproc {
struct Stats {
    double min = 0, median = 0, max = 0;
};
struct PreviewOptions {
    std::optional<model::IniMode> ini;              // --ini: forces the mode for every part
    std::function<void(double fraction)> progress;  // optional, called now and then with 0..1
    // ParticlePreview's x, y, z, mass, h and neighbours (smooth, the solver). Without them (the
    // rules' preview) they stay empty on LS-DYNA decks, 44 bytes a particle less: part, located
    // and nn_distance are always there, and Radioss decks always get every array.
    bool particle_arrays = true;
    // Without particle_arrays, still ParticlePreview::neighbours (4 bytes a particle): what a kept
    // preview needs to follow an edit of particle positions (preproc/preview_follow.hpp).
    bool neighbour_counts = false;
};
struct FollowWindows;  // preproc/preview_follow_window.hpp
struct PartPreview {
    long long part = 0;
    std::size_t particles = 0;
    double mass_total = 0;
    double spacing = 0;                   // median nearest-neighbour distance
    double h0 = 0, h_min = 0, h_max = 0;  // h0 and HMIN*h0, HMAX*h0
    Stats nn_distance, neighbours;
    double sound_speed = 0;  // 0 when the material/EOS gives none
    double dt_estimate = 0;  // CFL: TSSFAC * h0 / c (0 when c unknown)
    double dt_radioss = 0;   // OpenRadioss particle time step at rest
    model::IniMode ini = model::IniMode::BucketSort;
    bool sphini_given = false;
    long long memory = 150;  // MEMORY of *CONTROL_SPH
    std::string notes;       // why a value is missing, in words
    // Added beyond the shared interface:
    double support = 0;                         // kernel support radius: support factor (2 cubic, 3 quintic) * h0
    double density = 0;                         // rho0 of the part's material (0 when unknown)
    double mass_median = 0;                     // median particle mass
    std::string sound_source;                   // where the sound speed comes from ("*EOS_MURNAGHAN", ...)
    std::optional<RadiossPartPreview> radioss;  // Radioss decks only (docs/radioss.md)
    // A followed preview's values near the medians, for the next followed edit (preview_follow.hpp).
    std::shared_ptr<const FollowWindows> follow;
};
struct ParticlePreview {  // one entry per particle, in model order
    std::vector<double> x, y, z, mass, nn_distance, h;
    std::vector<std::uint32_t> neighbours;
    // Added beyond the shared interface:
    std::vector<std::uint32_t> part;    // index into Preview::parts
    std::vector<std::uint8_t> located;  // 0 when the particle's node is missing (then x = y = z = 0)
    std::vector<std::uint8_t> planes;   // Radioss: /SPHBCS planes the particle lies on at t = 0 (else empty)
};
struct Preview {
    int dimension = 3;  // 2 or 3 (IDIM 2/-2 → 2)
    std::vector<PartPreview> parts;
    ParticlePreview particles;
    // Added beyond the shared interface:
    // Pairs of particles (model indices, first < second) at the same position: closer than 1e-9
    // times their part's spacing, or at distance 0; any parts. `coincident_pairs` of them in all, the
    // first (in order) kept, at most coincident_pairs_kept (nearest_neighbours.hpp): m particles at one
    // place make m (m - 1) / 2 pairs.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> coincident;
    std::uint64_t coincident_pairs = 0;
    // 1 when every particle's neighbours were counted; k when only every k-th was (too much work,
    // usually a smoothing length inflated by a stray particle) and the others copy a nearby count.
    std::size_t neighbour_sample_stride = 1;
    std::optional<RadiossPreview> radioss;  // Radioss decks only: planes, ghosts, time-step scales
};
Preview compute_preview(const model::Model& model, const PreviewOptions& options = {});
// compute_preview after an edit of the settings only (*CONTROL_SPH, *SECTION_SPH, materials, EOS):
// `old` is the preview of the same particles, in the same parts, at the same places (the caller
// checks it: engine/preview_reuse.hpp). What depends on the places alone is kept (nearest distances,
// coincident pairs), the counts too when no support moved; the rest is computed again. nullopt on
// Radioss decks, with PreviewOptions::ini, and when `old` kept only the first of its coincident pairs
// (they could not be merged with the counts' again).
std::optional<Preview> recompute_settings(const model::Model& model, const Preview& old,
                                          const PreviewOptions& options = {});
}  // namespace sphdeck::preproc
