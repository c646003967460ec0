#include "lsp/checked_deck.hpp"

#include "engine/documents.hpp"

namespace sphdeck::lsp {

std::optional<grammar::FileId> file_of(const CheckedDeck& deck, const std::filesystem::path& path) {
    const auto wanted = engine::Documents::key(path);
    const auto& sources = deck.result.deck.sources;
    for (grammar::FileId id = 0; id < sources.size(); ++id)
        if (engine::Documents::key(sources.file(id).path) == wanted) return id;
    return std::nullopt;
}

}  // namespace sphdeck::lsp
