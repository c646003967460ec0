// A window on a text that passes over millions of lines front to back (the line split, the bulk blocks'
// decoding, the formatter's quick test) read through: a mapped file's bytes are copied (pread) into one
// buffer the window reuses, rather than read from the mapping. On the virtual machine the benchmarks run
// on, the first touch of each 4 KiB page of a mapping costs about 3 us (shadow paging), which made a pass
// over a 100 MB mapping 80-90 ms where the same pass through a reused buffer takes 35-40 ms, the copy
// included (bench/README.md, "the deck read through a reused buffer"); where page faults are cheap the
// gain is smaller, the copy taking their place. A buffer of the size of a second-level cache keeps the
// bytes hot for the pass, and the mapping's pages never become resident. Owned text (small files,
// editors' buffers) is read in place.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "text/source_text.hpp"

namespace sphdeck::text {

class TextWindow {
public:
    static constexpr std::size_t default_bytes = std::size_t{256} << 10;

    explicit TextWindow(const SourceText& text, std::size_t bytes = default_bytes) : text_(text), bytes_(bytes) {}
    TextWindow(const TextWindow&) = delete;
    TextWindow& operator=(const TextWindow&) = delete;

    // The text from byte `begin` (at most its size) on, at least `least` bytes of it, fewer only where the
    // text ends first; perhaps more. Valid until the next call. When the window reads, it reads the
    // buffer's size, but not more than `most` (nor less than `least`): a pass that ends there.
    // Inline: the passes ask once a line, and most asks lie in what the buffer holds already.
    std::string_view from(std::size_t begin, std::size_t least, std::size_t most = ~std::size_t{0}) {
        // Held (only a mapping's bytes are, and within the text: the clamps of read() change nothing).
        if (held_ > 0 && begin >= begin_ && begin - begin_ <= held_ && least <= held_ - (begin - begin_))
            return {buffer_.get() + (begin - begin_), held_ - (begin - begin_)};
        return read(begin, least, most);
    }

    // Whether `view` (from this window) runs to the text's end.
    bool at_end(std::string_view view) const { return view.data() + view.size() == end_; }

private:
    std::string_view read(std::size_t begin, std::size_t least, std::size_t most);  // the rest of from()

    const SourceText& text_;
    std::size_t bytes_;               // the buffer's usual size
    std::unique_ptr<char[]> buffer_;  // on a mapping: bytes [begin_, begin_ + held_) of the text
    std::size_t capacity_ = 0;
    std::size_t begin_ = 0, held_ = 0;
    const char* end_ = nullptr;  // where the text's last byte held ends (at_end)
};

}  // namespace sphdeck::text
