#include "grammar/deck_files.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace sphdeck::grammar {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

bool has_dyna_extension(const std::string& extension) {
    return std::find(dyna_deck_extensions.begin(), dyna_deck_extensions.end(), extension) != dyna_deck_extensions.end();
}

}  // namespace

bool has_deck_extension(const std::filesystem::path& path) {
    const std::string extension = lower(path.extension().string());
    return has_dyna_extension(extension) || extension == radioss_deck_extension;
}

bool is_deck_to_check(const std::filesystem::path& path) {
    if (has_dyna_extension(lower(path.extension().string()))) return true;
    const std::string name = lower(path.filename().string());
    return name.size() > radioss_starter_suffix.size() && name.ends_with(radioss_starter_suffix);
}

}  // namespace sphdeck::grammar
