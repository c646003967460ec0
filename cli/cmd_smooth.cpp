// sphdeck smooth DECK: what the solver will start from, per part: particles, mass, spacing, the
// initial smoothing length and its bounds, neighbour counts, a time step estimate and the INI
// mode used; as a table or JSON, with per-particle CSV, VTK (.vtp) and SVG histograms on request.
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/deck_input.hpp"
#include "cli/text_table.hpp"
#include "cli/progress_bar.hpp"
#include "diag/render_text.hpp"
#include "io/csv_writer.hpp"
#include "io/svg_histogram.hpp"
#include "io/vtp_writer.hpp"
#include "engine/check.hpp"
#include "preproc/preview.hpp"
#include "preproc/preview_json.hpp"
#include "preproc/sph_mesh_box.hpp"

namespace sphdeck::cli {
namespace {

struct SmoothArgs {
    std::string deck;   // as shown in the output: the path, or --stdin-filename for `-`
    std::string input;  // as given: a path or `-`
    std::string stdin_filename;
    std::string format = "table";
    std::optional<int> ini;
    std::string csv, vtk, plot;
    bool vtk_binary = false;
    std::vector<std::string> include_paths;
};

std::string_view ini_name(model::IniMode mode) {
    switch (mode) {
        case model::IniMode::BucketSort: return "bucket sort";
        case model::IniMode::Global: return "global search";
        case model::IniMode::FromMass: return "from the mass";
    }
    return "?";
}

std::string g4(double v) { return fmt::format("{:.4g}", v); }

// The particles that have a position, with the columns the CSV and VTK files share.
struct ParticleTable {
    std::vector<long long> id, part;
    std::vector<double> x, y, z, mass, nn_distance, h;
    std::vector<std::uint32_t> neighbours;
    std::vector<std::uint32_t> planes;  // Radioss: symmetry planes each particle lies on (else empty)
    std::size_t left_out = 0;           // particles without a *NODE

    std::vector<io::Column> columns() const {
        std::vector<io::Column> out = {{"id", std::span<const long long>(id)},
                                       {"part", std::span<const long long>(part)},
                                       {"mass", std::span<const double>(mass)},
                                       {"nn_distance", std::span<const double>(nn_distance)},
                                       {"h", std::span<const double>(h)},
                                       {"neighbours", std::span<const std::uint32_t>(neighbours)}};
        if (planes_column) out.push_back({"planes", std::span<const std::uint32_t>(planes)});
        return out;
    }
    bool planes_column = false;
};

ParticleTable particle_table(const model::Model& m, const preproc::Preview& p) {
    ParticleTable t;
    const preproc::ParticlePreview& pp = p.particles;
    for (std::size_t i = 0; i < pp.x.size(); ++i) {
        if (!pp.located[i]) {
            ++t.left_out;
            continue;
        }
        t.id.push_back(m.particles.node[i]);
        t.part.push_back(p.parts[pp.part[i]].part);
        t.x.push_back(pp.x[i]), t.y.push_back(pp.y[i]), t.z.push_back(pp.z[i]);
        t.mass.push_back(pp.mass[i]);
        t.nn_distance.push_back(pp.nn_distance[i]);
        t.h.push_back(pp.h[i]);
        t.neighbours.push_back(pp.neighbours[i]);
        if (!pp.planes.empty()) t.planes.push_back(pp.planes[i]);
    }
    t.planes_column = !pp.planes.empty();
    return t;
}

void write_csv(const std::string& path, const ParticleTable& t) {
    std::vector<io::Column> columns = t.columns();
    columns.insert(columns.begin() + 2, {{"x", std::span<const double>(t.x)},
                                         {"y", std::span<const double>(t.y)},
                                         {"z", std::span<const double>(t.z)}});
    io::write_csv_file(path, columns);
}

void write_vtk(const std::string& path, const ParticleTable& t, bool binary) {
    io::VtpPoints points{t.x, t.y, t.z, t.columns()};
    io::write_vtp_file(path, points, binary ? io::VtpEncoding::Base64 : io::VtpEncoding::Ascii);
}

// Two panels per part: h over the particle's nearest-neighbour distance, and neighbour counts.
void write_plot(const std::string& path, const std::string& deck, const preproc::Preview& p) {
    std::vector<io::HistogramPanel> panels;
    for (std::size_t q = 0; q < p.parts.size(); ++q) {
        const long long id = p.parts[q].part;
        io::HistogramPanel ratio{fmt::format("part {}: h / nearest-neighbour distance", id),
                                 "h / nn distance",
                                 {},
                                 false};
        io::HistogramPanel count{fmt::format("part {}: neighbours", id),
                                 fmt::format("particles within {} of each particle", g4(p.parts[q].support)),
                                 {},
                                 true};
        const preproc::ParticlePreview& pp = p.particles;
        for (std::size_t i = 0; i < pp.x.size(); ++i) {
            if (pp.part[i] != q || !pp.located[i]) continue;
            if (pp.nn_distance[i] > 0) ratio.values.push_back(pp.h[i] / pp.nn_distance[i]);
            count.values.push_back(pp.neighbours[i]);
        }
        panels.push_back(std::move(ratio));
        panels.push_back(std::move(count));
    }
    io::SvgOptions options;
    options.title = fmt::format("sphdeck smooth {}", deck);
    io::write_svg_file(path, panels, options);
}

// "file:line" of a *DEFINE_SPH_MESH_BOX keyword ("" when unknown).
std::string box_location(const engine::CheckResult& r, const preproc::MeshBox& b) {
    return b.span.valid() ? fmt::format("{}:{}", r.deck.sources.file(b.span.file).display_name, b.span.line) : "";
}

nlohmann::ordered_json mesh_boxes_json(const engine::CheckResult& r, const preproc::MeshBoxParticles& boxes) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const preproc::MeshBox& b : boxes.boxes)
        out.push_back({{"location", box_location(r, b)},
                       {"part", b.part},
                       {"particles", b.particles},
                       {"counts", {b.nx, b.ny, b.nz}},
                       {"cell", {b.dx, b.dy, b.dz}},
                       {"skipped", b.skipped}});
    return out;
}

nlohmann::ordered_json to_json(const SmoothArgs& args, const preproc::Preview& p) {
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    for (const preproc::PartPreview& pv : p.parts) parts.push_back(preproc::part_preview_json(pv));
    nlohmann::ordered_json out = {{"version", SPHDECK_VERSION},
                                  {"deck", args.deck},
                                  {"dimension", p.dimension},
                                  {"particles", p.particles.x.size()},
                                  {"ini_forced", args.ini.has_value()},
                                  {"coincident_pairs", p.coincident_pairs},
                                  {"neighbour_sample_stride", p.neighbour_sample_stride},
                                  {"parts", std::move(parts)}};
    if (p.radioss) out["radioss"] = preproc::radioss_preview_json(*p.radioss);
    return out;
}

// The Radioss values (docs/radioss.md): h rule, symmetry mass split, ghosts, time steps.
void print_radioss(const preproc::Preview& p) {
    const preproc::RadiossPreview& g = *p.radioss;
    fmt::print(
        "OpenRadioss parts: h0 is the median of the particles' h; h_min, h_max: hmin*h0, hmax*h0 with "
        "h_1D 3, h0 with h_1D 2 (constant), 0 when h is unbounded (h_1D 0, 1)\n");
    fmt::print("\nOpenRadioss (docs/radioss.md): alpha_sort {}, particle step scale {}{}{}\n", g4(g.alpha_sort),
               g4(g.dt_scale_particle), g.nodal ? fmt::format(", /DT/NODA scale {}", g4(g.dt_scale_nodal)) : "",
               g.engine_deck ? "" : " (no engine deck read: default scale)");
    for (const preproc::PartPreview& pv : p.parts) {
        if (!pv.radioss) continue;
        const preproc::RadiossPartPreview& r = *pv.radioss;
        fmt::print("part {}: h0 {} ({}), h {}..{}; {}\n", pv.part, g4(pv.h0), r.h_rule, g4(r.h_smallest),
                   g4(r.h_largest), r.h_evolution);
        fmt::print("part {}: mass {} before the symmetry split, {} after; particles on 1/2/3+ planes: {}/{}/{}\n",
                   pv.part, g4(r.mass_before), g4(r.mass_after), r.on_planes[1], r.on_planes[2], r.on_planes[3]);
        fmt::print("part {}: particle time step {} (qa {}, qb {}){}\n", pv.part,
                   r.dt_particle > 0 ? g4(r.dt_particle) : "-", g4(r.qa), g4(r.qb),
                   g.nodal ? fmt::format(", nodal time step {}", r.dt_nodal > 0 ? g4(r.dt_nodal) : "-") : "");
        for (std::size_t k = 0; k < g.planes.size(); ++k)
            fmt::print("part {}: /SPHBCS {}: {} particle(s) would create a ghost ({} by the coded bound)\n", pv.part,
                       g.planes[k].id, r.ghosts[k], r.ghosts_coded[k]);
    }
    for (const preproc::RadiossPlanePreview& plane : g.planes)
        fmt::print("/SPHBCS/{}/{}: {} particle(s) on the plane at t = 0, {} ghost(s) ({} by the coded bound)\n",
                   plane.type, plane.id, plane.on_plane, plane.ghosts, plane.ghosts_coded);
    for (long long id : g.unknown_planes) fmt::print("/SPHBCS {}: plane unknown (frame or Dir): left out\n", id);
}

// Where the header's dimension and INI come from: --ini, the deck's *CONTROL_SPH, or LS-DYNA's
// defaults when the deck has none (SPH120).
std::string_view settings_source(const SmoothArgs& args, bool control_sph) {
    if (args.ini) return ", forced by --ini";
    return control_sph ? ", from *CONTROL_SPH" : ", default: no *CONTROL_SPH";
}

void print_smooth(const SmoothArgs& args, const preproc::Preview& p, bool control_sph) {
    const model::IniMode mode = p.parts.empty() ? model::IniMode::BucketSort : p.parts.front().ini;
    if (p.radioss)  // no INI: h as the OpenRadioss starter computes it
        fmt::print("{}: {} particles in {} part(s), {}D, OpenRadioss deck (h0: the starter's rule, spinih.F)\n\n",
                   args.deck, p.particles.x.size(), p.parts.size(), p.dimension);
    else
        fmt::print("{}: {} particles in {} part(s), {}D, INI {} ({}{})\n\n", args.deck, p.particles.x.size(),
                   p.parts.size(), p.dimension, static_cast<int>(mode), ini_name(mode),
                   settings_source(args, control_sph));
    std::vector<std::vector<std::string>> rows = {
        {"part", "particles", "mass", "spacing", "h0", "h_min", "h_max", "neighbours", "dt", "ini"}};
    for (const preproc::PartPreview& pv : p.parts) {
        rows.push_back({std::to_string(pv.part), std::to_string(pv.particles), g4(pv.mass_total), g4(pv.spacing),
                        g4(pv.h0), g4(pv.h_min), g4(pv.h_max),
                        fmt::format("{}/{}/{}", g4(pv.neighbours.min), g4(pv.neighbours.median), g4(pv.neighbours.max)),
                        pv.dt_estimate > 0 ? g4(pv.dt_estimate) : "-",
                        fmt::format("{}{}", static_cast<int>(pv.ini), pv.sphini_given ? " (SPHINI)" : "")});
    }
    print_table(rows, WordColumn::Last);
    fmt::print(
        "\nmass: total per part; spacing: median nearest-neighbour distance; h_min, h_max: HMIN*h0, "
        "HMAX*h0;\nneighbours: min/median/max particles within the kernel support; dt: TSSFAC*h0/c, "
        "'-' when the sound speed c is unknown\n");
    for (const preproc::PartPreview& pv : p.parts)
        for (const std::string& note : preproc::split_notes(pv.notes)) fmt::print("part {}: {}\n", pv.part, note);
    if (p.coincident_pairs > 0)
        fmt::print("warning: {} pair(s) of particles at the same position\n", p.coincident_pairs);
    if (p.radioss) print_radioss(p);
}

// One line per *DEFINE_SPH_MESH_BOX: what it added to the table above, or why nothing.
void print_mesh_boxes(const engine::CheckResult& r, const preproc::MeshBoxParticles& boxes) {
    for (const preproc::MeshBox& b : boxes.boxes) {
        const std::string where = box_location(r, b);
        if (b.skipped.empty())
            fmt::print(
                "{}: *DEFINE_SPH_MESH_BOX: {} particles of part {} ({} x {} x {}, cells {} x {} x {}) "
                "included above\n",
                where, b.particles, b.part, b.nx, b.ny, b.nz, g4(b.dx), g4(b.dy), g4(b.dz));
        else
            fmt::print("{}: *DEFINE_SPH_MESH_BOX of part {}: not previewed: {}\n", where, b.part, b.skipped);
    }
}

int run_smooth(const SmoothArgs& args) {
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    // The geometry rules compute the preview of the deck's own INI mode: printed as it is unless
    // --ini asks for another mode (computing it twice was half the command's time on big decks).
    options.rules.keep_preview = !args.ini.has_value();
    options.rules.preview_arrays = options.rules.keep_preview;
    const engine::CheckResult r = check_deck_input(args.input, args.stdin_filename, options);
    const diag::Counts counts = diag::count(r.diagnostics);
    // *DEFINE_SPH_MESH_BOX particles join the deck's own (preproc/sph_mesh_box.hpp).
    const preproc::MeshBoxParticles boxes = preproc::generate_mesh_box_particles(r.model);
    const model::Model extended = boxes.size() ? preproc::with_mesh_box_particles(r.model, boxes) : model::Model{};
    const model::Model& model = boxes.size() ? extended : r.model;
    if (model.particles.size() == 0) {
        for (const diag::Diagnostic& d : r.diagnostics)
            if (d.severity == diag::Severity::Error) fmt::print(stderr, "{}", diag::render_concise(d, r.deck.sources));
        fmt::print(stderr, "sphdeck: error: {}: no SPH particles (*ELEMENT_SPH): nothing to preview\n", args.deck);
        return exit_usage;
    }
    if (counts.errors > 0)
        fmt::print(stderr, "sphdeck: note: {} has {} error(s); 'sphdeck check {}' lists them\n", args.deck,
                   counts.errors, args.deck);

    preproc::PreviewOptions preview_options;
    if (args.ini) preview_options.ini = static_cast<model::IniMode>(*args.ini);
    std::shared_ptr<const preproc::Preview> computed = boxes.size() ? nullptr : r.preview;
    if (!computed) {
        ProgressBar bar("smooth");
        if (bar.enabled()) preview_options.progress = [&bar](double f) { bar.update(f); };
        computed = std::make_shared<const preproc::Preview>(preproc::compute_preview(model, preview_options));
        bar.finish();
    }
    const preproc::Preview& preview = *computed;

    const bool json = args.format == "json";
    if (json) {
        nlohmann::ordered_json out = to_json(args, preview);
        out["mesh_boxes"] = mesh_boxes_json(r, boxes);
        fmt::print("{}\n", out.dump(2));
    } else {
        print_smooth(args, preview, model.controls.sph.present);
        print_mesh_boxes(r, boxes);
    }
    std::fflush(stdout);
    std::FILE* notes = json ? stderr : stdout;
    if (!args.csv.empty() || !args.vtk.empty()) {
        const ParticleTable table = particle_table(model, preview);
        if (table.left_out > 0)
            fmt::print(stderr, "sphdeck: warning: {} particle(s) without a *NODE left out of the files\n",
                       table.left_out);
        if (!args.csv.empty()) {
            write_csv(args.csv, table);
            fmt::print(notes, "wrote {} ({} particles)\n", args.csv, table.id.size());
        }
        if (!args.vtk.empty()) {
            write_vtk(args.vtk, table, args.vtk_binary);
            fmt::print(notes, "wrote {} ({} points)\n", args.vtk, table.id.size());
        }
    }
    if (!args.plot.empty()) {
        write_plot(args.plot, args.deck, preview);
        fmt::print(notes, "wrote {} ({} histograms)\n", args.plot, 2 * preview.parts.size());
    }
    return exit_clean;
}

}  // namespace

std::function<int()> setup_smooth(CLI::App& app) {
    auto args = std::make_shared<SmoothArgs>();
    app.add_option("deck", args->input, "LS-DYNA keyword deck or OpenRadioss starter deck, or - for standard input")
        ->required();
    app.add_option("--stdin-filename", args->stdin_filename, stdin_help);
    app.add_option("--format", args->format, "output format")
        ->check(CLI::IsMember({"table", "json"}))
        ->capture_default_str();
    app.add_option("--ini", args->ini,
                   "initial smoothing length mode, instead of the deck's *CONTROL_SPH INI: "
                   "0 bucket sort, 1 global search, 2 from the mass")
        ->check(CLI::Range(0, 2));
    app.add_option("--csv", args->csv,
                   "write one row per particle: id, part, x, y, z, mass, nn_distance, h, "
                   "neighbours");
    app.add_option("--vtk", args->vtk,
                   "write the particles and the same point data as VTK XML PolyData (.vtp) "
                   "for ParaView");
    app.add_flag("--vtk-binary", args->vtk_binary,
                 "store the .vtp arrays base64-encoded: smaller and faster "
                 "to load than ASCII");
    app.add_option("--plot", args->plot,
                   "write histograms of h / nearest-neighbour distance and neighbour "
                   "counts per part (.svg)");
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files")
        ->allow_extra_args(false);
    return [args] {
        args->deck = deck_display_name(args->input, args->stdin_filename);
        return run_smooth(*args);
    };
}

}  // namespace sphdeck::cli
