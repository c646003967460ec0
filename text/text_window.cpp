#include "text/text_window.hpp"

#include <algorithm>

namespace sphdeck::text {

std::string_view TextWindow::read(std::size_t begin, std::size_t least, std::size_t most) {
    const std::size_t size = text_.size();
    begin = std::min(begin, size);
    least = std::min(least, size - begin);
    if (!text_.mapped()) {
        end_ = text_.data() + size;
        return text_.view().substr(begin);
    }
    if (begin < begin_ || begin + least > begin_ + held_) {  // not held: read from `begin` on
        const std::size_t n = std::min(std::max(least, std::min(bytes_, most)), size - begin);
        if (n > capacity_) buffer_ = std::make_unique_for_overwrite<char[]>(n), capacity_ = n;
        text_.copy_bytes(begin, n, buffer_.get());
        begin_ = begin, held_ = n;
        end_ = begin + n == size ? buffer_.get() + n : nullptr;
    }
    return {buffer_.get() + (begin - begin_), held_ - (begin - begin_)};
}

}  // namespace sphdeck::text
