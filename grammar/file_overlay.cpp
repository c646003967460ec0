#include "grammar/file_overlay.hpp"

#include <system_error>

#include "grammar/file_paths.hpp"
#include "text/text_file.hpp"

namespace sphdeck::grammar {
namespace fs = std::filesystem;

fs::path FileOverlay::key(const fs::path& path) { return canonical_path(path); }

void FileOverlay::set(const fs::path& path, std::string text) {
    set_shared(path, std::make_shared<const std::string>(std::move(text)));
}

void FileOverlay::set_shared(const fs::path& path, std::shared_ptr<const std::string> text,
                             const std::optional<TextRevision>& revision) {
    const fs::path k = key(path);
    texts_[k] = text ? std::move(text) : std::make_shared<const std::string>();
    if (revision)
        revisions_[k] = *revision;
    else
        revisions_.erase(k);
}

void FileOverlay::erase(const fs::path& path) {
    const fs::path k = key(path);
    texts_.erase(k);
    revisions_.erase(k);
}

const TextRevision* FileOverlay::revision(const fs::path& path) const {
    if (revisions_.empty()) return nullptr;
    auto it = revisions_.find(key(path));
    return it == revisions_.end() ? nullptr : &it->second;
}

const std::string* FileOverlay::find(const fs::path& path) const {
    if (texts_.empty()) return nullptr;  // the common case (the command line) pays nothing
    auto it = texts_.find(key(path));
    return it == texts_.end() ? nullptr : it->second.get();
}

std::shared_ptr<const std::string> FileOverlay::find_shared(const fs::path& path) const {
    if (texts_.empty()) return nullptr;
    auto it = texts_.find(key(path));
    return it == texts_.end() ? nullptr : it->second;
}

bool is_regular_file(const fs::path& path, const FileOverlay* overlay) {
    if (overlay && overlay->find(path)) return true;
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

bool file_exists(const fs::path& path, const FileOverlay* overlay) {
    if (overlay && overlay->find(path)) return true;
    std::error_code ec;
    return fs::exists(path, ec);
}

std::string read_file_text(const std::string& path, const FileOverlay* overlay) {
    if (const std::string* text = overlay ? overlay->find(path) : nullptr) return *text;
    return text::read_text_file(path);
}

SourceText read_source_text(const std::string& path, const FileOverlay* overlay) {
    if (auto text = overlay ? overlay->find_shared(path) : nullptr) return SourceText(std::move(text));
    return SourceText::read(path);
}

std::string read_file_prefix(const std::string& path, std::size_t bytes, const FileOverlay* overlay) {
    if (const std::string* text = overlay ? overlay->find(path) : nullptr) return text->substr(0, bytes);
    return text::read_text_prefix(path, bytes);
}

}  // namespace sphdeck::grammar
