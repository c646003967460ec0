// The text of an included (or main) file as the readers take it: from the editor's overlay when it holds
// the file, else from the run's file cache when there is one, else from disk (grammar/dyna/reader.cpp).
#pragma once

#include <memory>
#include <string>

#include "grammar/file_cache.hpp"
#include "grammar/file_overlay.hpp"

namespace sphdeck::grammar::dyna {

// `cached`, when given, receives the cache's entry for the file (null when the overlay held it).
SourceText read_include_text(const std::string& path, const FileOverlay* overlay = nullptr, FileCache* cache = nullptr,
                             std::shared_ptr<const FileCache::File>* cached = nullptr);

}  // namespace sphdeck::grammar::dyna
