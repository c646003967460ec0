#include "grammar/dyna/include_resolver.hpp"

namespace sphdeck::grammar::dyna {
namespace fs = std::filesystem;

namespace {
struct Candidate {
    fs::path path;
    const char* why;
};

std::vector<Candidate> candidates(const std::string& name, const IncludeSearch& search) {
    fs::path given(name);
    if (given.is_absolute()) return {{given, "absolute path"}};
    std::vector<Candidate> list;
    list.push_back({search.including_directory / given, "including file's folder"});
    list.push_back({search.main_directory / given, "main deck's folder"});
    for (const auto& dir : search.include_paths) list.push_back({dir / given, "include path"});
    return list;
}
}  // namespace

std::optional<ResolvedInclude> resolve_include(const std::string& name, const IncludeSearch& search) {
    const auto list = candidates(name, search);
    for (const auto& c : list) {
        if (grammar::is_regular_file(c.path, search.overlay)) return ResolvedInclude{c.path, c.why};
    }
    // No file, but something of that name (a directory): reading it says what it is, where
    // "not found" would send the user looking for a file that is there.
    for (const auto& c : list) {
        if (file_exists(c.path, search.overlay)) return ResolvedInclude{c.path, c.why};
    }
    return std::nullopt;
}

std::optional<std::string> include_budget_problem(const fs::path& path, std::size_t files, std::size_t bytes,
                                                  std::size_t max_files, std::size_t max_bytes) {
    if (files >= max_files)
        return "the deck has already read " + std::to_string(files) + " include files, the most sphdeck reads";
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && (size > max_bytes || bytes > max_bytes - size))
        return "its " + std::to_string(size) + " bytes would take the deck past " + std::to_string(max_bytes) +
               " bytes read";
    return std::nullopt;
}

std::vector<fs::path> include_candidates(const std::string& name, const IncludeSearch& search) {
    std::vector<fs::path> out;
    for (const auto& c : candidates(name, search)) out.push_back(c.path);
    return out;
}

}  // namespace sphdeck::grammar::dyna
