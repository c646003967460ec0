// Reading a deck file as bytes, and telling a deck from what is not one (a directory, an empty or a
// binary file) with a plain message instead of a parse of garbage or an allocation of garbage size.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace sphdeck::grammar {

// The whole file. Throws std::runtime_error with a plain message when `path` is a directory or
// cannot be opened or read.
std::string read_text_file(const std::string& path);

// The first `bytes` bytes of the file (all of it when shorter); throws like read_text_file.
std::string read_text_prefix(const std::string& path, std::size_t bytes);

// Why `text` (the start of a file) cannot be keyword text, or nullopt: "the file is empty",
// UTF-16 text, or binary data (a NUL byte). Any other byte passes: decks carry Latin-1 comments.
std::optional<std::string> binary_or_empty(std::string_view text);

}  // namespace sphdeck::grammar
