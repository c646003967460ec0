// The Radioss Block format reader (radioss-format.md §1-§4): a starter deck (or an in-memory
// buffer) in, a RawDeck out. Blocks are keyed by their header path in upper case, ids included
// ("/PROP/SPH/7"); the decoder (model/radioss_decoder.hpp) reads the ids and the format version.
// The engine deck <run>_0001.rad next to a starter <run>_0000.rad is read into the same RawDeck,
// as a second main file, so /DT/... cards are checked with the starter's model.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "grammar/dyna/reader.hpp"  // ReaderOptions: include paths and depth, shared by both readers
#include "grammar/raw_deck.hpp"

namespace sphdeck::grammar::radioss {

using ReaderOptions = dyna::ReaderOptions;

// Reads a starter deck, its #include files and its engine deck when one lies next to it.
// Throws std::runtime_error only when the main file cannot be read.
RawDeck read_file(const std::string& path, const ReaderOptions& options = {});

// Reads a deck held in memory. Relative includes and the engine deck are searched from
// `base_directory`.
RawDeck read_buffer(std::string text, const std::string& display_name, const std::string& base_directory = ".",
                    const ReaderOptions& options = {});

// "<run>_0001.rad" for "<run>_0000.rad", "<stem>_0001.rad" for another "<stem>.rad"; nullopt
// for names that are not starter decks (engine decks "_0001.rad" and up, other extensions).
std::optional<std::string> engine_file_name(std::string_view starter_name);

// True for an engine deck name: "<run>_NNNN.rad" with NNNN >= 1.
bool is_engine_file_name(std::string_view name);

}  // namespace sphdeck::grammar::radioss
