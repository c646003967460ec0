// sphdeck sol2sph DECK: the particles OpenRadioss will create for SOL2SPH solids (docs/radioss.md):
// per part elements, particles, pitch, smoothing-length guidance and the mass check; the
// particles themselves as CSV and VTK (.vtp) on request.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "diag/render_text.hpp"
#include "io/csv_writer.hpp"
#include "io/vtp_writer.hpp"
#include "engine/check.hpp"
#include "preproc/sol2sph.hpp"

namespace sphdeck::cli {
namespace {

struct Sol2sphArgs {
    std::string deck, format = "table", csv, vtk, out_dir;
    bool vtk_binary = false;
    std::vector<std::string> include_paths;
};

// The mass check: particles carry the element mass to 1e-12 (relative).
constexpr double mass_tolerance = 1e-12;

bool part_passes(const preproc::Sol2sphPart& p) {
    return p.ndir >= 1 && p.ndir <= 9 && std::abs(p.relative_difference()) < mass_tolerance;
}

std::string format_g4(double v) { return fmt::format("{:.4g}", v); }

std::vector<io::Column> particle_columns(const preproc::Sol2sphParticles& p, std::vector<long long>& ids) {
    ids.resize(p.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<long long>(i + 1);
    return {{"index", std::span<const long long>(ids)},
            {"element", std::span<const long long>(p.element)},
            {"solid_part", std::span<const long long>(p.solid_part)},
            {"sph_part", std::span<const long long>(p.sph_part)},
            {"mass", std::span<const double>(p.mass)},
            {"mass_starter", std::span<const double>(p.mass_starter)},
            {"volume", std::span<const double>(p.volume)}};
}

std::string line_location(const engine::CheckResult& r, std::uint32_t line) {
    if (line >= r.deck.lines.size()) return r.model.radioss ? r.model.radioss->run_name : "";
    const grammar::CardLine& l = r.deck.lines[line];
    return fmt::format("{}:{}", r.deck.sources.file(l.file).display_name, l.line);
}

// "file:line:column" of a span, for findings about a part.
std::string line_location(const engine::CheckResult& r, const grammar::Span& span) {
    if (!span.valid()) return r.model.radioss ? r.model.radioss->run_name : "";
    return fmt::format("{}:{}:{}", r.deck.sources.file(span.file).display_name, span.line, span.column);
}

// The check column: no particles is not a mass check that passed.
std::string check_word(const preproc::Sol2sphPart& p) {
    if (!p.no_particles.empty()) return "none";
    return part_passes(p) ? "ok" : "FAILED";
}

std::string guidance(const preproc::Sol2sphPart& p) {
    std::string s = fmt::format(
        "pitch {}: h {} to {} (1.25 to 1.5 x pitch, docs/radioss.md: SOL2SPH); h_1D 3 "
        "with hcst 1.2 gives {}",
        format_g4(p.pitch), format_g4(1.25 * p.pitch), format_g4(1.5 * p.pitch), format_g4(1.2 * p.pitch));
    if (p.sph_h_1d == 3)
        s += fmt::format("; SPH part {} uses h_1D 3", p.sph_part);
    else if (p.sph_h > 0)
        s += fmt::format("; SPH part {} gives h {} = {} x pitch", p.sph_part, format_g4(p.sph_h),
                         format_g4(p.sph_h / p.pitch));
    else
        s += fmt::format("; SPH part {} gives no h: the starter takes (sqrt2 mp / rho)^(1/3), not the pitch",
                         p.sph_part);
    return s;
}

nlohmann::ordered_json sol2sph_json(const Sol2sphArgs& args, const engine::CheckResult& r, const preproc::Sol2sph& s) {
    nlohmann::ordered_json parts = nlohmann::ordered_json::array(), issues = nlohmann::ordered_json::array();
    for (const preproc::Sol2sphPart& p : s.parts)
        parts.push_back(
            {{"solid_part", p.solid_part},
             {"property", p.property},
             {"ndir", p.ndir},
             {"sph_part", p.sph_part},
             {"bricks", p.bricks},
             {"tetras", p.tetras},
             {"particles", p.particles},
             {"skipped_elements", p.skipped},
             {"pitch", p.pitch},
             {"h_guidance", {{"low", 1.25 * p.pitch}, {"high", 1.5 * p.pitch}, {"hcst_default", 1.2 * p.pitch}}},
             {"sph_h", p.sph_h},
             {"solid_density", p.solid_density},
             {"sph_density", p.sph_density},
             {"element_mass", p.element_mass},
             {"particle_mass", p.particle_mass},
             {"relative_difference", p.relative_difference()},
             {"starter_mass", p.starter_mass},
             {"starter_relative_difference", p.starter_relative_difference()},
             {"mass_check",
              p.no_particles.empty() ? nlohmann::ordered_json(part_passes(p)) : nlohmann::ordered_json(nullptr)},
             {"location", line_location(r, p.span)},
             {"warnings",
              p.no_particles.empty() ? std::vector<std::string>{} : std::vector<std::string>{p.no_particles}},
             {"notes", p.notes}});
    for (const preproc::Sol2sphIssue& i : s.issues)
        issues.push_back({{"element", i.element}, {"location", line_location(r, i.line)}, {"message", i.message}});
    return {{"version", SPHDECK_VERSION},
            {"deck", args.deck},
            {"particles", s.particles.size()},
            {"parts", std::move(parts)},
            {"issues", std::move(issues)}};
}

void print_sol2sph(const Sol2sphArgs& args, const engine::CheckResult& r, const preproc::Sol2sph& s) {
    fmt::print("{}: {} SOL2SPH part(s), {} particle(s)\n\n", args.deck, s.parts.size(), s.particles.size());
    std::vector<std::vector<std::string>> rows = {{"part", "Ndir", "SPH part", "bricks", "tetras", "particles", "pitch",
                                                   "element mass", "particle mass", "rel. diff", "check"}};
    for (const preproc::Sol2sphPart& p : s.parts)
        rows.push_back({std::to_string(p.solid_part), std::to_string(p.ndir), std::to_string(p.sph_part),
                        std::to_string(p.bricks), std::to_string(p.tetras), std::to_string(p.particles),
                        format_g4(p.pitch), fmt::format("{:.6g}", p.element_mass),
                        fmt::format("{:.6g}", p.particle_mass), fmt::format("{:.1e}", p.relative_difference()),
                        check_word(p)});
    std::vector<std::size_t> width(rows[0].size(), 0);
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c) line += fmt::format("{}{:>{}}", c ? "  " : "", row[c], width[c]);
        fmt::print("{}\n", line);
    }
    fmt::print(
        "\npitch: median of (element volume / particles per element)^(1/3); check: particle mass within "
        "1e-12 of the element mass\n");
    for (const preproc::Sol2sphPart& p : s.parts) {
        if (p.particles > 0) fmt::print("part {}: {}\n", p.solid_part, guidance(p));
        if (p.particles > 0 && std::abs(p.starter_relative_difference()) >= mass_tolerance)
            fmt::print(
                "part {}: OpenRadioss gives these particles {:.6g} in all ({:+.2e} of the element mass): it "
                "takes det J at each sub-cell centre (soltosph.F), exact only for parallelepipeds\n",
                p.solid_part, p.starter_mass, p.starter_relative_difference());
        for (const std::string& note : p.notes) fmt::print("part {}: {}\n", p.solid_part, note);
        if (!p.no_particles.empty())
            fmt::print("{}: warning: part {}: {}\n", line_location(r, p.span), p.solid_part, p.no_particles);
    }
    for (const preproc::Sol2sphIssue& i : s.issues) fmt::print("{}: error: {}\n", line_location(r, i.line), i.message);
}

int run_sol2sph(const Sol2sphArgs& args) {
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    const engine::CheckResult r = engine::check_file(args.deck, options);
    if (!r.model.radioss) {
        fmt::print(stderr,
                   "sphdeck: error: {} is not an OpenRadioss deck: SOL2SPH is a Radioss option "
                   "(/PROP/TYPE14 or /PROP/TYPE6 with Ndir)\n",
                   args.deck);
        return exit_usage;
    }
    const preproc::Sol2sph s = preproc::generate_sol2sph(r.model);
    const bool json = args.format == "json";
    if (json)
        fmt::print("{}\n", sol2sph_json(args, r, s).dump(2));
    else if (s.parts.empty())
        fmt::print("{}: no SOL2SPH solids (a /PROP/TYPE14 or /PROP/TYPE6 with Ndir > 0 used by a part)\n", args.deck);
    else
        print_sol2sph(args, r, s);
    std::fflush(stdout);

    std::string csv = args.csv, vtk = args.vtk;
    if (!args.out_dir.empty()) {
        std::filesystem::create_directories(args.out_dir);
        const std::string stem = std::filesystem::path(args.deck).stem().string();
        if (csv.empty()) csv = (std::filesystem::path(args.out_dir) / (stem + "_sol2sph.csv")).string();
        if (vtk.empty()) vtk = (std::filesystem::path(args.out_dir) / (stem + "_sol2sph.vtp")).string();
    }
    std::FILE* notes = json ? stderr : stdout;
    std::vector<long long> ids;
    const std::vector<io::Column> cols = particle_columns(s.particles, ids);
    if (!csv.empty()) {
        std::vector<io::Column> with_xyz = cols;
        with_xyz.insert(with_xyz.begin() + 1, {{"x", std::span<const double>(s.particles.x)},
                                               {"y", std::span<const double>(s.particles.y)},
                                               {"z", std::span<const double>(s.particles.z)}});
        io::write_csv_file(csv, with_xyz);
        fmt::print(notes, "wrote {} ({} particles)\n", csv, s.particles.size());
    }
    if (!vtk.empty()) {
        io::write_vtp_file(vtk, io::VtpPoints{s.particles.x, s.particles.y, s.particles.z, cols},
                           args.vtk_binary ? io::VtpEncoding::Base64 : io::VtpEncoding::Ascii);
        fmt::print(notes, "wrote {} ({} points)\n", vtk, s.particles.size());
    }
    bool ok = s.issues.empty();
    for (const preproc::Sol2sphPart& p : s.parts) ok = ok && part_passes(p);
    return ok ? exit_clean : exit_findings;
}

}  // namespace

std::function<int()> setup_sol2sph(CLI::App& app) {
    auto args = std::make_shared<Sol2sphArgs>();
    app.add_option("deck", args->deck, "OpenRadioss starter deck (<run>_0000.rad)")->required();
    app.add_option("--format", args->format, "output format")
        ->check(CLI::IsMember({"table", "json"}))
        ->capture_default_str();
    app.add_option("--csv", args->csv,
                   "write one row per particle: index, x, y, z, element, solid_part, sph_part, "
                   "mass, mass_starter, volume");
    app.add_option("--vtk", args->vtk, "write the particles with the same point data as VTK XML PolyData (.vtp)");
    app.add_flag("--vtk-binary", args->vtk_binary, "store the .vtp arrays base64-encoded");
    app.add_option("--out", args->out_dir,
                   "write <deck>_sol2sph.csv and <deck>_sol2sph.vtp into this folder "
                   "(created when missing)");
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for #include files")
        ->allow_extra_args(false);
    return [args] { return run_sol2sph(*args); };
}

}  // namespace sphdeck::cli
