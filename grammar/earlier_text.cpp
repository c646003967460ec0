#include "grammar/earlier_text.hpp"

#include <algorithm>
#include <cstring>

namespace sphdeck::grammar {

EarlierText::EarlierText(std::string_view now, const TextRevision& revision)
    : now_(now), size_(revision.previous_size) {
    if (revision.replaced) replaced_ = *revision.replaced;
    prefix_ = revision.same_prefix;
    suffix_ = revision.same_suffix;
}

bool EarlierText::consistent(std::string_view now, const TextRevision& revision) {
    return revision.replaced && revision.same_prefix + revision.same_suffix <= now.size() &&
           revision.same_prefix + revision.replaced->size() + revision.same_suffix == revision.previous_size;
}

template <typename Piece>
void EarlierText::pieces(std::size_t begin, std::size_t end, Piece&& piece) const {
    end = std::min(end, size_);
    const std::size_t middle_end = prefix_ + replaced_.size();
    if (begin < prefix_) piece(now_.substr(begin, std::min(end, prefix_) - begin));
    if (begin < middle_end && end > prefix_) {
        const std::size_t from = std::max(begin, prefix_), to = std::min(end, middle_end);
        piece(replaced_.substr(from - prefix_, to - from));
    }
    if (end > middle_end) {  // the suffix: the same bytes, at the end of the patched text
        const std::size_t from = std::max(begin, middle_end);
        piece(now_.substr(now_.size() - (size_ - from), end - from));
    }
}

bool EarlierText::equals(std::size_t begin, std::string_view other) const {
    if (begin > size_ || other.size() > size_ - begin) return false;
    bool same = true;
    std::size_t at = 0;
    pieces(begin, begin + other.size(), [&](std::string_view piece) {
        if (same && piece.size() > 0) same = std::memcmp(piece.data(), other.data() + at, piece.size()) == 0;
        at += piece.size();
    });
    return same && at == other.size();
}

std::string EarlierText::copy(std::size_t begin, std::size_t end) const {
    std::string out;
    if (begin >= end) return out;
    out.reserve(end - begin);
    pieces(begin, end, [&](std::string_view piece) { out.append(piece); });
    return out;
}

TextSince text_since(const std::string& path, std::string_view read, const FileOverlay* overlay) {
    TextSince out;
    const std::string* held = overlay ? overlay->find(path) : nullptr;
    // Another buffer (or the disk's file): the one read is alive and was never patched.
    if (!held || held->data() != read.data()) return out;
    const TextRevision* revision = overlay->revision(path);
    if (revision && revision->previous_data == read.data() && revision->previous_size == read.size() &&
        EarlierText::consistent(*held, *revision)) {
        out.state = TextSince::Fate::Patched;
        out.earlier.emplace(*held, *revision);
    } else if (revision || held->size() != read.size()) {
        out.state = TextSince::Fate::Unknown;
    }
    return out;
}

}  // namespace sphdeck::grammar
