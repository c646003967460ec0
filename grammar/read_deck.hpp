// Reads a deck of either format: picks the LS-DYNA or the Radioss reader by content, then by
// file name (design.md: two readers, one RawDeck).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "grammar/dyna/reader.hpp"
#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar {

enum class DeckFormat { LsDyna, Radioss };

std::string_view to_string(DeckFormat f);

// The format of a deck's text: the first line that is neither blank nor a '$' comment decides
// ("#RADIOSS" or a '/' header: Radioss; a '*' keyword: LS-DYNA); otherwise the name does
// (".rad": Radioss); otherwise LS-DYNA.
DeckFormat detect_format(std::string_view text, std::string_view file_name);

// The format a read deck was read in: Radioss when its blocks are header paths ('/').
DeckFormat format_of(const RawDeck& deck);

// Reads `path` with the reader its content asks for. Throws std::runtime_error with a plain
// message when the main file cannot be read or is not a deck: a directory, an empty or binary
// file, text without a single keyword line (text/text_file.hpp).
RawDeck read_deck(const std::string& path, const dyna::ReaderOptions& options = {},
                  std::optional<DeckFormat> format = std::nullopt);

// The same for text in memory; `format` overrides detection.
RawDeck read_deck_buffer(std::string text, const std::string& display_name, const std::string& base_directory = ".",
                         const dyna::ReaderOptions& options = {}, std::optional<DeckFormat> format = std::nullopt);

}  // namespace sphdeck::grammar
