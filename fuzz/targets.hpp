// The fuzz targets' bodies, shared by the libFuzzer executables (fuzz_*.cpp) and by the test
// that replays the corpus of found inputs (tests/test_fuzz_corpus.cpp). Each takes any bytes and
// must return without crashing, hanging or allocating more than the input warrants.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace sphdeck::fuzz {

// An LS-DYNA deck through the whole check (read, decode, every rule, suppressions), then every
// renderer over the findings.
void check_dyna_deck(const std::uint8_t* data, std::size_t size);
// The same for an OpenRadioss starter deck.
void check_radioss_deck(const std::uint8_t* data, std::size_t size);
// An LS-DYNA deck read and decoded into the model (the reader's and the decoder's findings), no rule and
// no renderer: the shallow target, fast enough for the 1e7 executions a deck target should see.
void read_dyna_deck(const std::uint8_t* data, std::size_t size);
// The same for an OpenRadioss starter deck.
void read_radioss_deck(const std::uint8_t* data, std::size_t size);
// The text after *KEYWORD (memory sizes, long=, i10=, ...).
void parse_keyword_arguments(const std::uint8_t* data, std::size_t size);
// A *PARAMETER_EXPRESSION expression, with a few parameters defined.
void evaluate_expression(const std::uint8_t* data, std::size_t size);

// `sphdeck format` on an LS-DYNA deck (issue 27): the formatted text reads the same values as the input
// (engine::diff_decks finds nothing) and formatting it again changes nothing; a breach traps. The first
// input byte picks the options (--headers, --to fixed).
void format_dyna_deck(const std::uint8_t* data, std::size_t size);

// LSP messages (headers and JSON bodies) through the editor server's reader, to the end of the input.
void read_lsp_messages(const std::uint8_t* data, std::size_t size);

// A target by its name (the executable's name without "fuzz_"); nullptr when unknown.
using Target = void (*)(const std::uint8_t*, std::size_t);
Target find_target(std::string_view name);

}  // namespace sphdeck::fuzz
