#include "text/big_file_heap.hpp"

#include <atomic>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <mutex>

// SPHDECK_SANITIZED: the sanitizer builds (CMakeLists.txt), whose allocator is their own.
#if defined(__GLIBC__) && defined(__linux__) && !defined(SPHDECK_SANITIZED)
#include <malloc.h>
#include <sys/mman.h>
#define SPHDECK_BIG_FILE_HEAP 1
#endif

namespace sphdeck::text {

namespace {
std::atomic<bool> allowed{false};
#ifdef SPHDECK_BIG_FILE_HEAP
std::mutex growing;
std::size_t prepared = 0;  // the largest file the heap was grown for
// Whether the heap grew since the free pages were last handed back: once after each growth, not after
// every deck of a run (32 decks over one mesh faulted three times as many pages when each handed back).
bool give_back_pending = false;
#endif
}  // namespace

void allow_big_file_heap() { allowed = true; }

bool big_file_heap_supported() {
#ifdef SPHDECK_BIG_FILE_HEAP
    return true;
#else
    return false;
#endif
}

bool prepare_heap_for_file(std::size_t bytes) {
#ifdef SPHDECK_BIG_FILE_HEAP
    if (!allowed || bytes < big_file_bytes) return false;
    const std::lock_guard lock(growing);
    if (bytes <= prepared) return false;
    if (prepared == 0) {
        mallopt(M_MMAP_MAX, 0);              // every block from the heap, none unmapped when freed
        mallopt(M_TRIM_THRESHOLD, INT_MAX);  // the heap's free top kept: the next arrays' pages are there
        // One arena from now on: the threads of the parallel passes that follow allocate from the shaped heap
        // too (4 MiB less at the peak at 2 threads, 1M-particle deck). Not set for small decks, where the
        // threads of `--jobs` would wait on one another's allocations.
        mallopt(M_ARENA_MAX, 1);
    }
    prepared = bytes;
    give_back_pending = true;
    // One block from the top of the heap (sbrk, untouched but for its header), advised for huge pages over
    // its whole 2 MiB pages, and freed back to the top: the arrays that follow fault it in a huge page at a
    // time. The file's size and a quarter: what `check` holds at its peak is about the deck's size, and
    // the heap's first megabytes (the program's own tables) lie below the block.
    const std::size_t grown = bytes + bytes / 4;
    char* block = static_cast<char*>(std::malloc(grown));
    if (!block) return false;
    constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(block) + huge - 1) & ~(huge - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(block) + grown) & ~(huge - 1);
    if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: may fail
    std::free(block);
    return true;
#else
    (void)bytes;
    return false;
#endif
}

void give_back_free_heap() {
#ifdef SPHDECK_BIG_FILE_HEAP
    const std::lock_guard lock(growing);
    if (!give_back_pending) return;
    give_back_pending = false;
    malloc_trim(SIZE_MAX / 2);  // a pad larger than the top: the top is not cut, only the free chunks' pages
#endif
}

}  // namespace sphdeck::text
