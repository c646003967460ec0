// The heap shaped for a big deck (text/big_file_heap.hpp, issue 40): nothing before the program allows it
// or for a small file; after it, an array freed and allocated again finds its pages already there (no
// page faults), which is what saves `check` a quarter of its time on a 100 MB deck; and the free pages inside
// the heap are handed back on request.
#include <doctest/doctest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <memory>

#include "text/big_file_heap.hpp"

namespace test_big_file_heap_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

long minor_faults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// Allocates `bytes`, writes every byte, frees them; the minor page faults it took.
long faults_of_touching(std::size_t bytes) {
    const long before = minor_faults();
    {
        const std::unique_ptr<char[]> block(new char[bytes]);
        std::memset(block.get(), 1, bytes);
        // Read back, so that the writes are not dropped as dead.
        REQUIRE(block[bytes - 1] == 1);
    }
    return minor_faults() - before;
}

// Resident bytes of this process (/proc/self/statm's second field, in pages).
long resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    statm >> size >> resident;
    return resident * sysconf(_SC_PAGESIZE);
}

}  // namespace

TEST_CASE("the heap is shaped for big files only once the program allows it") {
    constexpr std::size_t bytes = std::size_t{48} << 20;
    CHECK_FALSE(text::prepare_heap_for_file(bytes));  // not allowed yet (the library's default)
    text::allow_big_file_heap();
    CHECK_FALSE(text::prepare_heap_for_file(text::big_file_bytes - 1));  // a small file
    if (!text::big_file_heap_supported()) {                              // sanitizers or no glibc: the defaults stay
        CHECK_FALSE(text::prepare_heap_for_file(bytes));
        return;
    }
    CHECK(text::prepare_heap_for_file(bytes));
    CHECK_FALSE(text::prepare_heap_for_file(bytes));  // grown for this size already

    // A freed array's pages serve the next one: touching 48 MiB a second time takes (almost) no fault,
    // where a fresh mapping of 4 KiB pages takes 12,288.
    faults_of_touching(bytes);
    const long again = faults_of_touching(bytes);
    CHECK(again < 200);

    // A freed block inside the heap (one still in use above it) stays resident until the free pages are
    // handed back; the heap's top is kept.
    auto hole = std::make_unique<char[]>(bytes);
    std::memset(hole.get(), 1, bytes);
    // As large as the hole, so that no small free chunk lower in the heap serves it: it lies above the hole.
    const auto above = std::make_unique<char[]>(bytes);
    std::memset(above.get(), 1, bytes);
    hole.reset();
    const long before = resident_bytes();
    text::give_back_free_heap();
    CHECK(before - resident_bytes() > static_cast<long>(bytes) / 2);
}

}  // namespace test_big_file_heap_cpp
