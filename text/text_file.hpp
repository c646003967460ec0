// Reading a deck file as bytes, and telling a deck from what is not one (a directory, a device, a
// named pipe, a socket, an empty or a binary file) with a plain message instead of a parse of garbage,
// an allocation of garbage size or a read that waits for ever.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace sphdeck::text {

// A regular file open for reading (after following symbolic links). Opening never blocks: the type is
// asked with stat() first, and the file is opened without waiting (O_NONBLOCK), then asked again on
// the open descriptor, so a named pipe swapped in between is refused too. Throws std::runtime_error
// with a plain message: "'PATH' is a named pipe, not a deck file", "cannot open 'PATH': ...".
class RegularFile {
public:
    explicit RegularFile(const std::string& path);
    RegularFile(const RegularFile&) = delete;
    RegularFile& operator=(const RegularFile&) = delete;
    ~RegularFile();
    int descriptor() const { return descriptor_; }
    std::size_t size() const { return size_; }  // when opened
    // Up to `bytes` bytes from the start (fewer when the file is shorter or shrank); throws on a read error.
    std::string read(std::size_t bytes) const;

private:
    std::string path_;
    int descriptor_ = -1;
    std::size_t size_ = 0;
};

// What `path` is when it exists but is no regular file ("a directory", "a named pipe", "a character
// device", "a block device", "a socket"), following links; nullopt for a regular file or no file.
std::optional<std::string> special_file_kind(const std::string& path);

// The whole file. Throws std::runtime_error with a plain message when `path` is not a regular file
// or cannot be opened or read.
std::string read_text_file(const std::string& path);

// The first `bytes` bytes of the file (all of it when shorter); throws like read_text_file.
std::string read_text_prefix(const std::string& path, std::size_t bytes);

// Why `text` (the start of a file) cannot be keyword text, or nullopt: "the file is empty",
// UTF-16 text, or binary data (a NUL byte). Any other byte passes: decks carry Latin-1 comments.
std::optional<std::string> binary_or_empty(std::string_view text);

}  // namespace sphdeck::text
