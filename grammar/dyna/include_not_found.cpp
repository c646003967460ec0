#include "grammar/dyna/include_not_found.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "grammar/similar_names.hpp"

namespace sphdeck::grammar::dyna {

namespace fs = std::filesystem;

namespace {

// Folders with thousands of files are not listed whole: a suggestion is a courtesy, not a search.
constexpr std::size_t max_listed = 4096;

// The regular files of `dir` (and the overlay's texts in it), by name.
std::vector<std::string> files_in(const fs::path& dir, const FileOverlay* overlay) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end && names.size() < max_listed; it.increment(ec))
        if (it->is_regular_file(ec)) names.push_back(it->path().filename().string());
    if (overlay) {
        const fs::path key = FileOverlay::key(dir);
        for (const auto& [path, text] : overlay->texts())
            if (path.parent_path() == key) names.push_back(path.filename().string());
    }
    return names;
}

// `name` with its file name replaced by a similar one found in a folder tried, or "".
std::string similar_file(const std::string& name, const std::vector<IncludeTry>& tries, const FileOverlay* overlay) {
    const fs::path written(name);
    const std::string file = written.filename().string();
    if (file.empty()) return {};
    std::vector<fs::path> folders;
    for (const IncludeTry& t : tries) {
        const fs::path folder = t.path.has_parent_path() ? t.path.parent_path() : fs::path(".");
        if (std::find(folders.begin(), folders.end(), folder) == folders.end()) folders.push_back(folder);
    }
    for (const fs::path& folder : folders) {
        const auto close = closest_names(file, files_in(folder, overlay));
        if (!close.empty()) return (written.parent_path() / close.front()).string();
    }
    return {};
}

std::string joined(const std::vector<std::string>& rules) {
    std::string out;
    for (std::size_t i = 0; i < rules.size(); ++i)
        out += (i == 0 ? "" : i + 1 == rules.size() ? " and " : ", ") + rules[i];
    return out;
}

}  // namespace

diag::Diagnostic include_not_found(const std::string& name, Span where, const IncludeSearch& search, bool continued,
                                   bool radioss) {
    diag::Diagnostic d{"DK010", diag::Severity::Error, fmt::format("include file '{}' not found", name), where, {}};
    const std::vector<IncludeTry> tries = include_tries(name, search);
    const std::string similar = similar_file(name, tries, search.overlay);
    if (!similar.empty()) {
        d.message += fmt::format("; did you mean '{}'?", similar);
        if (!continued) d.fixes.push_back({fmt::format("include '{}'", similar), false, {{where, similar}}});
    }
    for (const IncludeTry& t : tries)
        d.notes.push_back({Span{}, fmt::format("tried {} ({})", t.path.string(), joined(t.rules))});
    if (!fs::path(name).is_absolute())
        d.notes.push_back(
            {Span{}, radioss ? "to search another folder, give it with -I DIR (or include-paths in sphdeck.toml)"
                             : "to search another folder, name it in an *INCLUDE_PATH card (LS-DYNA "
                               "searches it too) or give it with -I DIR (or include-paths in sphdeck.toml)"});
    // The lint rules see no definition of the file: they leave references unchecked (REF001-REF005,
    // REF007, REF008) rather than report every id it would have defined.
    d.notes.push_back({Span{},
                       "references to nodes, parts, sections, materials and sets are not checked "
                       "while it is missing"});
    return d;
}

}  // namespace sphdeck::grammar::dyna
