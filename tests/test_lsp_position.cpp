// URIs and UTF-16 positions of the editor server (lsp/uri.*, lsp/text_position.*).
#include <doctest/doctest.h>

#include "lsp/text_position.hpp"
#include "lsp/uri.hpp"

namespace test_lsp_position_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

TEST_CASE("lsp uri: file URIs and paths, percent-encoded both ways") {
    CHECK(lsp::path_from_uri("file:///work/a%20b.k") == std::filesystem::path("/work/a b.k"));
    CHECK(lsp::path_from_uri("file://localhost/tmp/x.k") == std::filesystem::path("/tmp/x.k"));
    CHECK(lsp::path_from_uri("FILE:///tmp/x.k") == std::filesystem::path("/tmp/x.k"));
    CHECK(lsp::path_from_uri("untitled:Untitled-1").empty());
    CHECK(lsp::path_from_uri("file://server/share/x.k").empty());
    CHECK(lsp::path_from_uri("file:///tmp/bad%2").empty());
    CHECK(lsp::path_from_uri("file:///tmp/bad%zz").empty());
    CHECK(lsp::uri_from_path("/work/a b#1.k") == "file:///work/a%20b%231.k");
    CHECK(lsp::path_from_uri(lsp::uri_from_path("/tmp/d\xC3\xA9k.k")) == std::filesystem::path("/tmp/d\xC3\xA9k.k"));
}

TEST_CASE("lsp positions: UTF-16 units against bytes") {
    const std::string_view ascii = "*PART";
    CHECK(lsp::utf16_offset(ascii, 3) == 3);
    CHECK(lsp::byte_offset(ascii, 3) == 3);
    CHECK(lsp::byte_offset(ascii, 99) == 5);
    const std::string_view accented = "$ d\xC3\xA9p\xF0\x9F\x98\x80x";  // "$ dép😀x": é 2 bytes, emoji 4 bytes
    CHECK(lsp::utf16_offset(accented, 5) == 4);                         // after "é"
    CHECK(lsp::utf16_offset(accented, 10) == 7);                        // after the emoji: a surrogate pair
    CHECK(lsp::byte_offset(accented, 7) == 10);
    CHECK(lsp::byte_offset(accented, 4) == 5);
    const std::string_view latin1 = "a\xE9z";  // not UTF-8: one unit per byte
    CHECK(lsp::utf16_offset(latin1, 3) == 3);
    CHECK(lsp::byte_offset(latin1, 2) == 2);
}

TEST_CASE("lsp positions: parse_position refuses what is not a position") {
    lsp::TextPosition p;
    CHECK(lsp::parse_position(nlohmann::json{{"line", 3}, {"character", 4}}, p));
    CHECK(p.line == 3);
    CHECK(p.character == 4);
    CHECK_FALSE(lsp::parse_position(nlohmann::json{{"line", -1}, {"character", 4}}, p));
    CHECK_FALSE(lsp::parse_position(nlohmann::json{{"line", "3"}, {"character", 4}}, p));
    CHECK_FALSE(lsp::parse_position(nlohmann::json::array(), p));
}
}  // namespace test_lsp_position_cpp
