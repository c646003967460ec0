// How a pass over `count` items is cut among threads by hand (inside one parallel region): thread t
// of `threads` takes one equal run, in order.
#pragma once

#include <cstddef>
#include <utility>

namespace sphdeck::preproc {

// Thread t's share [begin, end) of `count` items cut in `threads` equal runs.
inline std::pair<std::size_t, std::size_t> share_of(std::size_t count, int t, int threads) {
    return {count * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads),
            count * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads)};
}

}  // namespace sphdeck::preproc
