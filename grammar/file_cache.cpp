#include "grammar/file_cache.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <functional>
#include <string_view>
#include <system_error>

#include "grammar/file_overlay.hpp"

namespace sphdeck::grammar {
namespace fs = std::filesystem;
namespace {

bool starts_with_upper(std::string_view text, std::string_view upper) {
    if (text.size() < upper.size()) return false;
    for (std::size_t i = 0; i < upper.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(text[i])) != upper[i]) return false;
    return true;
}

// Whether a '*' in `slice` starts a keyword the reader acts on while reading (an include, a
// parameter, *KEYWORD's arguments): then the file's reading depends on the deck around it. Any
// such word after any '*' counts, in comments too: a false "no" only costs the sharing.
bool names_reader_keyword(std::string_view slice) {
    for (std::size_t at = 0; (at = slice.find('*', at)) != std::string_view::npos; ++at) {
        const std::string_view after = slice.substr(at + 1);
        for (std::string_view word : {"INCLUDE", "PARAMETER", "KEYWORD", "RVE"})
            if (starts_with_upper(after, word)) return true;
    }
    return false;
}

// The content hash and whether the file is self-contained, in one pass of 1 MiB slices handed back
// behind it (a mapped 1 GB include is not made resident by its hashing).
void describe(FileCache::File& file) {
    const std::string_view text = file.text.view();
    constexpr std::size_t slice = std::size_t{1} << 20;
    constexpr std::size_t word = 16;  // "*PARAMETER" and the others fit: slices overlap by this much
    std::uint64_t hash = text.size();
    bool names = false;
    for (std::size_t at = 0; at < text.size(); at += slice) {
        const std::string_view part = text.substr(at, slice);
        const std::uint64_t h = std::hash<std::string_view>{}(part);
        hash ^= h + 0x9e3779b97f4a7c15ULL + (hash << 6) + (hash >> 2);
        if (!names) names = names_reader_keyword(text.substr(at, slice + word));
        file.text.release(at, at + slice);
    }
    file.hash = hash;
    file.self_contained = !names;
}

}  // namespace

std::shared_ptr<const FileCache::File> FileCache::file(const std::string& path) {
    std::error_code ec;
    const fs::path key = FileOverlay::key(path);
    const std::uintmax_t size = fs::file_size(key, ec);
    const fs::file_time_type modified = ec ? fs::file_time_type{} : fs::last_write_time(key, ec);
    const bool known = !ec;  // a file the system cannot describe is read each time
    if (known) {
        std::lock_guard lock(mutex_);
        auto it = files_.find(key);
        if (it != files_.end() && it->second.size == size && it->second.modified == modified) {
            ++counters_.files_shared;
            return it->second.file;
        }
    }
    auto file = std::make_shared<File>();
    file->text = SourceText::read(path);
    describe(*file);
    std::lock_guard lock(mutex_);
    ++counters_.files_read;
    // The size read must be the size seen: a file that changed while being read is not kept.
    if (!known || file->text.size() != size) return file;
    auto [it, added] = files_.try_emplace(key, Version{size, modified, file});
    // Another thread read the same version meanwhile: give its copy, so that both decks hold one text.
    if (!added && it->second.size == size && it->second.modified == modified) return it->second.file;
    it->second = Version{size, modified, file};
    return file;
}

FileCache::Lookup FileCache::reading(const File& file, CardFormat format) {
    Lookup out;
    if (!file.self_contained) return out;
    std::shared_future<std::shared_ptr<const FileReading>> made;
    {
        std::lock_guard lock(mutex_);
        const ReadingKey key{file.hash, file.text.size(), format};
        auto it = readings_.find(key);
        if (it == readings_.end()) {
            out.claim = std::make_unique<Claim>();
            readings_.emplace(key, out.claim->promise_.get_future().share());
            ++counters_.readings_made;
            return out;
        }
        made = it->second;
    }
    std::shared_ptr<const FileReading> reading = made.get();  // waits while another thread reads it
    if (!reading) return out;
    // The same hash and size: the same bytes, unless both are one text already.
    const std::string_view a = reading->text.view(), b = file.text.view();
    if (a.data() != b.data() && (a.size() != b.size() || std::memcmp(a.data(), b.data(), a.size()) != 0)) return out;
    std::lock_guard lock(mutex_);
    ++counters_.readings_shared;
    out.reading = std::move(reading);
    return out;
}

FileCache::Counters FileCache::counters() const {
    std::lock_guard lock(mutex_);
    return counters_;
}

FileCache::Claim::~Claim() {
    if (!done_) promise_.set_value(nullptr);
}

void FileCache::Claim::fulfil(FileReading reading) {
    if (done_) return;
    done_ = true;
    promise_.set_value(std::make_shared<const FileReading>(std::move(reading)));
}

}  // namespace sphdeck::grammar
