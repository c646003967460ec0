// The colouring of a deck file by meaning (textDocument/semanticTokens): keyword names, comment and
// `$#` header lines, titles and text, each value by its kind (integer, real, id, enum, parameter
// reference), include file names. Values of every other field of a card carry the modifier
// `oddField`, so an editor can alternate the colour per field column and a value that slipped into
// the wrong columns shows at a glance.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "engine/position_index.hpp"
#include "lsp/checked_deck.hpp"

namespace sphdeck::lsp {

using engine::LineRange;  // the position index's range of lines

// The legend, in the order of the numbers sent (the server's capabilities announce it). "real" is
// sphdeck's own type (VS Code: superType number); the rest are LSP's standard names.
enum class TokenType : std::uint8_t { Keyword, Comment, String, Number, Real, Variable, EnumMember, Parameter };
inline constexpr std::array<std::string_view, 8> kTokenTypes = {"keyword", "comment",  "string",     "number",
                                                                "real",    "variable", "enumMember", "parameter"};
// Modifier bits: declaration (an id or parameter defined here), oddField (the 2nd, 4th... field of
// its card), header (a `$#` column-header comment), include (an include file name).
inline constexpr std::uint32_t kDeclaration = 1, kOddField = 2, kHeader = 4, kInclude = 8;
inline constexpr std::array<std::string_view, 4> kTokenModifiers = {"declaration", "oddField", "header", "include"};

struct SemanticToken {
    std::uint32_t line = 0;    // 1-based
    std::uint32_t column = 0;  // 1-based byte column
    std::uint32_t length = 0;  // bytes
    TokenType type = TokenType::Keyword;
    std::uint32_t modifiers = 0;
};

struct TokenOptions {
    // Values of blocks with more card lines than this are not coloured (0: all are); keyword
    // names, comments and includes always are.
    std::uint32_t max_block_lines = 0;
};

// The tokens of `file` on the lines of `range`, sorted and without overlaps.
std::vector<SemanticToken> semantic_tokens(const CheckedDeck& deck, grammar::FileId file, LineRange range,
                                           const TokenOptions& options = {});

}  // namespace sphdeck::lsp
