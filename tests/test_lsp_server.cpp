// The language server's lifecycle and dispatch (lsp/server.*), driven through string streams.
#include <doctest/doctest.h>

#include "lsp/features.hpp"
#include "lsp_session.hpp"

namespace test_lsp_server_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using nlohmann::json;
using test::notify;
using test::request;

namespace {
int error_code(const json& answer) {
    return answer.is_object() && answer.contains("error") ? answer["error"]["code"].get<int>() : 0;
}
}  // namespace

TEST_CASE("lsp server: initialize announces incremental sync, UTF-16 and the features; shutdown then exit is 0") {
    const auto s =
        test::serve({test::initialize_request(1), notify("initialized"), request(2, "shutdown"), notify("exit")});
    CHECK(s.exit_code == 0);
    const json init = s.answer(1);
    REQUIRE(init.contains("result"));
    const json& caps = init["result"]["capabilities"];
    CHECK(caps["positionEncoding"] == "utf-16");
    CHECK(caps["textDocumentSync"]["openClose"] == true);
    CHECK(caps["textDocumentSync"]["change"] == 2);
    CHECK(caps["textDocumentSync"].contains("save"));
    const json features = lsp::feature_capabilities();
    for (auto it = features.begin(); it != features.end(); ++it) CHECK(caps[it.key()] == it.value());
    CHECK(init["result"]["serverInfo"]["name"] == "sphdeck");
    const json shutdown = s.answer(2);
    REQUIRE(shutdown.contains("result"));
    CHECK(shutdown["result"].is_null());
}

TEST_CASE("lsp server: exit without shutdown is 1, and so is the input ending") {
    CHECK(test::serve({test::initialize_request(), notify("exit")}).exit_code == 1);
    CHECK(test::serve({test::initialize_request()}).exit_code == 1);
    CHECK(test::serve({test::initialize_request(), request(2, "shutdown")}).exit_code == 0);
    // Nothing after exit is handled.
    const auto s = test::serve({test::initialize_request(), notify("exit"), request(3, "shutdown")});
    CHECK(s.answer(3).is_null());
}

TEST_CASE("lsp server: requests before initialize, after shutdown, unknown methods") {
    const auto s =
        test::serve({request(1, "textDocument/hover"), notify("textDocument/didOpen"), test::initialize_request(2),
                     test::initialize_request(3), request(4, "no/such/method"), notify("no/such/notification"),
                     request(5, "shutdown"), request(6, "textDocument/hover"), notify("exit")});
    CHECK(error_code(s.answer(1)) == lsp::error_code::server_not_initialized);
    CHECK(s.answer(2).contains("result"));
    CHECK(error_code(s.answer(3)) == lsp::error_code::invalid_request);  // initialize only once
    CHECK(error_code(s.answer(4)) == lsp::error_code::method_not_found);
    CHECK(error_code(s.answer(6)) == lsp::error_code::invalid_request);
    CHECK(s.exit_code == 0);
    // Unknown notifications get no answer: one response per request, nothing else.
    CHECK(s.messages.size() == 6);
}

TEST_CASE("lsp server: a cancelled request still waiting is answered RequestCancelled, others in order") {
    const auto s = test::serve({test::initialize_request(), request(2, "no/such"), request(3, "no/such"),
                                notify("$/cancelRequest", {{"id", 3}}), notify("$/cancelRequest", {{"id", 99}}),
                                request(4, "shutdown")});
    CHECK(error_code(s.answer(2)) == lsp::error_code::method_not_found);
    CHECK(error_code(s.answer(3)) == lsp::error_code::request_cancelled);
    CHECK(s.answer(4).contains("result"));
    std::vector<int> order;
    for (const auto& m : s.messages)
        if (m.contains("id") && m["id"].is_number()) order.push_back(m["id"].get<int>());
    CHECK(order == std::vector<int>{1, 2, 3, 4});
}

TEST_CASE("lsp server: bad JSON is -32700 with id null, invalid requests -32600, responses ignored") {
    std::string input = test::frame(test::initialize_request());
    input += "Content-Length: 9\r\n\r\n{\"id\": 1,";  // not JSON
    for (const json& bad :
         {json::array({1, 2}), json{{"jsonrpc", "2.0"}, {"id", 5}}, json{{"jsonrpc", "2.0"}, {"id", 6}, {"method", 42}},
          json{{"jsonrpc", "2.0"}, {"id", json::array()}, {"method", "x"}}})
        input += test::frame(bad);
    input += test::frame(json{{"jsonrpc", "2.0"}, {"id", 77}, {"result", nullptr}});  // a response to nothing
    input += test::frame(request(8, "shutdown"));
    const auto s = test::serve_bytes(input);
    REQUIRE(s.messages.size() == 7);
    CHECK(s.messages[1]["id"].is_null());
    CHECK(error_code(s.messages[1]) == lsp::error_code::parse_error);
    CHECK(error_code(s.messages[2]) == lsp::error_code::invalid_request);
    CHECK(s.messages[2]["id"].is_null());
    CHECK(error_code(s.answer(5)) == lsp::error_code::invalid_request);
    CHECK(error_code(s.answer(6)) == lsp::error_code::invalid_request);
    CHECK(error_code(s.messages[5]) == lsp::error_code::invalid_request);  // an array is no id
    CHECK(s.messages[5]["id"].is_null());
    CHECK(s.answer(8).contains("result"));
}

TEST_CASE("lsp server: a request about a file no deck reads answers null, string ids are kept") {
    const json params = {{"textDocument", {{"uri", "file:///nonexistent/nowhere.k"}}},
                         {"position", {{"line", 0}, {"character", 0}}}};
    const auto s =
        test::serve({test::initialize_request(),
                     {{"jsonrpc", "2.0"}, {"id", "abc"}, {"method", "textDocument/hover"}, {"params", params}},
                     request(3, "textDocument/hover", json::object()),
                     request(4, "textDocument/noSuchThing", params)});
    bool answered = false;
    for (const auto& m : s.messages)
        if (m.contains("id") && m["id"] == "abc") {
            answered = true;
            CHECK(m.contains("result"));
            CHECK(m["result"].is_null());
        }
    CHECK(answered);
    CHECK(error_code(s.answer(3)) == lsp::error_code::invalid_params);
    CHECK(error_code(s.answer(4)) == lsp::error_code::method_not_found);
}

TEST_CASE("lsp server: a message above the bound is skipped and the user told; the server goes on") {
    lsp::ServerOptions options;
    options.max_body = 2048;
    const json open =
        notify("textDocument/didOpen", {{"textDocument",
                                         {{"uri", "file:///tmp/huge.k"},
                                          {"languageId", "lsdyna"},
                                          {"version", 1},
                                          {"text", "*KEYWORD\n" + std::string(4096, '$') + "\n*END\n"}}}});
    const auto s = test::serve({test::initialize_request(1), open, request(2, "shutdown"), notify("exit")}, options);
    CHECK(s.exit_code == 0);
    std::size_t shown = 0;
    for (const auto& m : s.messages)
        if (m.value("method", "") == "window/showMessage") {
            ++shown;
            CHECK(m["params"]["type"] == 1);
            CHECK(m["params"]["message"].get<std::string>().find("skipped") != std::string::npos);
        }
    CHECK(shown == 1);
    CHECK(s.publications("file:///tmp/huge.k") == 0);
    CHECK(s.answer(2).contains("result"));
}
}  // namespace test_lsp_server_cpp
