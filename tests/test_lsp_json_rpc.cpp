// The LSP base protocol reader and writer (lsp/json_rpc.*): framing, and what it does with bad input.
#include <doctest/doctest.h>

#include <sstream>
#include <streambuf>

#include "lsp_session.hpp"

namespace test_lsp_json_rpc_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using lsp::ReadStatus;
using nlohmann::json;

namespace {
// Hands out its text `step` bytes per read, as a pipe delivers a message in pieces.
class TrickleBuffer final : public std::streambuf {
public:
    TrickleBuffer(std::string text, std::size_t step) : text_(std::move(text)), step_(step) {}

protected:
    int_type underflow() override {
        if (at_ >= text_.size()) return traits_type::eof();
        const std::size_t n = std::min(step_, text_.size() - at_);
        setg(text_.data() + at_, text_.data() + at_, text_.data() + at_ + n);
        at_ += n;
        return traits_type::to_int_type(*gptr());
    }

private:
    std::string text_;
    std::size_t step_, at_ = 0;
};

std::vector<lsp::ReadResult> read_all(const std::string& bytes, std::size_t max_body = lsp::default_max_body) {
    std::istringstream in(bytes);
    lsp::MessageReader reader(in, max_body);
    std::vector<lsp::ReadResult> out;
    for (int guard = 0; guard < 10000; ++guard) {
        lsp::ReadResult r = reader.next();
        if (r.status == ReadStatus::end) break;
        out.push_back(std::move(r));
    }
    return out;
}

const json hello = test::request(7, "hello", {{"x", "é"}});
}  // namespace

TEST_CASE("lsp json-rpc: several messages in one buffer, and one split over many reads") {
    const std::string two = test::frame(hello) + test::frame(test::notify("n"));
    auto read = read_all(two);
    REQUIRE(read.size() == 2);
    CHECK(read[0].message == hello);
    CHECK(read[1].message["method"] == "n");

    for (std::size_t step : {1u, 3u, 17u}) {
        TrickleBuffer buffer(two + test::frame(hello), step);
        std::istream in(&buffer);
        lsp::MessageReader reader(in);
        CHECK(reader.next().message == hello);
        CHECK(reader.next().message["method"] == "n");
        CHECK(reader.next().message == hello);
        CHECK(reader.next().status == ReadStatus::end);
    }
}

TEST_CASE("lsp json-rpc: headers: Content-Type, any case, bare newlines") {
    const std::string body = hello.dump();
    const std::string text = "content-length: " + std::to_string(body.size()) +
                             "\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n" + body +
                             "Content-Length: " + std::to_string(body.size()) + "\n\n" + body;
    auto read = read_all(text);
    REQUIRE(read.size() == 2);
    CHECK(read[0].message == hello);
    CHECK(read[1].message == hello);
}

TEST_CASE("lsp json-rpc: a bad or missing Content-Length is skipped and the next message read") {
    for (const char* bad : {"Content-Length: abc\r\n\r\n", "Content-Length: -5\r\n\r\n",
                            "Content-Length: 99999999999999999999999\r\n\r\n", "Content-Type: x\r\n\r\n",
                            "garbage without colon\r\n\r\n", "{\"jsonrpc\":\"2.0\"}\r\n\r\n"}) {
        INFO(bad);
        auto read = read_all(std::string(bad) + test::frame(hello));
        REQUIRE(!read.empty());
        CHECK(read.front().status == ReadStatus::bad_header);
        CHECK(read.back().status == ReadStatus::message);
        CHECK(read.back().message == hello);
    }
    // Garbage straight before a header block: the Content-Length line starts the block afresh.
    auto read = read_all("noise\r\nmore: noise\r\n" + test::frame(hello));
    REQUIRE(read.size() == 1);
    CHECK(read[0].message == hello);
}

TEST_CASE("lsp json-rpc: a body above the bound is skipped without keeping it") {
    const std::string big = test::frame(test::request(1, "big", {{"text", std::string(5000, 'x')}}));
    auto read = read_all(big + test::frame(hello), 1000);
    REQUIRE(read.size() == 2);
    CHECK(read[0].status == ReadStatus::too_large);
    CHECK(read[1].message == hello);
    // A length far above the bound on a short stream: skipped to the end, no allocation of it.
    read = read_all("Content-Length: 999999999999999\r\n\r\n{}");
    REQUIRE(read.size() == 1);
    CHECK(read[0].status == ReadStatus::too_large);
}

TEST_CASE("lsp json-rpc: truncated streams end, bad JSON is a parse error, and a swallowed message is found again") {
    const std::string whole = test::frame(hello);
    for (std::size_t cut = 0; cut < whole.size(); ++cut) {
        auto read = read_all(whole.substr(0, cut));
        CHECK(read.empty());  // no message, no hang, no crash
    }
    auto read = read_all("Content-Length: 5\r\n\r\n{oops" + test::frame(hello));
    REQUIRE(read.size() == 2);
    CHECK(read[0].status == ReadStatus::parse_error);
    CHECK(read[1].message == hello);
    // A truncated message whose length runs into the next one.
    const std::string cut = "Content-Length: 60\r\n\r\n{\"jsonrpc\":\"2.0\",\"id\":1,";
    read = read_all(cut + test::frame(hello));
    REQUIRE(read.size() == 2);
    CHECK(read[0].status == ReadStatus::parse_error);
    CHECK(read[1].message == hello);
}

TEST_CASE("lsp json-rpc: deep nesting and invalid UTF-8 are parse errors, not crashes") {
    CHECK_FALSE(lsp::parse_body(std::string(100000, '[') + std::string(100000, ']')));
    CHECK(lsp::parse_body("[[[[1]]]]"));
    CHECK_FALSE(lsp::parse_body("\"\xff\""));
    CHECK(lsp::parse_body("{\"a\":\"[[[[[[\"}"));  // brackets inside strings do not nest
}

TEST_CASE("lsp json-rpc: writing replaces bytes that are not UTF-8 and frames by bytes") {
    std::ostringstream out;
    lsp::write_message(out, json{{"message", std::string("d\xe9p \xc3\xa9")}});
    const std::string text = out.str();
    const auto header_end = text.find("\r\n\r\n");
    REQUIRE(header_end != std::string::npos);
    const std::string body = text.substr(header_end + 4);
    CHECK(text.substr(0, header_end) == "Content-Length: " + std::to_string(body.size()));
    CHECK(json::parse(body)["message"] == "d\xef\xbf\xbdp \xc3\xa9");
}
}  // namespace test_lsp_json_rpc_cpp
