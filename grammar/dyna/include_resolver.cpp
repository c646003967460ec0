#include "grammar/dyna/include_resolver.hpp"

#include <algorithm>

#include "grammar/file_paths.hpp"

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
    for (std::size_t i = 0; i < search.include_paths.size(); ++i)
        list.push_back({search.include_paths[i] / given, i < search.include_path_origins.size()
                                                             ? search.include_path_origins[i].c_str()
                                                             : "include path"});
    return list;
}

// A name written with Windows separators (`other\define.k`): the decks were run on Windows as
// written, where a backslash separates folders. Tried with / when the name as written is not found.
std::string with_forward_slashes(std::string name) {
    std::replace(name.begin(), name.end(), '\\', '/');
    return name;
}

std::optional<ResolvedInclude> resolve_as_written(const std::string& name, const IncludeSearch& search) {
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
}  // namespace

std::optional<ResolvedInclude> resolve_include(const std::string& name, const IncludeSearch& search) {
    if (auto found = resolve_as_written(name, search)) return found;
    if (name.find('\\') == std::string::npos) return std::nullopt;
    auto found = resolve_as_written(with_forward_slashes(name), search);
    if (found) found->matched_by += " ('\\' read as '/')";
    return found;
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

std::vector<IncludeTry> include_tries(const std::string& name, const IncludeSearch& search) {
    std::vector<IncludeTry> out;
    const auto add = [&](const Candidate& c, std::string rule) {
        const fs::path normal = normal_path(c.path);
        auto same = std::find_if(out.begin(), out.end(), [&](const IncludeTry& t) { return t.path == normal; });
        if (same == out.end())
            out.push_back({normal, {std::move(rule)}});
        else if (std::find(same->rules.begin(), same->rules.end(), rule) == same->rules.end())
            same->rules.push_back(std::move(rule));
    };
    for (const auto& c : candidates(name, search)) add(c, c.why);
    if (name.find('\\') != std::string::npos)
        for (const auto& c : candidates(with_forward_slashes(name), search))
            add(c, std::string(c.why) + ", '\\' read as '/'");
    return out;
}

}  // namespace sphdeck::grammar::dyna
