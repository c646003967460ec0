#include "text/source_text.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

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
    int descriptor = -1;  // the file, open for copy_bytes (pread)
    ~Mapping() {
#ifdef SPHDECK_HAS_MMAP
        if (address) ::munmap(address, size);
        if (descriptor >= 0) ::close(descriptor);
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
            mapping->descriptor = ::fcntl(file.descriptor(), F_DUPFD_CLOEXEC, 0);  // -1: copy_bytes reads the mapping
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

void SourceText::copy_bytes(std::size_t begin, std::size_t n, char* out) const {
    const std::string_view text = view();
    begin = std::min(begin, text.size());
    n = std::min(n, text.size() - begin);
#ifdef SPHDECK_HAS_MMAP
    if (mapping_ && mapping_->descriptor >= 0) {
        std::size_t done = 0;
        while (done < n) {
            const ssize_t got = ::pread(mapping_->descriptor, out + done, n - done, static_cast<off_t>(begin + done));
            if (got > 0) {
                done += static_cast<std::size_t>(got);
            } else if (got == 0 || errno != EINTR) {
                break;  // the file shrank, or a read error: the rest from the mapping, as the readers see it
            }
        }
        begin += done, out += done, n -= done;
    }
#endif
    if (n > 0) std::memcpy(out, text.data() + begin, n);
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
