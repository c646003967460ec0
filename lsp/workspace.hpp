// The editor's open documents and the decks they make up. Open buffers lie over the disk
// (engine::Documents), so a deck reads its edited includes as the editor holds them. An open file
// that is a deck is checked as one, unless an open deck includes it: then that deck's check covers
// it; an open file no open deck reads is checked as part of a deck on disk that includes it, if there is
// one (`sphdeck check` does the same). Changes are collected and re-checked on flush(), which publishes the diagnostics
// of every file a re-checked deck read (an empty list for a clean file and for a file no deck reads any more).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/documents.hpp"
#include "lsp/checked_deck.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/document_text.hpp"

namespace sphdeck::lsp {

class Workspace {
public:
    // Receives PublishDiagnosticsParams ({"uri", "version"?, "diagnostics"}).
    using Publish = std::function<void(const nlohmann::json& params)>;

    explicit Workspace(Publish publish) : publish_(std::move(publish)) {}

    // Folders searched for a sphdeck.toml when none is found above a deck (initialize's workspace).
    void set_roots(std::vector<std::filesystem::path> roots) { roots_ = std::move(roots); }

    // Document events (textDocument/didOpen ... didClose). `uri` must name a file (lsp/uri.hpp);
    // false when it does not or, for change, when the document is not open or a change is malformed.
    bool open(const std::string& uri, std::string text, std::int64_t version);
    bool change(const std::string& uri, std::int64_t version, const nlohmann::json& content_changes);
    bool save(const std::string& uri, const std::optional<std::string>& text);
    bool close(const std::string& uri);
    // workspace/didChangeWatchedFiles: a file changed, appeared or went away on disk; the decks that
    // read it (or looked for it) are checked again on the next flush. False for a URI that is no file.
    bool changed_on_disk(const std::string& uri);

    // Re-checks the decks that changed since the last flush and publishes; nothing when nothing changed.
    void flush();
    bool dirty() const { return !dirty_.empty(); }

    // The checked deck a request about `path` reads (the deck whose main file it is, else the first
    // that includes it) and the file's id in it; nullopt when no deck read the file. Call flush() first.
    struct Located {
        const CheckedDeck* deck = nullptr;
        grammar::FileId file = 0;
    };
    std::optional<Located> locate(const std::filesystem::path& path) const;

    // Every deck checked now (workspace/symbol), in the order they were first checked. Call flush() first.
    std::vector<const CheckedDeck*> checked_decks() const;

    // The text of an open document with every change so far (tests); nullopt when it is not open.
    std::optional<std::string> text(const std::string& uri) const;
    // The main files of the decks checked now, in the order they were first checked (tests).
    std::vector<std::filesystem::path> deck_mains() const;

private:
    struct OpenDocument {
        std::string uri;  // as the editor spelled it: diagnostics are published under it
        std::int64_t version = 0;
        std::uint64_t order = 0;  // when it was opened
        // The text as the changes leave it; `documents_` holds it joined as the last flush saw it.
        std::shared_ptr<DocumentText> text;
    };
    struct Deck {
        CheckedDeck checked;
        std::map<std::filesystem::path, FileFindings> findings;  // every file it read (or the one below)
        // The open file the deck is checked for: its main file, or an open include no open deck reads,
        // checked as part of a deck on disk that includes it (then `findings` holds that file only).
        std::filesystem::path opened_as;
    };

    // `previous`: the deck's last check, whose geometry preview is kept when the edit left its inputs
    // alone; the caller drops it after (its bulk columns may have moved into the result).
    Deck check(const std::filesystem::path& main, engine::CheckResult* previous = nullptr) const;
    // An open include checked as part of the deck around it that includes it (engine/include_context),
    // `known_main` first when given; nullopt when no deck does. Only the include's findings are kept.
    std::optional<Deck> check_in_context(const std::filesystem::path& include,
                                         const std::filesystem::path& known_main = {},
                                         engine::CheckResult* previous = nullptr) const;
    std::string uri_of(const std::filesystem::path& key, const std::string& path) const;
    bool reads(const Deck& deck, const std::filesystem::path& key) const;
    void publish(const std::set<std::filesystem::path>& files);
    // Stores the changed open documents' texts in `documents_`, each joined once (not per change). A
    // join patches the buffer the last checks read in place (lsp/document_text.hpp): every deck that
    // read a joined text is checked again in the same flush, told how it changed.
    void join_changed_texts();

    Publish publish_;
    std::vector<std::filesystem::path> roots_;
    engine::Documents documents_;                         // the open buffers, by key
    std::map<std::filesystem::path, OpenDocument> open_;  // by key
    std::uint64_t opened_ = 0;
    std::vector<Deck> decks_;                                 // in the order they were first checked
    std::set<std::filesystem::path> dirty_;                   // keys of files changed since the last flush
    std::map<std::filesystem::path, std::string> published_;  // files a deck read when last published -> URI
};

}  // namespace sphdeck::lsp
