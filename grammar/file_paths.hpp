// The two names of a file path (issue 38): the canonical one every comparison uses, and the one people
// read. A deck reached through a symbolic link is the same deck as the one reached directly: the
// include cycle check, the file cache, the overlay of an editor's buffers, the fixes and the formatting
// tell files apart by the canonical path (grammar::SourceFile::key), never by the path as written.
#pragma once

#include <filesystem>

namespace sphdeck::grammar {

// Absolute, normalised, symbolic links resolved as far as the path exists (a buffer not yet saved has
// no file): two paths of one file give one canonical path.
std::filesystem::path canonical_path(const std::filesystem::path& path);

// `path` as people read it: `.` and doubled separators dropped, and `folder/..` folded away where that
// names the same file. After a symbolic link, `..` climbs out of the link's target, not out of the
// link (link/../x is not x), so a path that climbs after a link is named by its canonical path.
// Costs nothing (no system call) for a path without `..`.
std::filesystem::path normal_path(const std::filesystem::path& path);

}  // namespace sphdeck::grammar
