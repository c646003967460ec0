#include "cli/fix_output.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "edit/unified_diff.hpp"

namespace sphdeck::cli {

std::string shown_path(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path p(path);
    const std::filesystem::path relative = std::filesystem::proximate(p, ec);
    if (ec || relative.empty() || relative.native().starts_with("..")) return path;
    return relative.string();
}

std::string write_fixed_file(const edit::FixedFile& file) {
    // Written in place (not a new file renamed over it): the file keeps its permissions and links.
    std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
    if (out) out.write(file.fixed.data(), static_cast<std::streamsize>(file.fixed.size()));
    if (out) out.flush();
    if (!out) return "cannot write " + file.path + ": " + std::strerror(errno);
    return {};
}

std::string fixed_file_diff(const edit::FixedFile& file) {
    return edit::unified_diff(shown_path(file.path), file.original,
                              edit::line_edits_between(file.original, file.fixed));
}

}  // namespace sphdeck::cli
