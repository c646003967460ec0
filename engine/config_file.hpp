#pragma once
// sphdeck.toml on disk: where it is and reading it. Parsing and applying the settings is lint/config's job.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "engine/check.hpp"
#include "lint/config.hpp"

namespace sphdeck::engine {

// File names searched in each folder, in order of precedence.
inline constexpr std::string_view config_names[] = {"sphdeck.toml", ".sphdeck.toml"};

// The nearest config file in the deck's folder or a folder above it, up to the filesystem root.
std::optional<std::filesystem::path> find_config(const std::filesystem::path& deck);

// Reads and parses the file at `path` into `out`.
std::optional<lint::ConfigError> load_config(const std::string& path, lint::Config& out);

// What a deck is checked with under `config` (overrides already applied), for `sphdeck check` and the
// editor alike: the reader searches the config's include paths, the rules see its solver (named by
// the config file's path), the geometry rules run. The command line changes what it overrides.
CheckOptions options_for(lint::Config config);

}  // namespace sphdeck::engine
