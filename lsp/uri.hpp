// file:// URIs as LSP clients send them, and the paths they name (RFC 8089, RFC 3986 percent-encoding).
// Only the file scheme names something sphdeck can read; other schemes give an empty path.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace sphdeck::lsp {

// "file:///work/a%20b.k" -> "/work/a b.k"; empty for another scheme or a malformed escape.
std::filesystem::path path_from_uri(std::string_view uri);

// "/work/a b.k" -> "file:///work/a%20b.k" (the path made absolute first).
std::string uri_from_path(const std::filesystem::path& path);

}  // namespace sphdeck::lsp
