// The text of one source file: either owned (a buffer from an editor, a test, a fuzzer, a small
// file read whole) or a read-only mapping of a big file. A mapping costs nothing until touched,
// is never zero-filled nor copied, and its pages can be handed back after a reading pass
// (release), so a deck of 1 GB does not keep 1 GB resident while the model is built.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace sphdeck::text {

class SourceText {
public:
    SourceText() = default;
    SourceText(std::string text) : owned_(std::move(text)) {}  // NOLINT: a buffer is a source text
    SourceText(const char* text) : owned_(text) {}             // NOLINT
    // A buffer shared with its holder (an editor's document in the overlay): not copied, kept alive
    // by the share.
    explicit SourceText(std::shared_ptr<const std::string> shared)
        : shared_(std::move(shared)), view_(shared_->data()), size_(shared_->size()) {}
    SourceText& operator=(std::string text) {
        owned_ = std::move(text);
        mapping_.reset();
        shared_.reset();
        view_ = nullptr, size_ = 0;
        return *this;
    }

    // Maps `path` read-only when it is at least `min_bytes` long and mapping works; otherwise
    // (small files, no mmap) reads it whole. Throws like read_text_file (text/text_file.hpp).
    static SourceText read(const std::string& path, std::size_t min_bytes = std::size_t{1} << 20);

    std::string_view view() const { return view_ ? std::string_view(view_, size_) : std::string_view(owned_); }
    operator std::string_view() const { return view(); }  // NOLINT: read like a string_view
    const char* data() const { return view().data(); }
    std::size_t size() const { return view().size(); }
    bool empty() const { return size() == 0; }
    std::size_t find(std::string_view s, std::size_t pos = 0) const { return view().find(s, pos); }
    std::string_view substr(std::size_t pos, std::size_t n = std::string_view::npos) const {
        return view().substr(pos, n);
    }
    bool mapped() const { return mapping_ != nullptr; }
    friend bool operator==(const SourceText& a, std::string_view b) { return a.view() == b; }

    // Bytes [begin, end) are not needed for a while: a mapping drops their whole pages from the
    // process (the next access reads them again from the page cache, unchanged); owned text stays.
    void release(std::size_t begin, std::size_t end) const;

    // Copies bytes [begin, begin + n) (clamped to the text) to `out`; a mapping's from its file (pread), so
    // that its pages are not touched (text/text_window.hpp says why).
    void copy_bytes(std::size_t begin, std::size_t n, char* out) const;

    // Whether `needle` occurs, read in slices that are released behind the search on a mapping
    // (a scan of the whole text must not make the whole file resident again).
    bool contains(std::string_view needle) const;

    struct Mapping;

private:
    std::string owned_;
    std::shared_ptr<const Mapping> mapping_;     // shared: copies of a SourceFile share the pages
    std::shared_ptr<const std::string> shared_;  // a buffer shared with its holder
    const char* view_ = nullptr;                 // the mapping's or the shared buffer's bytes
    std::size_t size_ = 0;
};

}  // namespace sphdeck::text

// grammar/ and the rooms above it named these grammar::X before text/ was split out of grammar/ (issue 39);
// the names stay so that their code reads on unchanged.
namespace sphdeck::grammar {
using text::SourceText;
}  // namespace sphdeck::grammar
