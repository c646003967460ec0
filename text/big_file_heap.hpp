// malloc's heap made ready for the model of a big deck (issue 40), in the programs that ask for it.
//
// A check of a 100 MB deck allocates and frees some 100 MB of arrays (bulk columns, search grids,
// results). With glibc's defaults each array of more than 128 KiB is a fresh mmap, freed by munmap, and
// every 4 KiB page of it is faulted in and zeroed by the kernel on first touch: 30,000 faults, a quarter
// of `check`'s time on the project's VM. Once a program has called allow_big_file_heap(), reading a file
// of at least big_file_bytes (SourceText::read) makes malloc keep its arrays in the heap (M_MMAP_MAX 0),
// never hand freed memory back (M_TRIM_THRESHOLD), so that a freed array's pages serve the next one
// unfaulted, use one arena, and grows the heap by the file's size and a quarter at once, advised for
// transparent huge pages (a fault a 2 MiB page: Debian's kernels give them on madvise only). Untouched,
// that space costs no memory. The engine hands the free pages inside it back once the model is built.
//
// For a process that runs one job and ends (the command line's batch commands): a long-lived one (the
// editor server, the Python module) keeps the defaults. Nothing happens under the sanitizers (their own
// allocator) or without glibc.
#pragma once

#include <cstddef>

namespace sphdeck::text {

// Files from this size on prepare the heap.
inline constexpr std::size_t big_file_bytes = std::size_t{16} << 20;

// The program's opt-in, before it reads a deck.
void allow_big_file_heap();

// Whether this build can shape the heap (glibc on Linux, no sanitizer).
bool big_file_heap_supported();

// Called with the size of each file read; once allowed, prepares the heap for the largest file so far.
// True when it grew the heap for this one.
bool prepare_heap_for_file(std::size_t bytes);

// The free pages inside a shaped heap handed back (malloc_trim; its top, grown for huge pages, kept):
// what the reading used and freed (the line tables of its chunks, the decoders' scratch) lies in holes the
// model's arrays do not fill, and would stay beside the searches' grids at the peak of memory. Once after
// each growth of the heap (the next decks of a run reuse those pages); nothing when it was not shaped.
void give_back_free_heap();

}  // namespace sphdeck::text
