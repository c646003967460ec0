#include "text/source_text.hpp"

#include <algorithm>

#include "text/big_file_heap.hpp"
#include "text/page_release.hpp"
#include "text/text_file.hpp"

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define SPHDECK_HAS_MMAP 1
#endif

namespace sphdeck::text {

struct SourceText::Mapping {
    void* address = nullptr;
    std::size_t size = 0;
    ~Mapping() {
#ifdef SPHDECK_HAS_MMAP
        if (address) ::munmap(address, size);
#endif
    }
};

SourceText SourceText::read(const std::string& path, std::size_t min_bytes) {
    const RegularFile file(path);        // a directory, a device, a pipe or a socket is refused here
    prepare_heap_for_file(file.size());  // a big deck's model follows (does nothing unless the program allowed it)
#ifdef SPHDECK_HAS_MMAP
    // Small files are read whole: a deck with thousands of small includes must not use thousands of
    // mappings.
    if (file.size() >= min_bytes && file.size() > 0) {
        void* address = ::mmap(nullptr, file.size(), PROT_READ, MAP_PRIVATE, file.descriptor(), 0);
        if (address != MAP_FAILED) {
            ::madvise(address, file.size(), MADV_SEQUENTIAL);  // read ahead: the readers walk it front to back
            auto mapping = std::make_shared<Mapping>();
            mapping->address = address, mapping->size = file.size();
            SourceText text;
            text.view_ = static_cast<const char*>(address);
            text.size_ = file.size();
            text.mapping_ = std::move(mapping);
            return text;
        }
    }
#else
    (void)min_bytes;
#endif
    return SourceText(file.read(file.size()));
}

void SourceText::release(std::size_t begin, std::size_t end) const {
#ifdef SPHDECK_HAS_MMAP
    if (!mapping_) return;
    end = std::min(end, size_);
    if (begin < end) release_whole_pages(view_ + begin, end - begin);
#else
    (void)begin, (void)end;
#endif
}

bool SourceText::contains(std::string_view needle) const {
    const std::string_view text = view();
    if (!mapping_ || needle.empty()) return text.find(needle) != std::string_view::npos;
    // 1 MiB slices: this runs after the model is built (suppressions), at the peak of memory of a
    // check without geometry, where 8 MiB of deck text resident showed in the peak RSS.
    constexpr std::size_t slice = std::size_t{1} << 20;
    for (std::size_t at = 0; at < text.size(); at += slice) {
        // Each slice reaches needle.size() - 1 bytes into the next, so no occurrence is cut.
        const std::size_t length = std::min(text.size() - at, slice + needle.size() - 1);
        const bool found = text.substr(at, length).find(needle) != std::string_view::npos;
        release(at, at + slice);
        if (found) return true;
    }
    return false;
}

}  // namespace sphdeck::text
