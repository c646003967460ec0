#include "grammar/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sphdeck::grammar {
namespace {
// std::ifstream opens a directory on Linux and then reports a size of 2^63 - 1: ask first.
std::ifstream open_regular(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw std::runtime_error("'" + path + "' is a directory, not a deck file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
    return in;
}
}  // namespace

std::string read_text_file(const std::string& path) {
    std::ifstream in = open_regular(path);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw std::runtime_error("cannot read '" + path + "': not a regular file");
    std::string text(static_cast<std::size_t>(size), '\0');
    in.seekg(0, std::ios::beg);
    in.read(text.data(), size);
    if (!in) throw std::runtime_error("cannot read '" + path + "'");
    return text;
}

std::string read_text_prefix(const std::string& path, std::size_t bytes) {
    std::ifstream in = open_regular(path);
    std::string text(bytes, '\0');
    in.read(text.data(), static_cast<std::streamsize>(bytes));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
}

std::optional<std::string> binary_or_empty(std::string_view text) {
    if (text.empty()) return "the file is empty";
    if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF")
        return "it is UTF-16 text; save it as ASCII or UTF-8";
    // Text never holds a NUL byte; binary files (d3plot, .zip, an all-NUL file) almost always do.
    if (std::size_t nul = text.find('\0'); nul != std::string_view::npos)
        return "it holds binary data (a NUL byte at offset " + std::to_string(nul) + ")";
    return std::nullopt;
}

}  // namespace sphdeck::grammar
