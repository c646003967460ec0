// What a deck is checked with in the editor: the sphdeck.toml found for it, as `sphdeck check`
// finds and applies it (cli/cmd_check.cpp), and whether an open file is a deck at all.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "engine/check.hpp"
#include "lint/config.hpp"

namespace sphdeck::lsp {

struct DeckSettings {
    engine::CheckOptions options;
    std::optional<lint::ConfigError> error;  // a sphdeck.toml that does not parse (then ignored)
};

// The nearest sphdeck.toml in the deck's folder or above (engine::find_config), else one at the
// root of a workspace folder; the options `sphdeck check DECK` would use with it.
DeckSettings settings_for(const std::filesystem::path& deck, const std::vector<std::filesystem::path>& roots);

// Whether an open file is a deck: by name (LS-DYNA .k .key .dyn .inc, OpenRadioss .rad including
// _0000.rad) or by content (the first line that is not blank or a comment is a '*' keyword, a '/'
// Radioss header or #RADIOSS).
bool is_deck(const std::filesystem::path& path, std::string_view text);

}  // namespace sphdeck::lsp
