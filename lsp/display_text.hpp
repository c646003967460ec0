// Deck text shown to the editor (titles, headings, values in hovers and outlines) as valid UTF-8:
// decks are often Latin-1, and JSON text must be UTF-8. Well-formed UTF-8 passes unchanged; any
// other byte is taken as Latin-1 (so "d\xE9p\xF4t" shows as "dépôt").
#pragma once

#include <string>
#include <string_view>

namespace sphdeck::lsp {

std::string display_text(std::string_view text);

}  // namespace sphdeck::lsp
