// The language server against a hostile or broken client: thousands of random, corrupted and
// truncated messages, then a valid request that must still be answered. And the real binary,
// `sphdeck lsp`, through a pipe.
#include <doctest/doctest.h>

#include <cstdlib>
#include <random>
#include <sys/wait.h>

#include "lsp/uri.hpp"
#include "lsp_session.hpp"
#include "run_sphdeck.hpp"
#include "test_support.hpp"

namespace test_lsp_robustness_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using nlohmann::json;

namespace {
// Random messages that look enough like LSP to reach past the framing: requests and notifications
// with known and unknown methods, bad params, odd ids, document events with random texts and ranges.
json random_message(std::mt19937& rng, const std::string& uri) {
    const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
    // Not "shutdown" or "exit": the server must stay up to the end.
    static const char* methods[] = {"initialize",
                                    "initialized",
                                    "textDocument/hover",
                                    "textDocument/didOpen",
                                    "textDocument/didChange",
                                    "textDocument/didClose",
                                    "textDocument/didSave",
                                    "textDocument/definition",
                                    "$/cancelRequest",
                                    "workspace/symbol",
                                    "textDocument/completion",
                                    "",
                                    "x"};
    static const char* texts[] = {"*KEYWORD\n*CONTROL_TERMINATION\n 1.0\n*END\n",
                                  "",
                                  "garbage\n",
                                  "*KEYWORD\n*INCLUDE\nnowhere.inc\n*PART\n\n 1 2 3\n",
                                  "#RADIOSS STARTER\n/BEGIN\n",
                                  "*KEYWORD\n$ d\xc3\xa9j\xc3\xa0 \xf0\x9f\x98\x80\n*END\n"};
    json params;
    switch (pick(5)) {
        case 0: params = json::object(); break;
        case 1: params = nullptr; break;
        case 2: params = json::array({1, "two"}); break;
        default:
            params = {{"textDocument",
                       {{"uri", pick(4) ? json(uri) : json(pick(2) ? "untitled:1" : "file:///nope/%zz")},
                        {"version", static_cast<int>(pick(100)) - 5},
                        {"text", texts[pick(std::size(texts))]}}},
                      {"position", {{"line", pick(10)}, {"character", pick(3) ? json(pick(40)) : json(-1)}}},
                      {"contentChanges", json::array({{{"range",
                                                        {{"start", {{"line", pick(8)}, {"character", pick(30)}}},
                                                         {"end", {{"line", pick(8)}, {"character", pick(30)}}}}},
                                                       {"text", texts[pick(std::size(texts))]}},
                                                      {{"text", texts[pick(std::size(texts))]}}})},
                      {"id", pick(50)}};
    }
    json message = {{"jsonrpc", "2.0"}, {"method", methods[pick(std::size(methods))]}, {"params", params}};
    switch (pick(4)) {
        case 0: break;  // a notification
        case 1: message["id"] = pick(1000); break;
        case 2: message["id"] = "s" + std::to_string(pick(1000)); break;
        default: message["id"] = pick(2) ? json(1.5) : json::object(); break;  // not an id
    }
    return message;
}

std::string random_bytes(std::mt19937& rng, std::size_t n) {
    std::string out;
    for (std::size_t i = 0; i < n; ++i) out += static_cast<char>(rng() % 256);
    return out;
}
}  // namespace

TEST_CASE("lsp robustness: thousands of random and truncated messages, then a valid request is answered") {
    test::TempDir dir;
    const std::string uri = lsp::uri_from_path(dir.write("deck.k", "*KEYWORD\n*END\n"));
    std::mt19937 rng(20261125);
    std::string input = test::frame(test::initialize_request());
    std::size_t sent = 0;
    for (; sent < 3000; ++sent) {
        const std::string framed = test::frame(random_message(rng, uri));
        switch (rng() % 8) {
            case 0: input += random_bytes(rng, rng() % 200); break;           // noise
            case 1: input += framed.substr(0, rng() % framed.size()); break;  // truncated
            case 2: {                                                         // corrupted
                std::string bad = framed;
                for (int k = 0; k < 3; ++k) bad[rng() % bad.size()] = static_cast<char>(rng() % 256);
                input += bad;
                break;
            }
            case 3:
                input += "Content-Length: " + std::to_string(rng() % 300) + "\r\n\r\n" + random_bytes(rng, rng() % 300);
                break;
            case 4: input += "Content-Length: 5000\r\n\r\n" + std::string(5000, '['); break;  // above the bound below
            default: input += framed; break;                                                  // well-formed
        }
    }
    input += "\r\n" + test::frame(json{{"jsonrpc", "2.0"}, {"id", "the-last-one"}, {"method", "no/such/method"}});
    lsp::ServerOptions options;
    options.max_body = 4096;
    const auto s = test::serve_bytes(input, options);
    bool answered = false;
    for (const auto& m : s.messages)
        if (m.contains("id") && m["id"] == "the-last-one" && m.contains("error")) answered = true;
    CHECK(answered);
    CHECK(s.messages.size() > sent / 4);  // it kept answering all along
    std::size_t published = 0;
    for (const auto& m : s.messages) published += m.value("method", "") == "textDocument/publishDiagnostics";
    CHECK(published > 0);  // the random documents were checked
    MESSAGE(s.messages.size() << " messages out for " << sent << " in, " << published << " diagnostics lists");
}

TEST_CASE("lsp binary: sphdeck lsp --stdio through a pipe: initialize, shutdown, exit 0; exit alone 1") {
    test::TempDir dir;
    const auto run = [&](const std::vector<json>& messages) {
        std::string input;
        for (const auto& m : messages) input += test::frame(m);
        dir.write("input.bin", input);
        const std::string command = "cd '" + dir.path().string() + "' && cat input.bin | '" + SPHDECK_BINARY +
                                    "' lsp --stdio > output.bin 2> errors.txt";
        const int status = std::system(command.c_str());
        std::ifstream in(dir.path() / "output.bin", std::ios::binary);
        const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::messages_in(output));
    };
    const std::string deck =
        dir.write("deck.k", "*KEYWORD\n*CONTROL_TERMINATION\n 1.0\n*CONTROL_TERMINATION\n 2.0\n*END\n");
    const auto [code, messages] =
        run({test::initialize_request(1), test::notify("initialized"),
             test::did_open(lsp::uri_from_path(deck),
                            "*KEYWORD\n*CONTROL_TERMINATION\n 1.0\n*CONTROL_TERMINATION\n 2.0\n*END\n"),
             test::request(2, "shutdown"), test::notify("exit")});
    CHECK(code == 0);
    REQUIRE(messages.size() == 3);
    CHECK(messages[0]["id"] == 1);
    CHECK(messages[0]["result"]["capabilities"]["textDocumentSync"]["change"] == 2);
    CHECK(messages[1]["method"] == "textDocument/publishDiagnostics");
    CHECK(messages[1]["params"]["diagnostics"][0]["code"] == "DK018");
    CHECK(messages[2]["id"] == 2);
    CHECK(run({test::initialize_request(1), test::notify("exit")}).first == 1);
}
}  // namespace test_lsp_robustness_cpp
