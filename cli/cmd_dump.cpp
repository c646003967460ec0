// sphdeck dump DECK --format json: the decoded model, for scripts and for checking the reader
// (LS-DYNA: model/model_json.hpp; OpenRadioss: model/radioss_json.hpp).
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "engine/check.hpp"
#include "model/model_json.hpp"
#include "model/radioss_json.hpp"

namespace sphdeck::cli {
namespace {

struct DumpArgs {
    std::string deck;
    std::string format = "json";
    bool particles = false;
    std::vector<std::string> include_paths;
};

int run_dump(const DumpArgs& args) {
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    engine::CheckResult r = engine::check_file(args.deck, options);
    // Decks carry Latin-1 comments and titles: bytes that are not UTF-8 become U+FFFD, as in check.
    const auto replace = nlohmann::ordered_json::error_handler_t::replace;
    if (grammar::format_of(r.deck) == grammar::DeckFormat::Radioss) {
        nlohmann::ordered_json out = model::radioss_to_json(model::read_radioss_records(r.deck), r.model, r.deck,
                                                                  args.particles);
        fmt::print("{}\n", out.dump(2, ' ', false, replace));
        return exit_clean;
    }
    nlohmann::ordered_json out = model::to_json(r.model, r.deck, {args.particles});
    fmt::print("{}\n", out.dump(2, ' ', false, replace));
    return exit_clean;
}

}  // namespace

std::function<int()> setup_dump(CLI::App& app) {
    auto args = std::make_shared<DumpArgs>();
    app.add_option("deck", args->deck, "LS-DYNA keyword deck or OpenRadioss starter deck")->required();
    app.add_option("--format", args->format, "output format")->check(CLI::IsMember({"json"}))->capture_default_str();
    app.add_flag("--particles", args->particles, "list every particle (id, part, mass), not only counts");
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files");
    return [args] { return run_dump(*args); };
}

}  // namespace sphdeck::cli
