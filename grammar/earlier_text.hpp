// A text as a reading read it before an editor patched its buffer in place (issue 45: the editor
// holds a document's text once, lsp/document_text.hpp). The last check's reading views the patched
// bytes since, so a re-check that compares it with the new reading (the splice, the kept bulk blocks,
// the rules' line map) reads the earlier text from here: the bytes before the change and after it are
// the patched text's (those after moved by the change of length), and those the change replaced were
// kept aside before the patch (grammar::TextRevision::replaced).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "grammar/file_overlay.hpp"

namespace sphdeck::grammar {

class EarlierText {
public:
    // `now`: the patched buffer's text; `revision`: the patch, with `replaced` set (consistent()).
    EarlierText(std::string_view now, const TextRevision& revision);
    // Whether `revision` tells how `now` was patched: the replaced bytes and the kept ones add up.
    static bool consistent(std::string_view now, const TextRevision& revision);

    std::size_t size() const { return size_; }
    // Whether bytes [begin, begin + other.size()) of the earlier text are `other` (false past its end).
    bool equals(std::size_t begin, std::string_view other) const;
    // Bytes [begin, end) of the earlier text, copied (a few lines: an edit's).
    std::string copy(std::size_t begin, std::size_t end) const;

private:
    // Calls `piece(view)` for the views that make bytes [begin, end) up, in order.
    template <typename Piece>
    void pieces(std::size_t begin, std::size_t end, Piece&& piece) const;

    std::string_view now_, replaced_;
    std::size_t prefix_ = 0, suffix_ = 0, size_ = 0;
};

// What became of the text a reading of `path` viewed (`read`: its bytes as the reading saw them):
// unchanged (the buffer is not the one `overlay` holds for the path now, or it is and was not patched),
// patched in place (`earlier` reads it as it was), or unknown (patched, and not told how: compare nothing).
struct TextSince {
    // Not `State`: grammar/dyna/expression.cpp has a file-local one, and the unity batches
    // (cmake/speed_up.cmake) would keep the two files apart, a batch more for grammar/.
    enum class Fate { Unchanged, Patched, Unknown };
    Fate state = Fate::Unchanged;
    std::optional<EarlierText> earlier;
};
TextSince text_since(const std::string& path, std::string_view read, const FileOverlay* overlay);

}  // namespace sphdeck::grammar
