// The file names decks go by, written once: LS-DYNA keyword files and their includes, OpenRadioss decks
// (the starter reads <run>_0000.rad, the engine <run>_0001.rad). Who lists, watches or opens deck files
// asks here: `sphdeck check FOLDER`, the include search, the editor.
#pragma once

#include <array>
#include <filesystem>
#include <string_view>

namespace sphdeck::grammar {

inline constexpr std::array<std::string_view, 4> dyna_deck_extensions = {".k", ".key", ".dyn", ".inc"};
inline constexpr std::string_view radioss_deck_extension = ".rad";
inline constexpr std::string_view radioss_starter_suffix = "_0000.rad";  // <run>_0000.rad

// Whether the file's extension, in any case, is a deck's: LS-DYNA or OpenRadioss (any .rad: starter, engine
// deck or include).
bool has_deck_extension(const std::filesystem::path& path);

// Whether a file found in a folder is a deck to check on its own: an LS-DYNA deck or include, or an
// OpenRadioss starter deck (<run>_0000.rad, in any case; its engine deck is read with it).
bool is_deck_to_check(const std::filesystem::path& path);

}  // namespace sphdeck::grammar
