#include "engine/include_context.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <set>
#include <system_error>
#include <tuple>

#include "grammar/deck_files.hpp"
#include "grammar/file_cache.hpp"
#include "grammar/file_overlay.hpp"
#include "grammar/file_paths.hpp"
#include "text/source_text.hpp"

namespace sphdeck::engine {
namespace fs = std::filesystem;
namespace {

bool marks_project_root(const fs::path& folder) {
    std::error_code ec;
    for (const char* marker : {"sphdeck.toml", ".sphdeck.toml", ".git", ".hg", ".svn"})
        if (fs::exists(folder / marker, ec)) return true;
    return false;
}

// The folders searched when sphdeck.toml names no roots: the file's, and those above it up to the root.
std::vector<fs::path> folders_up_to_root(const fs::path& file) {
    std::vector<fs::path> chain;
    for (fs::path folder = file.parent_path(); !folder.empty(); folder = folder.parent_path()) {
        chain.push_back(folder);
        if (marks_project_root(folder)) return chain;
        if (folder == folder.parent_path() || chain.size() >= 16) break;
    }
    chain.resize(std::min<std::size_t>(chain.size(), 2));  // no root: the file's folder and its parent
    return chain;
}

void add_deck_files(const fs::path& folder, std::vector<fs::path>& out) {
    std::error_code ec;
    std::vector<fs::path> found;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && grammar::has_deck_extension(it->path())) found.push_back(it->path());
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
}

std::vector<fs::path> subfolders(const fs::path& folder) {
    std::error_code ec;
    std::vector<fs::path> found;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_directory(ec) && it->path().filename().string().rfind('.', 0) != 0) found.push_back(it->path());
    std::sort(found.begin(), found.end());
    return found;
}

// Whether `text` holds `name` (case-insensitive: decks written on Windows name their includes so).
bool mentions_in(std::string_view text, std::string_view name) {
    if (name.empty() || text.size() < name.size()) return false;
    const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
    const char first_lower = lower(name.front());
    const char first_upper = static_cast<char>(std::toupper(static_cast<unsigned char>(name.front())));
    for (std::size_t at = 0; at + name.size() <= text.size(); ++at) {
        if (text[at] != first_lower && text[at] != first_upper) continue;
        std::size_t i = 1;
        while (i < name.size() && lower(text[at + i]) == lower(name[i])) ++i;
        if (i == name.size()) return true;
    }
    return false;
}

// The same over a deck's text, read in 1 MiB slices released behind the search when it is mapped: the
// decks around a file are only searched, and stayed resident beside its check (the 1M-particle deck
// checked among other big decks, no project root marked: 58 of its 209 MB peak).
bool mentions(const grammar::SourceText& text, std::string_view name) {
    constexpr std::size_t slice = std::size_t{1} << 20;
    const std::string_view all = text.view();
    for (std::size_t at = 0; at < all.size(); at += slice) {
        // Each slice reaches name.size() - 1 bytes into the next, so no occurrence is cut.
        const bool found = mentions_in(all.substr(at, std::min(all.size() - at, slice + name.size() - 1)), name);
        text.release(at, at + slice);
        if (found) return true;
    }
    return false;
}

// The candidate's text; through the run's cache when there is one, so the decks checked next and the
// other files checked in context find it read.
grammar::SourceText text_of(const fs::path& path, const Documents& documents, grammar::FileCache* cache) {
    if (const std::string* held = documents.find(path)) return *held;
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec || size > kMostCandidateBytes) return {};
    try {
        return cache ? cache->file(path.string())->text : grammar::SourceText::read(path.string());
    } catch (const std::exception&) {
        return {};
    }
}

// `path` absolute, its folders as the user reaches them (a linked folder stays the link): the decks
// around a file reached through a link are searched, checked and named where the user sees them.
fs::path as_reached(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return grammar::normal_path(ec ? path : absolute);
}

// The names a deck may include `path` by: its own and, when it is a link, its target's.
void add_names(const fs::path& path, std::vector<std::string>& names) {
    for (const fs::path& p : {path, Documents::key(path)})
        if (std::find(names.begin(), names.end(), p.filename().string()) == names.end())
            names.push_back(p.filename().string());
}

}  // namespace

std::vector<fs::path> candidate_decks(const fs::path& file, const std::vector<std::string>& roots) {
    std::vector<fs::path> out;
    if (!roots.empty()) {
        for (const std::string& root : roots) {
            std::error_code ec;
            if (fs::is_directory(root, ec))
                add_deck_files(root, out);
            else if (fs::is_regular_file(root, ec))
                out.emplace_back(root);
        }
    } else {
        const auto chain = folders_up_to_root(as_reached(file));
        for (const fs::path& folder : chain) add_deck_files(folder, out);
        for (const fs::path& folder : chain)
            for (const fs::path& inner : subfolders(folder))
                if (std::find(chain.begin(), chain.end(), inner) == chain.end()) add_deck_files(inner, out);
    }
    // Told apart by canonical path (a deck reached by two names is one candidate), kept as reached.
    std::vector<fs::path> unique;
    std::set<fs::path> seen{Documents::key(file)};
    for (const fs::path& candidate : out)
        if (seen.insert(Documents::key(candidate)).second && unique.size() < kMostCandidates)
            unique.push_back(as_reached(candidate));
    return unique;
}

IncludeContext check_in_context(const fs::path& file, const Documents& documents, const CheckOptions& options) {
    const fs::path key = Documents::key(file);
    const auto candidates = candidate_decks(file, options.config.roots);
    // The candidates that name the file, or name a candidate that does (an include of an include):
    // grown until nothing new is named.
    std::vector<grammar::SourceText> texts(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i)
        texts[i] = text_of(candidates[i], documents, options.reader.cache);
    std::vector<bool> reached(candidates.size(), false);
    std::vector<std::string> names;
    add_names(file, names);
    for (std::size_t named = 0; named < names.size(); ++named)
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (!reached[i] && mentions(texts[i], names[named])) {
                reached[i] = true;
                add_names(candidates[i], names);
            }
    IncludeContext context;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!reached[i]) continue;
        try {
            // Named as the user would type it from here, as the file itself was; lexically, so that a
            // deck reached through a linked folder keeps the link in its name (fs::proximate resolves it).
            std::error_code ec;
            fs::path shown = candidates[i].lexically_proximate(fs::current_path(ec));
            if (ec || shown.empty()) shown = candidates[i];
            CheckResult r = check_deck(shown.string(), documents, options);
            if (r.includes.main != key && r.includes.depends_on(key)) context.decks.push_back(std::move(r));
        } catch (const std::exception&) {
            // A candidate that cannot be read includes nothing.
        }
    }
    // A deck another of them reads is covered by that one's check.
    std::vector<bool> read_by_another(context.decks.size(), false);
    for (std::size_t i = 0; i < context.decks.size(); ++i)
        for (std::size_t j = 0; j < context.decks.size(); ++j)
            if (j != i && !read_by_another[j] && context.decks[j].includes.depends_on(context.decks[i].includes.main)) {
                read_by_another[i] = true;  // a cycle keeps its first deck
                break;
            }
    std::vector<CheckResult> tops;
    for (std::size_t i = 0; i < context.decks.size(); ++i)
        if (!read_by_another[i]) tops.push_back(std::move(context.decks[i]));
    context.decks = std::move(tops);
    // Each finding once over all decks: (code, line, column, message) seen so far.
    std::set<std::tuple<std::string, std::uint32_t, std::uint32_t, std::string>> seen;
    for (const CheckResult& r : context.decks) {
        std::vector<bool> is_file(r.deck.sources.size());  // which include instances are the file
        for (grammar::FileId id = 0; id < r.deck.sources.size(); ++id)
            is_file[id] = Documents::key(r.deck.sources.file(id).path) == key;
        std::vector<diag::Diagnostic> in_file;
        for (const diag::Diagnostic& d : r.diagnostics)
            if (d.span.valid() && d.span.file < is_file.size() && is_file[d.span.file] &&
                seen.emplace(d.code, d.span.line, d.span.column, d.message).second)
                in_file.push_back(d);
        context.findings.push_back(std::move(in_file));
    }
    return context;
}

}  // namespace sphdeck::engine
