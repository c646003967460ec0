// lsp/json_long_strings: a body's long strings (a didOpen's document) decoded apart from the rest
// give exactly what nlohmann-json gives for the whole body, and are refused exactly when it refuses.
#include <doctest/doctest.h>

#include <random>
#include <string>

#include "lsp/json_long_strings.hpp"
#include "lsp/json_rpc.hpp"

namespace test_json_long_strings_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {
std::optional<nlohmann::json> reference(const std::string& body) {
    nlohmann::json parsed = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
    if (parsed.is_discarded()) return std::nullopt;
    return parsed;
}

std::string did_open(const std::string& escaped_text) {
    return R"({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///d.k",)"
           R"("languageId":"lsdyna","version":1,"text":")" +
           escaped_text + R"("}}})";
}

std::string repeated(std::string_view piece, std::size_t bytes) {
    std::string out;
    while (out.size() < bytes) out += piece;
    return out;
}
}  // namespace

TEST_CASE("json long strings: a document's text is lifted, decoded and put back") {
    const std::string escaped = repeated(R"(       1 -4.94938015e-02 \"q\" \\ a\/b\ttab caf)"
                                         "\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"
                                         R"(\r\n)",
                                         200000);
    const std::string body = did_open(escaped);
    const auto lifted = lsp::lift_long_strings(body);
    REQUIRE(lifted);
    CHECK(lifted->strings.size() == 1);
    CHECK(lifted->rest.size() < 400);
    const auto parsed = lsp::parse_body(body);
    REQUIRE(parsed);
    CHECK(*parsed == *reference(body));
}

TEST_CASE("json long strings: what the fast scan leaves to nlohmann-json, and what JSON forbids") {
    const std::string lines = repeated("       1 -4.94938015e-02\\n", 100000);
    // A \u escape: parsed whole, the same answer.
    std::string body = did_open(lines + "caf\\u00e9 \\ud83d\\ude00");
    CHECK_FALSE(lsp::lift_long_strings(body));
    REQUIRE(lsp::parse_body(body));
    CHECK(*lsp::parse_body(body) == *reference(body));
    // Refused by both: a raw control character, bytes that are not UTF-8, a bad escape, an open string,
    // a lone surrogate, an overlong encoding, a surrogate encoded in UTF-8.
    for (const std::string& bad :
         {std::string("a\tb"), std::string("\xC3"), std::string("\\x"), std::string("\xE0\x80\x80"),
          std::string("\xED\xA0\x80"), std::string("\\ud800"), std::string("\xF5\x80\x80\x80")}) {
        CAPTURE(bad);
        body = did_open(lines + bad);
        CHECK_FALSE(reference(body));
        CHECK_FALSE(lsp::parse_body(body));
    }
    body = did_open(lines);
    body.resize(body.size() - 4);  // no closing quote
    CHECK_FALSE(lsp::parse_body(body));
    // Invalid around the string: still refused.
    body = did_open(lines) + ",";
    CHECK_FALSE(lsp::parse_body(body));
    // A long key stays a key.
    body = "{\"" + lines + "\":1}";
    REQUIRE(lsp::parse_body(body));
    CHECK(*lsp::parse_body(body) == *reference(body));
    // Several long strings (a didChange with two whole texts), and short ones that look like them.
    body = R"({"a":[")" + lines + R"(","x",")" + lines + R"("],"b":"\u0000sphdeck-long-string:0"})";
    REQUIRE(lsp::parse_body(body));
    CHECK(*lsp::parse_body(body) == *reference(body));
}

TEST_CASE("json long strings: random texts give nlohmann-json's answer") {
    std::mt19937 random(29);
    const std::vector<std::string> pieces = {
        "a",       " ",   "1.0e-3", "\\n",  "\\r\\n",   "\\t",          "\\\"",
        "\\\\",    "\\/", "\\b",    "\\f",  "\xC3\xA9", "\xE2\x82\xAC", "\xF0\x9F\x98\x80",
        "\\u0041", "\"",  "\\",     "\x01", "\xC3",     "\xFF",         "{",
        "}",       "[",   ":",      ","};
    for (int round = 0; round < 200; ++round) {
        std::string text = repeated("*NODE\\n", 11000);
        const int extra = std::uniform_int_distribution<int>(0, 3)(random);
        for (int i = 0; i < extra; ++i) {
            const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size())(random);
            text.insert(at, pieces[std::uniform_int_distribution<std::size_t>(0, pieces.size() - 1)(random)]);
        }
        const std::string body = did_open(text);
        CAPTURE(round);
        const auto expected = reference(body);
        const auto got = lsp::parse_body(body);
        REQUIRE(got.has_value() == expected.has_value());
        if (got) CHECK(*got == *expected);
        std::string taken = body;  // the server's way: the text takes the body's buffer
        const auto got_taking = lsp::parse_body_taking(taken);
        REQUIRE(got_taking.has_value() == expected.has_value());
        if (got_taking) CHECK(*got_taking == *expected);
        if (!got_taking) CHECK(taken == body);  // left whole for the reader's resync
    }
}

TEST_CASE("json long strings: a body given up lends its buffer to the document, and only then") {
    const std::string lines = repeated(R"(       1 -4.94938015e-02 caf\u00e9\n)", 100000);
    const std::string plain = repeated(R"(       1 -4.94938015e-02 \"q\" caf)"
                                       "\xC3\xA9"
                                       R"(\n)",
                                       100000);
    std::string body = did_open(plain);
    const char* buffer = body.data();
    auto parsed = lsp::parse_body_taking(body);
    REQUIRE(parsed);
    CHECK(*parsed == *reference(did_open(plain)));
    CHECK(body.empty());
    CHECK((*parsed)["params"]["textDocument"]["text"].get_ref<const std::string&>().data() == buffer);
    // Left to nlohmann-json, the body unchanged when it is not JSON: a \u in the text, a short string
    // that looks like a placeholder (parsed whole: it is no placeholder), a repeated key.
    for (const std::string& text :
         {did_open(lines), R"({"b":"\u0000sphdeck-long-string:0","a":")" + plain + R"("})",
          R"({"a":")" + plain + R"(","a":")" + plain + R"(x"})", did_open(plain) + ",", did_open(plain + "\x01")}) {
        std::string taken = text;
        const auto expected = reference(text);
        const auto got = lsp::parse_body_taking(taken);
        REQUIRE(got.has_value() == expected.has_value());
        if (got) CHECK(*got == *expected);
        if (!got) CHECK(taken == text);
    }
}
}  // namespace test_json_long_strings_cpp
