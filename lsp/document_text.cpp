#include "lsp/document_text.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "lsp/text_change.hpp"
#include "lsp/text_position.hpp"
#include "text/page_release.hpp"

namespace sphdeck::lsp {
namespace {
// A chunk's size: small enough that rebuilding one is cheap (a few microseconds), big enough that
// the chunks of a 400 MB document stay a few thousand to walk.
constexpr std::size_t kChunkBytes = std::size_t{64} << 10;
// What a join in place keeps aside and copies at least may reach (else a sixteenth of the text).
constexpr std::size_t kKeptAsideBytes = std::size_t{4} << 20;

std::size_t count_newlines(std::string_view text) {
    std::size_t count = 0;
    const char* at = text.data();
    const char* const end = text.data() + text.size();
    while (at < end) {
        const void* newline = std::memchr(at, '\n', static_cast<std::size_t>(end - at));
        if (!newline) break;
        ++count;
        at = static_cast<const char*>(newline) + 1;
    }
    return count;
}

// The pages of `buffer`'s room past its bytes handed back to the system (not the room itself: a join
// that grows the text faults them in again). An opened text keeps the buffer its message was read
// into, whose JSON escapes took about 2 MB more than the text on a 100 MB deck, all of it touched.
void hand_back_room(std::string& buffer) {
    if (buffer.capacity() - buffer.size() < (std::size_t{1} << 20)) return;
    const std::size_t past_end = buffer.size() + 1;  // past the '\0'
    text::release_whole_pages(buffer.data() + past_end, buffer.capacity() - past_end);
}

}  // namespace

DocumentText::DocumentText(std::shared_ptr<const std::string> text) : base_(std::move(text)) {
    if (!base_) base_ = std::make_shared<const std::string>();
    split_into_chunks(*base_, chunks_, nullptr);
    if (chunks_.empty()) chunks_.push_back(Chunk{});
    since_base_ = Kept{base_->size(), base_->size()};
}

DocumentText::DocumentText(std::shared_ptr<std::string> text) : DocumentText(std::shared_ptr<const std::string>(text)) {
    if (text) hand_back_room(*text);
    own_base_ = std::move(text);
}

void DocumentText::Kept::changed(std::size_t begin, std::size_t end, std::size_t size) {
    prefix = std::min(prefix, begin);
    suffix = std::min(suffix, size - end);
}

std::size_t DocumentText::offset_of(Place place) const {
    std::size_t offset = place.offset;
    for (std::size_t k = 0; k < place.chunk; ++k) offset += chunks_[k].text.size();
    return offset;
}

// Cuts `text` after a '\n' every kChunkBytes or so: every chunk but the last ends with '\n'.
void DocumentText::split_into_chunks(std::string_view text, std::vector<Chunk>& out,
                                     const std::shared_ptr<std::string>& owner) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.size();
        if (text.size() - start > kChunkBytes) {
            const void* newline =
                std::memchr(text.data() + start + kChunkBytes, '\n', text.size() - start - kChunkBytes);
            if (newline) end = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        }
        const std::string_view piece = text.substr(start, end - start);
        out.push_back(Chunk{piece, owner, count_newlines(piece)});
        start = end;
    }
}

DocumentText::Place DocumentText::place_of(std::uint32_t line, std::uint32_t character) const {
    std::size_t before = 0;  // lines that start in the chunks before
    for (std::size_t k = 0; k < chunks_.size(); ++k) {
        const Chunk& chunk = chunks_[k];
        if (line >= before + chunk.newlines && k + 1 < chunks_.size()) {
            before += chunk.newlines;
            continue;
        }
        // The line starts in this chunk (or lies past the last line: the text's end).
        const std::string_view text = chunk.text;
        std::size_t start = 0;
        for (std::size_t skip = line - before; skip > 0; --skip) {
            if (start >= text.size()) return Place{k, text.size()};  // past the end (an empty text has no data())
            const void* newline = std::memchr(text.data() + start, '\n', text.size() - start);
            if (!newline) return Place{k, text.size()};
            start = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        }
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        if (end > start && text[end - 1] == '\r') --end;  // "\r\n": the '\r' ends the line too
        return Place{k, start + byte_offset(text.substr(start, end - start), character)};
    }
    return Place{};  // not reached: there is always a chunk
}

bool DocumentText::apply(const nlohmann::json& change) {
    const auto event = read_change(change);
    if (!event) return false;
    changed_ = true;
    const std::string& inserted = *event->text;
    if (event->whole) {
        since_base_ = Kept{};
        auto owner = std::make_shared<std::string>(inserted);
        base_.reset();  // no chunk views it any more
        chunks_.clear();
        split_into_chunks(*owner, chunks_, owner);
        if (chunks_.empty()) chunks_.push_back(Chunk{});
        return true;
    }
    Place from = place_of(event->start.line, event->start.character);
    Place to = place_of(event->end.line, event->end.character);
    if (to.chunk < from.chunk || (to.chunk == from.chunk && to.offset < from.offset)) std::swap(from, to);
    const std::size_t before = size(), begin = offset_of(from), end = offset_of(to);
    since_base_.changed(begin, end, before);
    // The chunks the range touches are rebuilt; followers join them while the result is small, so
    // deletions do not leave a trail of tiny chunks.
    std::size_t last = to.chunk;
    auto rebuilt = std::make_shared<std::string>();
    rebuilt->reserve(from.offset + inserted.size() + chunks_[last].text.size() - to.offset);
    rebuilt->append(chunks_[from.chunk].text.substr(0, from.offset))
        .append(inserted)
        .append(chunks_[last].text.substr(to.offset));
    while (rebuilt->size() < kChunkBytes / 4 && last + 1 < chunks_.size()) rebuilt->append(chunks_[++last].text);
    std::vector<Chunk> pieces;
    split_into_chunks(*rebuilt, pieces, rebuilt);
    const auto first = chunks_.begin() + static_cast<std::ptrdiff_t>(from.chunk);
    const auto position = chunks_.erase(first, chunks_.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    chunks_.insert(position, pieces.begin(), pieces.end());
    if (chunks_.empty()) chunks_.push_back(Chunk{});
    return true;
}

std::size_t DocumentText::size() const {
    std::size_t bytes = 0;
    for (const Chunk& chunk : chunks_) bytes += chunk.text.size();
    return bytes;
}

std::string DocumentText::joined() const {
    std::string out;
    out.reserve(size());
    for (const Chunk& chunk : chunks_) out.append(chunk.text);
    return out;
}

void DocumentText::copy_into(char* target, std::size_t begin, std::size_t end) const {
    std::size_t offset = 0;
    for (const Chunk& chunk : chunks_) {
        const std::size_t chunk_end = offset + chunk.text.size();
        if (chunk_end > begin && offset < end) {
            const std::size_t from = std::max(begin, offset), to = std::min(end, chunk_end);
            std::memcpy(target + (from - begin), chunk.text.data() + (from - offset), to - from);
        }
        if (chunk_end >= end) break;
        offset = chunk_end;
    }
}

// The base made the text it is now, in its own buffer: the bytes the changes replaced are kept aside
// first (the last check's reading views this buffer, and its re-check reads them: grammar::EarlierText),
// the new ones copied out of the chunks (some may view the bytes about to move), then the bytes after
// them move with the length's change and the new ones go in. Null when the buffer has no room for the
// text or the changes span too much of it (then a fresh buffer is joined).
std::optional<grammar::TextRevision> DocumentText::patch_base_in_place(std::size_t total) {
    if (!own_base_ || own_base_.get() != base_.get() || total > own_base_->capacity()) return std::nullopt;
    std::string& text = *own_base_;
    const std::size_t old_size = text.size(), shorter = std::min(old_size, total);
    const std::size_t prefix = std::min(since_base_.prefix, shorter);
    const std::size_t suffix = std::min(since_base_.suffix, shorter - prefix);
    const std::size_t old_middle = old_size - prefix - suffix, new_middle = total - prefix - suffix;
    // Kept aside and copied: a few lines for an editor's edits; a change spread over the whole text
    // is joined afresh instead (held twice until the last check goes, as every join was before).
    if (old_middle + new_middle > std::max(kKeptAsideBytes, total / 16)) return std::nullopt;
    auto replaced = std::make_shared<std::string>(text, prefix, old_middle);
    std::string inserted(new_middle, '\0');
    copy_into(inserted.data(), prefix, prefix + new_middle);
    const char* const data = text.data();
    if (total > old_size) text.resize(total);  // within its capacity: the buffer stays where it is
    if (total != old_size && suffix > 0)
        std::memmove(text.data() + total - suffix, text.data() + old_size - suffix, suffix);
    if (total < old_size) text.resize(total);
    if (new_middle > 0) std::memcpy(text.data() + prefix, inserted.data(), new_middle);
    if (text.data() != data) std::abort();  // not reached: a reallocation would leave the last reading dangling
    return grammar::TextRevision{data, old_size, prefix, suffix, std::move(replaced)};
}

DocumentText::Joined DocumentText::join_for_check() {
    const std::size_t total = size();
    Joined out;
    if (base_) out.revision = patch_base_in_place(total);  // none after a change of the whole text
    if (!out.revision) {
        auto text = std::make_shared<std::string>();
        text->reserve(total + total / 64 + 4096);  // room to grow, so that a patch seldom finds none
        for (const Chunk& chunk : chunks_) text->append(chunk.text);
        if (base_)
            out.revision =
                grammar::TextRevision{base_->data(), base_->size(), since_base_.prefix, since_base_.suffix, nullptr};
        own_base_ = std::move(text);
        base_ = own_base_;
    }
    std::size_t offset = 0;
    for (Chunk& chunk : chunks_) {  // the same lengths: every chunk views the new text
        chunk.text = std::string_view(base_->data() + offset, chunk.text.size());
        chunk.owned.reset();
        offset += chunk.text.size();
    }
    since_base_ = Kept{total, total};
    changed_ = false;
    out.text = own_base_;
    return out;
}

void DocumentText::rebase(std::shared_ptr<const std::string> text) {
    own_base_.reset();  // a text from elsewhere is never patched
    base_ = std::move(text);
    since_base_ = Kept{base_->size(), base_->size()};
    std::size_t offset = 0;
    for (Chunk& chunk : chunks_) {
        if (offset + chunk.text.size() > base_->size()) break;  // not the joined text: split it anew below
        chunk.text = std::string_view(base_->data() + offset, chunk.text.size());
        chunk.owned.reset();
        offset += chunk.text.size();
    }
    if (offset != base_->size()) {
        chunks_.clear();
        split_into_chunks(*base_, chunks_, nullptr);
        if (chunks_.empty()) chunks_.push_back(Chunk{});
    }
    changed_ = false;
}

}  // namespace sphdeck::lsp
