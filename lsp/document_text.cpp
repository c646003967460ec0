#include "lsp/document_text.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "lsp/text_change.hpp"
#include "lsp/text_position.hpp"

namespace sphdeck::lsp {
namespace {
// A chunk's size: small enough that rebuilding one is cheap (a few microseconds), big enough that
// the chunks of a 400 MB document stay a few thousand to walk.
constexpr std::size_t kChunkBytes = std::size_t{64} << 10;

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

}  // namespace

DocumentText::DocumentText(std::shared_ptr<const std::string> text) : base_(std::move(text)) {
    if (!base_) base_ = std::make_shared<const std::string>();
    split_into_chunks(*base_, chunks_, nullptr);
    if (chunks_.empty()) chunks_.push_back(Chunk{});
    since_base_ = Kept{base_->size(), base_->size()};
}

DocumentText::DocumentText(std::shared_ptr<std::string> text) : DocumentText(std::shared_ptr<const std::string>(text)) {
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
        since_base_ = since_spare_ = Kept{};
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
    since_spare_.changed(begin, end, before);
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

void DocumentText::copy_into(std::string& target, std::size_t begin, std::size_t end) const {
    std::size_t offset = 0;
    for (const Chunk& chunk : chunks_) {
        const std::size_t chunk_end = offset + chunk.text.size();
        if (chunk_end > begin && offset < end) {
            const std::size_t from = std::max(begin, offset), to = std::min(end, chunk_end);
            std::memcpy(target.data() + from, chunk.text.data() + (from - offset), to - from);
        }
        if (chunk_end >= end) break;
        offset = chunk_end;
    }
}

// `target` held the text `kept` counts from; it becomes the text now: the bytes after the kept
// prefix move with the length's change, and only those between are copied from the chunks.
void DocumentText::patch(std::string& target, Kept kept, const DocumentText& now) {
    const std::size_t old_size = target.size(), new_size = now.size();
    const std::size_t shorter = std::min(old_size, new_size);
    const std::size_t prefix = std::min(kept.prefix, shorter);
    const std::size_t suffix = std::min(kept.suffix, shorter - prefix);
    if (new_size > old_size) target.resize(new_size);
    if (new_size != old_size && suffix > 0)
        std::memmove(target.data() + new_size - suffix, target.data() + old_size - suffix, suffix);
    if (new_size < old_size) target.resize(new_size);
    now.copy_into(target, prefix, new_size - suffix);
}

DocumentText::Joined DocumentText::join_for_check() {
    const std::size_t total = size();
    std::shared_ptr<std::string> text;
    if (spare_ && spare_.use_count() == 1) {  // nothing reads the spare any more: patched, not rebuilt
        text = std::move(spare_);
        patch(*text, since_spare_, *this);
    } else {
        text = std::make_shared<std::string>();
        text->reserve(total + total / 64 + 4096);  // room to grow, so that a patch seldom reallocates
        for (const Chunk& chunk : chunks_) text->append(chunk.text);
    }
    Joined out;
    if (base_)  // none after a change of the whole text
        out.revision = grammar::TextRevision{base_->data(), base_->size(), since_base_.prefix, since_base_.suffix};
    spare_ = std::move(own_base_);  // null when the base was the opened text: the next join builds afresh
    since_spare_ = since_base_;
    own_base_ = text;
    base_ = text;
    std::size_t offset = 0;
    for (Chunk& chunk : chunks_) {  // the same lengths: every chunk views the new text
        chunk.text = std::string_view(base_->data() + offset, chunk.text.size());
        chunk.owned.reset();
        offset += chunk.text.size();
    }
    since_base_ = Kept{total, total};
    changed_ = false;
    out.text = std::move(text);
    return out;
}

void DocumentText::rebase(std::shared_ptr<const std::string> text) {
    own_base_.reset();
    spare_.reset();  // what it kept of the spare is not known for a text from elsewhere
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
