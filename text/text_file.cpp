#include "text/text_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace sphdeck::text {
namespace {

// What a file of type `mode` is when it is no regular file, for the message; nullptr for a regular one.
const char* kind_of(mode_t mode) {
    if (S_ISREG(mode)) return nullptr;
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a named pipe";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

[[noreturn]] void refuse(const std::string& path, const char* kind) {
    throw std::runtime_error("'" + path + "' is " + kind + ", not a deck file");
}

}  // namespace

std::optional<std::string> special_file_kind(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return std::nullopt;
    if (const char* kind = kind_of(st.st_mode)) return kind;
    return std::nullopt;
}

RegularFile::RegularFile(const std::string& path) : path_(path) {
    // Asked before opening: opening a named pipe for reading waits for a writer, a socket cannot be
    // opened at all, and a device (/dev/zero) reads for ever.
    if (auto kind = special_file_kind(path)) refuse(path, kind->c_str());
    descriptor_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (descriptor_ < 0) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
    struct stat st {};
    if (::fstat(descriptor_, &st) != 0) {
        const int error = errno;
        ::close(descriptor_);
        throw std::runtime_error("cannot read '" + path + "': " + std::strerror(error));
    }
    if (const char* kind = kind_of(st.st_mode)) {  // swapped in after the stat() above
        ::close(descriptor_);
        refuse(path, kind);
    }
    size_ = static_cast<std::size_t>(st.st_size);
}

RegularFile::~RegularFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
}

std::string RegularFile::read(std::size_t bytes) const {
    std::string text(bytes, '\0');
    std::size_t done = 0;
    while (done < bytes) {
        const ssize_t got = ::pread(descriptor_, text.data() + done, bytes - done, static_cast<off_t>(done));
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw std::runtime_error("cannot read '" + path_ + "': " + std::strerror(errno));
        if (got == 0) break;  // the file is shorter than asked (or shrank since it was opened)
        done += static_cast<std::size_t>(got);
    }
    text.resize(done);
    return text;
}

std::string read_text_file(const std::string& path) {
    const RegularFile file(path);
    return file.read(file.size());
}

std::string read_text_prefix(const std::string& path, std::size_t bytes) {
    const RegularFile file(path);
    return file.read(std::min(bytes, file.size()));
}

std::optional<std::string> binary_or_empty(std::string_view text) {
    if (text.empty()) return "the file is empty";
    if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF")
        return "it is UTF-16 text; save it as ASCII or UTF-8";
    // Text never holds a NUL byte; binary files (d3plot, .zip, an all-NUL file) almost always do.
    if (std::size_t nul = text.find('\0'); nul != std::string_view::npos)
        return "it holds binary data (a NUL byte at offset " + std::to_string(nul) + ")";
    return std::nullopt;
}

}  // namespace sphdeck::text
