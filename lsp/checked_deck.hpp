// A deck as the editor server last checked it: what every request (hover, definition, completion,
// outline, code actions) reads. The server re-checks a deck when one of its files changes, so the
// texts in `result.deck.sources` are the editor's buffers at that moment.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "engine/check.hpp"
#include "text/source_map.hpp"

namespace sphdeck::lsp {

struct CheckedDeck {
    std::filesystem::path main;  // the deck's main file, keyed like engine::Documents::key
    engine::CheckResult result;  // raw deck, model, findings, include graph
};

// The first file instance of the deck read from `path` (compared by engine::Documents::key), or
// nullopt when the deck did not read it.
std::optional<grammar::FileId> file_of(const CheckedDeck& deck, const std::filesystem::path& path);

}  // namespace sphdeck::lsp
