// An open document's text held in chunks of whole lines (issue 45 item 1), so that a change costs
// in proportion to the change and the chunk it falls in, not to the document: finding its line walks
// the chunks' line counts, not the text, and only the chunks it touches are rebuilt. Unedited chunks
// view the text the document was opened (or last joined) with, without a copy. The readers want one
// contiguous buffer: join_for_check() makes it once per check, and a burst of changes between two
// checks costs no pass over the text at all (lsp::Workspace joins at flush, before its check).
// Joining costs in proportion to the changes too, and the text is held once: the join patches the
// buffer the last check read in place (the bytes the changes replaced kept aside first, and a change
// of the text's length moving the bytes after it), and tells the re-check which bytes may differ and
// what they were (grammar::TextRevision, grammar/earlier_text.hpp) instead of comparing 100 MB texts.
// So the text a join returns changes at the next join: whoever reads it must be done by then, or read
// the earlier bytes through the revision (lsp::Workspace re-checks every deck that read a changed
// document in the flush that joins it). A buffer without room for the text, or changes spread over
// much of it, get a fresh buffer instead (the old one freed once its last reader goes).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "grammar/file_overlay.hpp"

namespace sphdeck::lsp {

class DocumentText {
public:
    // Views `text` (shared, never copied) until a change touches it.
    explicit DocumentText(std::shared_ptr<const std::string> text);
    // The same for a text this document owns (its holder gave it up): the joins patch it in place.
    explicit DocumentText(std::shared_ptr<std::string> text);

    // Applies one LSP change event with the rules of lsp/text_change.hpp (UTF-16 positions, lines
    // split at '\n', clamped to the text). False (and the text unchanged) when it is not one.
    bool apply(const nlohmann::json& change);

    // Whether a change came since the text was opened or last joined.
    bool changed() const { return changed_; }
    // The whole text as a new string (one pass over the chunks).
    std::string joined() const;
    // The whole text for a check: the chunks view it from now on. `revision`: how it differs from the
    // text of the last join or the opened text (none after a change of the whole text); with
    // `replaced` set when that text's buffer was patched into this one.
    struct Joined {
        std::shared_ptr<const std::string> text;
        std::optional<grammar::TextRevision> revision;
    };
    Joined join_for_check();
    // After the joined text was stored as `text` (the same bytes): the chunks view it from now on and
    // the edited chunks' own copies are freed. A text from elsewhere is never patched.
    void rebase(std::shared_ptr<const std::string> text);

    std::size_t size() const;
    std::size_t chunk_count() const { return chunks_.size(); }

private:
    struct Chunk {
        std::string_view text;               // into `base_` or into `owned`
        std::shared_ptr<std::string> owned;  // the chunk's own text once a change rebuilt it
        std::size_t newlines = 0;
    };
    // Where a byte lies: chunk and offset in it.
    struct Place {
        std::size_t chunk = 0;
        std::size_t offset = 0;
    };
    Place place_of(std::uint32_t line, std::uint32_t character) const;
    std::size_t offset_of(Place place) const;  // from the text's start
    // Bytes a text shares with an earlier one at its start and end (at least: a bound kept per change).
    struct Kept {
        std::size_t prefix = 0, suffix = 0;
        void changed(std::size_t begin, std::size_t end, std::size_t size);  // bytes [begin, end) of `size` replaced
    };
    void copy_into(char* target, std::size_t begin, std::size_t end) const;  // text bytes [begin, end) to target
    std::optional<grammar::TextRevision> patch_base_in_place(std::size_t total);
    void split_into_chunks(std::string_view text, std::vector<Chunk>& out, const std::shared_ptr<std::string>& owner);

    std::shared_ptr<const std::string> base_;
    std::vector<Chunk> chunks_;  // never empty; each but the last ends with '\n'
    bool changed_ = false;
    // Since the last join: what the text keeps of `base_` (told to the re-check).
    Kept since_base_;
    std::shared_ptr<std::string> own_base_;  // `base_` when it is this document's own (the next join patches it)
};

}  // namespace sphdeck::lsp
