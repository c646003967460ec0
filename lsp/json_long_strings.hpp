// A didOpen carries the whole document as one JSON string (100 MB for a 1M-particle deck), and
// nlohmann-json's lexer reads strings at about 70 MB/s: a big deck's open spent more time in the
// JSON than in its check. The long strings of a body are taken out by a fast scan (memchr for
// quotes and backslashes), decoded and checked here, and nlohmann-json parses the small rest.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphdeck::lsp {

struct LiftedStrings {
    std::string rest;                  // the body with each long string value replaced by a placeholder
    std::vector<std::string> strings;  // the long strings, decoded, in the body's order
};

// The body's string values of at least `min_length` bytes lifted out (object keys stay). nullopt when
// there is none, or when one holds what this decoder leaves to nlohmann-json (a \u escape) or what
// JSON forbids (a control character, bytes that are not UTF-8, an unknown escape, no closing quote):
// then the body is parsed whole, as before. Lifting never changes whether a body is JSON: a string
// token is replaced by a string token.
std::optional<LiftedStrings> lift_long_strings(std::string_view body, std::size_t min_length = 65536);

// The same in two steps, for a body its reader gives up (a didOpen of 100 MB): the long strings are
// found and checked first (`rest` as in LiftedStrings; `ranges`: each string's bytes between its quotes
// in the body), and decoded only once `rest` was parsed, the longest into the body's own buffer, so the
// document is never held twice.
struct LongStrings {
    std::string rest;
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
};
std::optional<LongStrings> find_long_strings(std::string_view body, std::size_t min_length = 65536);
// Whether `rest` holds no \u escape but the placeholders': then no other string of the body parses to
// what starts a placeholder (a NUL is written \u0000 in JSON), and restoring cannot fail after the
// body is gone but where an object repeats a key (its last value wins, as in a whole parse).
bool only_placeholders_escape_u(const LongStrings& found);
// The strings of `found` decoded in body order; the longest takes `body`'s buffer (`body` is left empty).
std::vector<std::string> take_long_strings(std::string& body, const LongStrings& found);

// Puts the lifted strings back where their placeholders were parsed; false when a placeholder is
// missing or repeated (then parse the body whole).
bool restore_long_strings(nlohmann::json& parsed, std::vector<std::string>& strings);

}  // namespace sphdeck::lsp
