#pragma once
// sphdeck.toml on disk: where it is and reading it. Parsing and applying the settings is lint/config's job.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "lint/config.hpp"

namespace sphdeck::engine {

// File names searched in each folder, in order of precedence.
inline constexpr std::string_view config_names[] = {"sphdeck.toml", ".sphdeck.toml"};

// The nearest config file in the deck's folder or a folder above it, up to the filesystem root.
std::optional<std::filesystem::path> find_config(const std::filesystem::path& deck);

// Reads and parses the file at `path` into `out`.
std::optional<lint::ConfigError> load_config(const std::string& path, lint::Config& out);

}  // namespace sphdeck::engine
