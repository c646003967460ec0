#include "engine/config_file.hpp"

#include <fstream>
#include <sstream>

namespace sphdeck::engine {
namespace fs = std::filesystem;

std::optional<fs::path> find_config(const fs::path& deck) {
    std::error_code ec;
    fs::path folder = fs::absolute(deck, ec).parent_path();
    while (!folder.empty()) {
        for (std::string_view name : config_names) {
            fs::path candidate = folder / name;
            if (fs::is_regular_file(candidate, ec)) return candidate;
        }
        if (folder == folder.root_path() || folder == folder.parent_path()) break;
        folder = folder.parent_path();
    }
    return std::nullopt;
}

std::optional<lint::ConfigError> load_config(const std::string& path, lint::Config& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return lint::ConfigError{path, 0, 0, "cannot read the configuration file"};
    std::ostringstream text;
    text << in.rdbuf();
    return lint::parse_config(text.str(), path, out);
}

CheckOptions options_for(lint::Config config) {
    CheckOptions options;
    options.reader.include_paths = config.include_paths;
    options.rules.geometry = true;
    if (config.solver) {
        options.rules.solver = *config.solver == "mpp" ? lint::Solver::Mpp : lint::Solver::Smp;
        options.rules.solver_source = config.path;
    }
    options.config = std::move(config);
    return options;
}

}  // namespace sphdeck::engine
