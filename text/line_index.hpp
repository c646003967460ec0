// Where each line of a text starts and where its content ends (before "\n" or "\r\n").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace sphdeck::text {

class LineIndex {
public:
    explicit LineIndex(std::string_view text) : text_(text) {
        starts_.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') starts_.push_back(i + 1);
    }
    // Lines counted as an editor does: a text ending in "\n" has an empty last line.
    std::uint32_t count() const { return static_cast<std::uint32_t>(starts_.size()); }
    std::size_t begin(std::uint32_t line) const { return starts_[line - 1]; }
    // One past the line's last byte, line break included (the next line's start, or the text's end).
    std::size_t end(std::uint32_t line) const { return line < count() ? starts_[line] : text_.size(); }
    std::size_t content_end(std::uint32_t line) const {
        std::size_t e = line < count() ? starts_[line] - 1 : text_.size();
        if (e > begin(line) && text_[e - 1] == '\r') --e;
        return e;
    }
    // The line holding byte `offset` (1-based).
    std::uint32_t line_of(std::size_t offset) const;

private:
    std::string_view text_;
    std::vector<std::size_t> starts_;
};

inline std::uint32_t LineIndex::line_of(std::size_t offset) const {
    std::size_t lo = 0, hi = starts_.size();
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (starts_[mid] <= offset ? lo : hi) = mid;
    }
    return static_cast<std::uint32_t>(lo + 1);
}

}  // namespace sphdeck::text
