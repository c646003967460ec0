#include "text/page_release.hpp"

#include <cstdint>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#include <unistd.h>
#define SPHDECK_HAS_MADVISE 1
#endif

namespace sphdeck::text {

void release_whole_pages(const char* begin, std::size_t size) {
#ifdef SPHDECK_HAS_MADVISE
    static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto start = reinterpret_cast<std::uintptr_t>(begin);
    const std::uintptr_t first = (start + page - 1) / page * page;
    const std::uintptr_t last = (start + size) / page * page;
    if (first < last) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
    (void)begin, (void)size;
#endif
}

}  // namespace sphdeck::text
