#include "grammar/file_paths.hpp"

#include <algorithm>
#include <system_error>

namespace sphdeck::grammar {
namespace fs = std::filesystem;

fs::path canonical_path(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) absolute = path;
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : canonical;
}

fs::path normal_path(const fs::path& path) {
    const fs::path normal = path.lexically_normal();
    if (std::none_of(path.begin(), path.end(), [](const fs::path& part) { return part == ".."; })) return normal;
    // The lexical fold is right when no folder it folds away is a symbolic link: both name one file.
    return canonical_path(normal) == canonical_path(path) ? normal : canonical_path(path);
}

}  // namespace sphdeck::grammar
