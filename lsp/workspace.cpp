#include "lsp/workspace.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <system_error>

#include <omp.h>

#include "engine/include_context.hpp"
#include "engine/recheck.hpp"
#include "lsp/deck_settings.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {
namespace fs = std::filesystem;
namespace {
bool blank(const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); });
}

// A small deck is checked on the calling thread alone. Between the parallel regions of a check,
// OpenMP's idle workers spin (libgomp's default wait policy): on a deck of 10,000 lines that cost
// five times the check itself on a busy 2-core machine (bench/bench_incremental.cpp). Big decks
// keep every thread: their decoding and geometry gain from them.
constexpr std::size_t kSmallDeckBytes = std::size_t{4} << 20;  // about 40,000 particles

class ThreadsForDeck {
public:
    explicit ThreadsForDeck(std::size_t bytes) : saved_(omp_get_max_threads()) {
        if (bytes < kSmallDeckBytes) omp_set_num_threads(1);
    }
    ~ThreadsForDeck() { omp_set_num_threads(saved_); }
    ThreadsForDeck(const ThreadsForDeck&) = delete;
    ThreadsForDeck& operator=(const ThreadsForDeck&) = delete;

private:
    int saved_;
};

// The bytes a check of the deck at `main` reads: the last check's count, else its main file's.
std::size_t deck_bytes(const fs::path& main, const engine::Documents& documents, const engine::CheckResult* previous) {
    if (previous && previous->deck.stats.bytes > 0) return previous->deck.stats.bytes;
    if (const std::string* text = documents.find(main)) return text->size();
    std::error_code error;
    const auto size = fs::file_size(main, error);
    return error ? 0 : static_cast<std::size_t>(size);
}

// A deck that cannot be read at all (`sphdeck check` says "error: ..." and exits 2): one error at
// its first line, unless the buffer is still empty (a new file being written).
nlohmann::json unreadable(const std::string& message) {
    return {{"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}},
            {"severity", 1},
            {"source", "sphdeck"},
            {"message", message}};
}
}  // namespace

bool Workspace::open(const std::string& uri, std::string text, std::int64_t version) {
    const fs::path path = path_from_uri(uri);
    if (path.empty()) return false;
    const fs::path key = engine::Documents::key(path);
    auto shared = std::make_shared<std::string>(std::move(text));
    documents_.set_shared(key, shared);
    open_[key] = OpenDocument{uri, version, opened_++, std::make_shared<DocumentText>(std::move(shared))};
    dirty_.insert(key);
    return true;
}

bool Workspace::change(const std::string& uri, std::int64_t version, const nlohmann::json& content_changes) {
    const fs::path path = path_from_uri(uri);
    if (path.empty() || !content_changes.is_array()) return false;
    const fs::path key = engine::Documents::key(path);
    const auto document = open_.find(key);
    if (document == open_.end() || !document->second.text) return false;
    // Each change rebuilds only the chunks of lines it touches; the text is joined at the next flush.
    bool all_applied = true;
    for (const nlohmann::json& change : content_changes)
        if (!document->second.text->apply(change)) all_applied = false;
    document->second.version = version;
    dirty_.insert(key);
    return all_applied;
}

void Workspace::join_changed_texts() {
    // A revision told the checks of the last flush how a text changed; the checks of this one read
    // the texts those checks read, but for the ones joined now (a join patches the buffer in place).
    documents_.forget_revisions();
    for (auto& [key, document] : open_) {
        if (!document.text || !document.text->changed()) continue;
        DocumentText::Joined joined = document.text->join_for_check();
        documents_.set_shared(key, std::move(joined.text), joined.revision);
    }
}

bool Workspace::save(const std::string& uri, const std::optional<std::string>& text) {
    const fs::path path = path_from_uri(uri);
    if (path.empty()) return false;
    const fs::path key = engine::Documents::key(path);
    if (const auto document = open_.find(key); text && document != open_.end()) {
        documents_.set(key, *text);
        document->second.text = std::make_shared<DocumentText>(documents_.find_shared(key));
    }
    dirty_.insert(key);  // a saved file may also have been written by another program
    return true;
}

bool Workspace::changed_on_disk(const std::string& uri) {
    const fs::path path = path_from_uri(uri);
    if (path.empty()) return false;
    dirty_.insert(engine::Documents::key(path));  // an open buffer still has the say over the disk
    return true;
}

bool Workspace::close(const std::string& uri) {
    const fs::path path = path_from_uri(uri);
    if (path.empty()) return false;
    const fs::path key = engine::Documents::key(path);
    const bool was_open = open_.erase(key) > 0;
    documents_.erase(key);  // the disk has the say again
    dirty_.insert(key);
    return was_open;
}

std::string Workspace::uri_of(const fs::path& key, const std::string& path) const {
    const auto document = open_.find(key);
    return document != open_.end() ? document->second.uri : uri_from_path(path);
}

bool Workspace::reads(const Deck& deck, const fs::path& key) const { return deck.findings.count(key) > 0; }

Workspace::Deck Workspace::check(const fs::path& main, engine::CheckResult* previous) const {
    Deck out;
    out.checked.main = main;
    out.opened_as = main;
    DeckSettings settings = settings_for(main, roots_);
    settings.options.rules.keep_preview = true;  // for the next re-check
    const ThreadsForDeck threads(deck_bytes(main, documents_, previous));
    try {
        // The last check is replaced by this one: what it holds is moved rather than copied.
        out.checked.result = previous
                                 ? engine::recheck_deck_taking(main.string(), documents_, settings.options, *previous)
                                 : engine::check_deck(main.string(), documents_, settings.options);
    } catch (const std::exception& e) {
        out.checked.result = engine::CheckResult{};
        out.checked.result.includes.main = main;
        FileFindings& findings = out.findings[main];
        findings.path = main.string();
        const std::string* text = documents_.find(main);
        if (!text || !blank(*text)) findings.diagnostics.push_back(unreadable(e.what()));
        return out;
    }
    out.findings = findings_by_file(out.checked.result,
                                    [this](const fs::path& key, const std::string& path) { return uri_of(key, path); });
    if (settings.error) {
        FileFindings& findings = out.findings[main];
        if (findings.path.empty()) findings.path = main.string();
        findings.diagnostics.insert(findings.diagnostics.begin(), unreadable(settings.error->to_string()));
    }
    return out;
}

std::optional<Workspace::Deck> Workspace::check_in_context(const fs::path& include, const fs::path& known_main,
                                                           engine::CheckResult* previous) const {
    DeckSettings settings = settings_for(include, roots_);
    if (settings.error) return std::nullopt;     // checked on its own, which reports the bad settings
    settings.options.rules.keep_preview = true;  // for the next re-check
    const ThreadsForDeck threads(deck_bytes(known_main.empty() ? include : known_main, documents_, previous));
    engine::CheckResult result;
    bool found = false;
    // The deck found last time first: re-searching the folders at every edit of the include costs more.
    if (!known_main.empty()) {
        try {
            result = previous
                         ? engine::recheck_deck_taking(known_main.string(), documents_, settings.options, *previous)
                         : engine::check_deck(known_main.string(), documents_, settings.options);
            found = result.includes.depends_on(include);
        } catch (const std::exception&) {
        }
    }
    if (!found) {
        engine::IncludeContext context = engine::check_in_context(include, documents_, settings.options);
        if (context.decks.empty()) return std::nullopt;
        result = std::move(context.decks.front());
    }
    Deck out;
    out.opened_as = include;
    out.checked.main = result.includes.main;
    out.checked.result = std::move(result);
    auto findings = findings_by_file(out.checked.result, [this](const fs::path& key, const std::string& path) {
        return uri_of(key, path);
    });
    const auto own = findings.find(include);
    out.findings[include] = own != findings.end() ? std::move(own->second) : FileFindings{};
    if (out.findings[include].path.empty()) out.findings[include].path = include.string();
    return out;
}

void Workspace::flush() {
    if (dirty_.empty()) return;
    join_changed_texts();
    std::set<fs::path> affected;
    const auto note = [&](const Deck& deck) {
        for (const auto& entry : deck.findings) affected.insert(entry.first);
    };
    // Closed decks go; decks that read a changed file are checked again.
    std::vector<Deck> kept;
    for (Deck& deck : decks_) {
        note(deck);
        if (!open_.count(deck.opened_as)) continue;
        if (std::any_of(dirty_.begin(), dirty_.end(), [&](const fs::path& key) {
                return reads(deck, key) || deck.checked.result.includes.depends_on(key);
            })) {
            if (deck.opened_as == deck.checked.main) {
                deck = check(deck.checked.main, &deck.checked.result);
            } else if (auto again = check_in_context(deck.opened_as, deck.checked.main, &deck.checked.result)) {
                deck = std::move(*again);
            } else {
                continue;  // no deck includes it any more: checked on its own below
            }
            note(deck);
        }
        kept.push_back(std::move(deck));
    }
    decks_ = std::move(kept);
    // Open decks that no deck reads are checked on their own, oldest first.
    std::vector<std::pair<std::uint64_t, fs::path>> candidates;
    for (const auto& [key, document] : open_) candidates.emplace_back(document.order, key);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& candidate : candidates) {
        const fs::path& key = candidate.second;  // a plain name: lambdas cannot capture bindings (clang 14)
        if (std::any_of(decks_.begin(), decks_.end(), [&](const Deck& deck) { return reads(deck, key); })) continue;
        const std::string* text = documents_.find(key);
        if (!text || !is_deck(key, *text)) continue;
        auto in_context = check_in_context(key);
        decks_.push_back(in_context ? std::move(*in_context) : check(key));
        note(decks_.back());
    }
    // A deck that another deck includes is checked as part of it (the first of a cycle stays).
    std::vector<bool> removed(decks_.size(), false);
    for (std::size_t i = 0; i < decks_.size(); ++i)
        for (std::size_t j = 0; j < decks_.size(); ++j)
            if (j != i && !removed[j] && reads(decks_[j], decks_[i].checked.main)) {
                removed[i] = true;
                break;
            }
    std::vector<Deck> roots;
    for (std::size_t i = 0; i < decks_.size(); ++i)
        if (!removed[i]) roots.push_back(std::move(decks_[i]));
    decks_ = std::move(roots);
    dirty_.clear();
    publish(affected);
}

void Workspace::publish(const std::set<fs::path>& files) {
    for (const fs::path& key : files) {
        nlohmann::json diagnostics = nlohmann::json::array();
        std::string path;
        std::size_t readers = 0;
        for (const Deck& deck : decks_) {
            const auto found = deck.findings.find(key);
            if (found == deck.findings.end()) continue;
            path = found->second.path;
            // A file two open decks read: each finding once.
            for (const nlohmann::json& d : found->second.diagnostics)
                if (readers == 0 || std::find(diagnostics.begin(), diagnostics.end(), d) == diagnostics.end())
                    diagnostics.push_back(d);
            ++readers;
        }
        nlohmann::json params;
        if (readers > 0) {
            params["uri"] = uri_of(key, path);
            published_[key] = params["uri"];
        } else {
            const auto previous = published_.find(key);
            params["uri"] = previous != published_.end() ? previous->second : uri_of(key, key.string());
            published_.erase(key);
        }
        if (const auto document = open_.find(key); document != open_.end())
            params["version"] = document->second.version;
        params["diagnostics"] = std::move(diagnostics);
        publish_(params);
    }
}

std::optional<Workspace::Located> Workspace::locate(const fs::path& path) const {
    const fs::path key = engine::Documents::key(path);
    const Deck* chosen = nullptr;
    for (const Deck& deck : decks_)
        if (deck.checked.main == key) chosen = &deck;
    for (std::size_t i = 0; !chosen && i < decks_.size(); ++i)
        if (reads(decks_[i], key)) chosen = &decks_[i];
    if (!chosen) return std::nullopt;
    const auto file = file_of(chosen->checked, key);
    if (!file) return std::nullopt;
    return Located{&chosen->checked, *file};
}

std::optional<std::string> Workspace::text(const std::string& uri) const {
    const fs::path path = path_from_uri(uri);
    if (path.empty()) return std::nullopt;
    const auto document = open_.find(engine::Documents::key(path));
    if (document == open_.end() || !document->second.text) return std::nullopt;
    return document->second.text->joined();
}

std::vector<fs::path> Workspace::deck_mains() const {
    std::vector<fs::path> out;
    for (const Deck& deck : decks_) out.push_back(deck.checked.main);
    return out;
}

std::vector<const CheckedDeck*> Workspace::checked_decks() const {
    std::vector<const CheckedDeck*> out;
    for (const Deck& deck : decks_) out.push_back(&deck.checked);
    return out;
}

}  // namespace sphdeck::lsp
