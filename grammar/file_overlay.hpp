// Texts held in memory that stand in for files of the same path: an editor's unsaved buffers, or
// a test's decks. The readers ask the overlay before the file system, for the main deck, its
// includes and the Radioss engine deck alike, so an edited include is read as the editor holds it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "text/source_text.hpp"

namespace sphdeck::grammar {

// What an editor knows of a text's change (issue 45): the text replaced the one at `previous_data`
// (`previous_size` bytes, still alive where a reading views it), and at least their first
// `same_prefix` and last `same_suffix` bytes are the same. A re-check that read the previous text
// finds the changed lines from it without comparing the two texts (grammar/deck_splice.hpp).
// An editor may patch the previous text's buffer in place instead of making a new one (the text held
// once, lsp/document_text.hpp): `previous_data` is then the new text's own, a reading of the previous
// text views patched bytes since, and `replaced` holds the previous text's bytes [same_prefix,
// previous_size - same_suffix), kept aside before the patch (grammar/earlier_text.hpp reads it back).
struct TextRevision {
    const char* previous_data = nullptr;
    std::size_t previous_size = 0;
    std::size_t same_prefix = 0, same_suffix = 0;
    std::shared_ptr<const std::string> replaced;  // null: the previous text is alive and unchanged
};

class FileOverlay {
public:
    // Adds or replaces the text of `path` (relative paths are taken from the working directory).
    // Texts are held by shared pointer: a deck read from the overlay shares its text instead of
    // copying it (an editor's 100 MB buffer), a copy of the overlay shares them all, and a text
    // replaced later stays alive while a deck read before still views it.
    void set(const std::filesystem::path& path, std::string text);
    // The same with a text shared with its holder (an editor's document), and what changed since
    // the text it replaces when the holder knows it.
    void set_shared(const std::filesystem::path& path, std::shared_ptr<const std::string> text,
                    const std::optional<TextRevision>& revision = std::nullopt);
    void erase(const std::filesystem::path& path);
    // Forgets what every text was told to replace: a revision describes one change, from the text the
    // last checks read, and holds only until they were checked again (an editor's next round of checks).
    void forget_revisions() { revisions_.clear(); }
    // The text held for `path`, or nullptr when the file system has the say.
    const std::string* find(const std::filesystem::path& path) const;
    std::shared_ptr<const std::string> find_shared(const std::filesystem::path& path) const;
    // How the text held for `path` differs from the one it replaced, when set_shared was told; else null.
    const TextRevision* revision(const std::filesystem::path& path) const;
    bool empty() const { return texts_.empty(); }
    // keyed by key()
    const std::map<std::filesystem::path, std::shared_ptr<const std::string>>& texts() const { return texts_; }

    // The name both sides are compared by: absolute, normalised, symbolic links resolved where the
    // folders exist (a buffer not yet saved has no file).
    static std::filesystem::path key(const std::filesystem::path& path);

private:
    std::map<std::filesystem::path, std::shared_ptr<const std::string>> texts_;
    std::map<std::filesystem::path, TextRevision> revisions_;  // keyed by key(); only texts set with one
};

// The file access the readers use: the overlay's text when it holds the path, else the disk's.
// `overlay` may be null (disk only). read_file_text throws like read_text_file (text/text_file.hpp).
bool is_regular_file(const std::filesystem::path& path, const FileOverlay* overlay);
bool file_exists(const std::filesystem::path& path, const FileOverlay* overlay);
std::string read_file_text(const std::string& path, const FileOverlay* overlay);
// The same as a SourceText: a big file on disk is mapped, not copied (text/source_text.hpp).
SourceText read_source_text(const std::string& path, const FileOverlay* overlay);
std::string read_file_prefix(const std::string& path, std::size_t bytes, const FileOverlay* overlay);

}  // namespace sphdeck::grammar
