// Handing the pages of a range of memory back to the system (madvise MADV_DONTNEED), where there is
// one: the whole pages inside [begin, begin + size) only, never a page the range shares with bytes
// outside it. A mapped file's pages are read again when next touched; anonymous memory reads as zeros.
#pragma once

#include <cstddef>

namespace sphdeck::text {

void release_whole_pages(const char* begin, std::size_t size);

}  // namespace sphdeck::text
