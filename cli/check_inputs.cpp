#include "cli/check_inputs.hpp"

#include "grammar/deck_files.hpp"
#include "grammar/file_paths.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <system_error>

namespace sphdeck::cli {
namespace fs = std::filesystem;
namespace {

constexpr std::uintmax_t kMostScannedBytes = std::uintmax_t{64} << 20;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// Whether --exclude leaves out a file or folder found under a given folder, as .gitignore patterns do:
// a pattern without '/' matches the name of the file or of any folder on its way ("water_tank",
// "tmp_*.k"); one with '/' matches the path as found or a folder of it ("*/old/*", "decks/old").
// Names are those below the folder given on the command line (`root`).
bool excluded(const fs::path& path, const fs::path& root, const std::vector<std::string>& exclude) {
    return std::any_of(exclude.begin(), exclude.end(), [&](std::string pattern) {
        while (pattern.size() > 1 && pattern.back() == '/') pattern.pop_back();
        if (pattern.find('/') == std::string::npos) {
            for (const fs::path& part : path.lexically_relative(root))
                if (fnmatch(pattern.c_str(), part.string().c_str(), 0) == 0) return true;
            return false;
        }
        fs::path prefix;
        for (const fs::path& part : path) {
            prefix /= part;
            if (fnmatch(pattern.c_str(), prefix.string().c_str(), 0) == 0) return true;
        }
        return false;
    });
}

std::string trimmed(std::string line) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    return first == std::string::npos ? std::string() : line.substr(first);
}

// The files a deck's text names in *INCLUDE blocks (every data line of a plain *INCLUDE, the first of
// *INCLUDE_TRANSFORM and _STAMPED_PART; *INCLUDE_PATH and the other *INCLUDE_ options with other first
// lines are left out) or #include lines, resolved from its folder.
std::vector<fs::path> named_includes(const fs::path& deck) {
    std::vector<fs::path> out;
    std::error_code ec;
    if (fs::file_size(deck, ec) > kMostScannedBytes || ec) return out;
    std::ifstream in(deck, std::ios::binary);
    bool in_include = false, every_line = false;
    for (std::string raw; std::getline(in, raw);) {
        const std::string line = trimmed(raw);
        if (line.empty() || line[0] == '$') continue;
        if (line[0] != '#' && line[0] != '*' && !in_include) continue;  // a data line: nothing to lower
        const std::string lowered = line[0] == '#' || line[0] == '*' ? lower(line) : std::string();
        if (lowered.rfind("#include", 0) == 0) {
            out.push_back(deck.parent_path() / trimmed(line.substr(8)));
            continue;
        }
        if (line[0] == '*') {
            const std::string keyword = lowered.substr(0, lowered.find_first_of(" \t,"));
            every_line = keyword == "*include";
            in_include = every_line || keyword == "*include_transform" || keyword == "*include_stamped_part";
            continue;
        }
        if (in_include) {
            std::string name = line;
            std::replace(name.begin(), name.end(), '\\', '/');
            out.push_back(deck.parent_path() / name);
            in_include = every_line;
        }
    }
    return out;
}

fs::path key(const fs::path& path) { return grammar::canonical_path(path); }

}  // namespace

ExpandedInputs expand_inputs(const std::vector<std::string>& given, const std::vector<std::string>& exclude) {
    ExpandedInputs out;
    for (const std::string& path : given) {
        std::error_code ec;
        if (path == "-" || !fs::is_directory(path, ec)) {
            out.inputs.push_back({path, false});  // a missing file: the reader says it cannot open it
            continue;
        }
        std::vector<std::string> found;
        for (fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
             !ec && it != end; it.increment(ec)) {
            if (it->is_directory(ec) &&
                (it->path().filename().string().rfind('.', 0) == 0 || excluded(it->path(), path, exclude))) {
                it.disable_recursion_pending();  // .git, .vscode ..., and folders --exclude names
                continue;
            }
            if (it->is_regular_file(ec) && grammar::is_deck_to_check(it->path()) &&
                !excluded(it->path(), path, exclude))
                found.push_back(it->path().string());
        }
        if (found.empty()) {
            out.error = "'" + path + "' is a directory with no deck files in it (*.k *.key *.dyn *.inc *_0000.rad)";
            return out;
        }
        std::sort(found.begin(), found.end());
        for (std::string& f : found) out.inputs.push_back({std::move(f), true});
    }
    return out;
}

std::vector<CheckInput> drop_included(const std::vector<CheckInput>& inputs) {
    std::set<fs::path> included;
    for (const CheckInput& input : inputs)
        if (input.found_in_folder)
            for (const fs::path& name : named_includes(input.path)) included.insert(key(name));
    std::vector<CheckInput> kept;
    for (const CheckInput& input : inputs)
        if (!input.found_in_folder || !included.count(key(input.path))) kept.push_back(input);
    return kept;
}

}  // namespace sphdeck::cli
