#include "cli/deck_input.hpp"

#include <filesystem>
#include <iostream>
#include <iterator>

namespace sphdeck::cli {

std::string deck_display_name(const std::string& path, const std::string& stdin_filename) {
    if (path != "-") return path;
    return stdin_filename.empty() ? "<stdin>" : stdin_filename;
}

engine::CheckResult check_deck_input(const std::string& path, const std::string& stdin_filename,
                                     const engine::CheckOptions& options) {
    if (path != "-") return engine::check_file(path, options);
    const std::string name = deck_display_name(path, stdin_filename);
    std::string text(std::istreambuf_iterator<char>(std::cin), {});
    const std::string folder = stdin_filename.empty() ? "." : std::filesystem::path(name).parent_path().string();
    return engine::check_buffer(std::move(text), name, options, std::nullopt, folder.empty() ? "." : folder);
}

}  // namespace sphdeck::cli
