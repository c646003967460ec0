// Open documents, edits and published diagnostics of the language server (lsp/text_change.*,
// lsp/document_text.*, lsp/workspace.*, lsp/diagnostics.*): the editor sees what `sphdeck check` reports.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <random>
#include <memory>
#include <vector>

#include "engine/check.hpp"
#include "grammar/earlier_text.hpp"
#include "lsp/deck_settings.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/document_text.hpp"
#include "lsp/text_change.hpp"
#include "lsp/text_position.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"
#include "lsp_session.hpp"
#include "test_support.hpp"

namespace test_lsp_documents_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using nlohmann::json;

namespace {
json range(int l0, int c0, int l1, int c1) {
    return {{"start", {{"line", l0}, {"character", c0}}}, {"end", {{"line", l1}, {"character", c1}}}};
}

json edit(int l0, int c0, int l1, int c1, const std::string& text) {
    return {{"range", range(l0, c0, l1, c1)}, {"text", text}};
}

// A workspace that keeps what it publishes.
struct Recorder {
    std::vector<json> published;
    lsp::Workspace workspace{[this](const json& params) { published.push_back(params); }};

    json last(const std::string& uri) const {
        json out;
        for (const auto& p : published)
            if (p["uri"] == uri) out = p;
        return out;
    }
    std::vector<std::string> codes(const std::string& uri) const {
        std::vector<std::string> out;
        const json published_last = last(uri);  // kept: the loop must not walk a temporary
        for (const auto& d : published_last["diagnostics"]) out.push_back(d["code"]);
        return out;
    }
};

const std::string fine_inc = "*CONTROL_TERMINATION\n$#  endtim\n     0.003\n";
const std::string main_deck = "*KEYWORD\n*INCLUDE\nparts.inc\n*END\n";
}  // namespace

TEST_CASE("lsp edits: full and incremental changes, UTF-16 ranges over multi-byte characters") {
    std::string text = "ab\ncd\n";
    CHECK(lsp::apply_change(text, edit(0, 1, 1, 1, "X")));
    CHECK(text == "aXd\n");
    CHECK(lsp::apply_change(text, json{{"text", "new"}}));
    CHECK(text == "new");
    // "é" is one UTF-16 unit and two bytes, "😀" two units and four bytes.
    text = "$ \xc3\xa9\xf0\x9f\x98\x80z\r\n*END\n";
    CHECK(lsp::apply_change(text, edit(0, 3, 0, 5, "")));  // the emoji
    CHECK(text == "$ \xc3\xa9z\r\n*END\n");
    CHECK(lsp::apply_change(text, edit(0, 2, 0, 3, "e")));  // the é
    CHECK(text == "$ ez\r\n*END\n");
    CHECK(lsp::apply_change(text, edit(0, 99, 0, 99, "!")));  // past the line's end: before its "\r\n"
    CHECK(text == "$ ez!\r\n*END\n");
    CHECK(lsp::apply_change(text, edit(9, 0, 9, 0, "tail")));  // past the last line: the end
    CHECK(text == "$ ez!\r\n*END\ntail");
    CHECK(lsp::apply_change(text, edit(1, 4, 1, 0, "")));  // a reversed range is taken in order
    CHECK(text == "$ ez!\r\n\ntail");
    CHECK_FALSE(lsp::apply_change(text, json{{"range", range(0, 0, 0, 1)}}));
    CHECK_FALSE(lsp::apply_change(text, json{{"range", "x"}, {"text", ""}}));
    CHECK(text == "$ ez!\r\n\ntail");
}

TEST_CASE("lsp decks: which open files are decks, by name and by content") {
    CHECK(lsp::is_deck("a.k", ""));
    CHECK(lsp::is_deck("a.KEY", ""));
    CHECK(lsp::is_deck("a.dyn", ""));
    CHECK(lsp::is_deck("a.inc", ""));
    CHECK(lsp::is_deck("a_0000.rad", ""));
    CHECK(lsp::is_deck("a.rad", ""));
    CHECK(lsp::is_deck("a.txt", "$ comment\n\n*KEYWORD\n"));
    CHECK(lsp::is_deck("a.txt", "#RADIOSS STARTER\n/BEGIN\n"));
    CHECK(lsp::is_deck("a.txt", "# comment\n/BEGIN\n"));
    CHECK_FALSE(lsp::is_deck("a.txt", "hello\n*KEYWORD\n"));
    CHECK_FALSE(lsp::is_deck("a.txt", ""));
}

TEST_CASE("lsp diagnostics: the findings of sphdeck check, with ranges, severities, notes and rule URLs") {
    const std::string path = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/dk/DK018_fires.k";
    const engine::CheckResult expected = engine::check_file(path, lsp::settings_for(path, {}).options);
    REQUIRE(expected.diagnostics.size() >= 2);

    const std::string uri = lsp::uri_from_path(path);
    std::string text;
    {
        std::ifstream in(path, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const auto s =
        test::serve({test::initialize_request(), test::did_open(uri, text, 5), test::request(2, "shutdown")});
    std::vector<json> got;
    for (const auto& m : s.messages)
        if (m.value("method", "") == "textDocument/publishDiagnostics")
            for (const auto& d : m["params"]["diagnostics"]) got.push_back(json{{"uri", m["params"]["uri"]}, {"d", d}});
    REQUIRE(got.size() == expected.diagnostics.size());
    const auto& sources = expected.deck.sources;
    std::size_t with_notes = 0, in_include = 0;
    for (const diag::Diagnostic& d : expected.diagnostics) {
        INFO(d.code << " " << d.message);
        const std::string file_uri = lsp::uri_from_path(sources.file(d.span.file).path);
        const json range = lsp::range_json(sources, d.span);
        const auto match = std::find_if(got.begin(), got.end(), [&](const json& g) {
            return g["uri"] == file_uri && g["d"]["code"] == d.code && g["d"]["range"] == range;
        });
        REQUIRE(match != got.end());
        const json& g = (*match)["d"];
        CHECK(g["severity"] == lsp::lsp_severity(d.severity));
        CHECK(g["message"] == d.message);
        CHECK(g["source"] == "sphdeck");
        CHECK(g["codeDescription"]["href"] == "https://github.com/sphdeck/sphdeck/blob/main/docs/rules.md#dk018");
        REQUIRE(g.contains("relatedInformation"));
        CHECK(g["relatedInformation"].size() == d.notes.size());
        CHECK(g["relatedInformation"][0]["message"] == d.notes[0].message);
        CHECK(g["relatedInformation"][0]["location"]["uri"] == uri);
        CHECK(g["relatedInformation"][0]["location"]["range"] == lsp::range_json(sources, d.notes[0].span));
        with_notes += 1;
        in_include += file_uri != uri;
    }
    CHECK(with_notes == expected.diagnostics.size());
    CHECK(in_include == 1);  // the include's finding went to the include's URI
    CHECK(s.last_published(uri)["version"] == 5);
    CHECK_FALSE(s.last_published(lsp::uri_from_path(std::string(SPHDECK_SOURCE_DIR) +
                                                    "/decks/tests/dk/include/dk018_f_controls.inc"))
                    .contains("version"));  // not open: no version
}

TEST_CASE("lsp diagnostics: notes without a location join the message; unknown codes link their rule page") {
    diag::Diagnostic d{"XX999", diag::Severity::Info, "something", {}, {{{}, "a remark"}}};
    grammar::SourceMap sources;
    const json j = lsp::lsp_diagnostic(d, sources, [](grammar::FileId) { return std::string("file:///x"); });
    CHECK(j["message"] == "something\nnote: a remark");
    CHECK(j["severity"] == 3);
    CHECK_FALSE(j.contains("relatedInformation"));
    CHECK(j["codeDescription"]["href"] == "https://github.com/sphdeck/sphdeck/blob/main/docs/rules/XX999.md");
}

TEST_CASE("lsp workspace: an edit fixes a finding, the list empties, versions follow") {
    test::TempDir dir;
    const std::string deck =
        dir.write("deck.k", "*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*CONTROL_TERMINATION\n     0.003\n*END\n");
    const std::string uri = lsp::uri_from_path(deck);
    Recorder r;
    // Open with the text on disk, then edit the buffer only.
    std::ifstream in(deck);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(r.workspace.open(uri, text, 1));
    r.workspace.flush();
    CHECK(r.codes(uri) == std::vector<std::string>{"DK018"});
    CHECK(r.last(uri)["version"] == 1);
    // Delete the second *CONTROL_TERMINATION and its card (lines 3-4).
    REQUIRE(r.workspace.change(uri, 2, json::array({edit(3, 0, 5, 0, "")})));
    CHECK(*r.workspace.text(uri) == "*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*END\n");
    r.workspace.flush();
    CHECK(r.last(uri)["diagnostics"].empty());
    CHECK(r.last(uri)["version"] == 2);
    const std::size_t before = r.published.size();
    r.workspace.flush();  // nothing changed: nothing published
    CHECK(r.published.size() == before);
    // Closing the deck clears what it published.
    REQUIRE(r.workspace.change(uri, 3, json::array({json{{"text", text}}})));
    r.workspace.flush();
    CHECK(r.codes(uri) == std::vector<std::string>{"DK018"});
    REQUIRE(r.workspace.close(uri));
    r.workspace.flush();
    CHECK(r.last(uri)["diagnostics"].empty());
    CHECK(r.workspace.deck_mains().empty());
}

TEST_CASE("lsp workspace: an edited include re-checks the deck that reads it, buffers win over the disk") {
    test::TempDir dir;
    const std::string main_path = dir.write("main.k", main_deck);
    const std::string inc_path = dir.write("parts.inc", fine_inc);
    const std::string main_uri = lsp::uri_from_path(main_path), inc_uri = lsp::uri_from_path(inc_path);
    Recorder r;
    REQUIRE(r.workspace.open(inc_uri, fine_inc, 1));  // opened first: checked as part of main.k on disk
    r.workspace.flush();
    REQUIRE(r.workspace.deck_mains().size() == 1);
    CHECK(r.workspace.deck_mains()[0] == engine::Documents::key(main_path));
    REQUIRE(r.workspace.open(main_uri, main_deck + "", 1));
    r.workspace.flush();
    // The include is checked as part of the main deck, not on its own.
    REQUIRE(r.workspace.deck_mains().size() == 1);
    CHECK(r.workspace.deck_mains()[0] == engine::Documents::key(main_path));
    CHECK(r.last(inc_uri)["diagnostics"].empty());
    CHECK(r.last(main_uri)["diagnostics"].empty());

    // The include, edited in the editor only, now repeats a control the main deck gains too.
    REQUIRE(r.workspace.change(main_uri, 2, json::array({edit(1, 0, 1, 0, "*CONTROL_TERMINATION\n     0.001\n")})));
    r.workspace.flush();
    CHECK(r.codes(inc_uri) == std::vector<std::string>{"DK018"});
    CHECK(r.last(inc_uri)["version"] == 1);
    const json note = r.last(inc_uri)["diagnostics"][0]["relatedInformation"][0];
    CHECK(note["location"]["uri"] == main_uri);
    CHECK(note["location"]["range"]["start"]["line"] == 1);

    // Fix it in the include's buffer: the main deck is re-checked and the finding goes.
    REQUIRE(r.workspace.change(inc_uri, 2, json::array({edit(0, 0, 3, 0, "$ nothing here\n")})));
    r.workspace.flush();
    CHECK(r.last(inc_uri)["diagnostics"].empty());
    CHECK(r.last(inc_uri)["version"] == 2);

    // A request about the include finds the main deck.
    const auto located = r.workspace.locate(inc_path);
    REQUIRE(located);
    CHECK(located->deck->main == engine::Documents::key(main_path));
    CHECK(located->deck->result.deck.sources.file(located->file).text == "$ nothing here\n");

    // The main deck closes: the include, still open, is checked as part of main.k as the disk holds it
    // (without the edit's *CONTROL_TERMINATION), and main.k's own list goes.
    REQUIRE(r.workspace.close(main_uri));
    r.workspace.flush();
    REQUIRE(r.workspace.deck_mains().size() == 1);
    CHECK(r.workspace.deck_mains()[0] == engine::Documents::key(main_path));
    CHECK(r.last(main_uri)["diagnostics"].empty());
    CHECK(r.last(inc_uri)["diagnostics"].empty());

    // With no deck on disk that includes it, it is a deck of its own.
    std::filesystem::remove(main_path);
    REQUIRE(r.workspace.save(inc_uri, std::nullopt));
    r.workspace.flush();
    REQUIRE(r.workspace.deck_mains().size() == 1);
    CHECK(r.workspace.deck_mains()[0] == engine::Documents::key(inc_path));
}

TEST_CASE("lsp workspace: an include dropped from the deck gets an empty list; sphdeck.toml is honoured") {
    test::TempDir dir;
    const std::string main_path = dir.write("main.k", main_deck);
    const std::string inc_path = dir.write("parts.inc", fine_inc + "*CONTROL_TERMINATION\n     0.004\n");
    const std::string main_uri = lsp::uri_from_path(main_path), inc_uri = lsp::uri_from_path(inc_path);
    Recorder r;
    REQUIRE(r.workspace.open(main_uri, main_deck, 1));
    r.workspace.flush();
    CHECK(r.codes(inc_uri) == std::vector<std::string>{"DK018"});  // read from the disk
    CHECK_FALSE(r.last(inc_uri).contains("version"));
    REQUIRE(r.workspace.change(main_uri, 2, json::array({edit(1, 0, 3, 0, "")})));  // no *INCLUDE any more
    r.workspace.flush();
    CHECK(r.last(inc_uri)["diagnostics"].empty());

    dir.write("sphdeck.toml", "ignore = [\"DK018\"]\n");
    REQUIRE(r.workspace.change(main_uri, 3, json::array({json{{"text", main_deck}}})));
    r.workspace.flush();
    CHECK(r.last(inc_uri)["diagnostics"].empty());
    dir.write("sphdeck.toml", "ignore = [\n");  // broken: said on the deck, the check goes on without it
    REQUIRE(r.workspace.save(main_uri, std::nullopt));
    r.workspace.flush();
    CHECK(r.codes(inc_uri) == std::vector<std::string>{"DK018"});
    const json main_list = r.last(main_uri)["diagnostics"];
    REQUIRE(main_list.size() == 1);
    CHECK(main_list[0]["message"].get<std::string>().find("sphdeck.toml") != std::string::npos);
}

TEST_CASE("lsp workspace: a buffer that is no deck yet, and one that cannot be read") {
    test::TempDir dir;
    const std::string uri = lsp::uri_from_path(dir.path() / "new.k");
    Recorder r;
    REQUIRE(r.workspace.open(uri, "", 1));
    r.workspace.flush();
    CHECK(r.last(uri)["diagnostics"].empty());  // an empty new file is not an error
    REQUIRE(r.workspace.change(uri, 2, json::array({json{{"text", "just words\n"}}})));
    r.workspace.flush();
    CHECK(r.last(uri)["diagnostics"].size() == 1);  // what `check` says: no keyword line
    CHECK_FALSE(r.workspace.open("untitled:Untitled-1", "*KEYWORD\n", 1));
    CHECK_FALSE(r.workspace.change(lsp::uri_from_path(dir.path() / "closed.k"), 1, json::array()));
}

TEST_CASE("lsp server: waiting didChange notifications cost one re-check; a request sees every edit before it") {
    test::TempDir dir;
    const std::string text = "*KEYWORD\n*CONTROL_TERMINATION\n     0.002\n*END\n";
    const std::string uri = lsp::uri_from_path(dir.write("deck.k", text));
    const json add_twice = json::array({edit(1, 0, 1, 0, "*CONTROL_TERMINATION\n     0.001\n")});
    std::vector<json> messages = {test::initialize_request(), test::did_open(uri, text, 1)};
    for (int version = 2; version <= 6; ++version)
        messages.push_back(test::did_change(uri, version, json::array({edit(0, 0, 0, 0, "$ typing\n")})));
    auto s = test::serve(messages);
    CHECK(s.publications(uri) == 1);  // five edits, one re-check
    CHECK(s.last_published(uri)["version"] == 6);

    const json hover = {{"textDocument", {{"uri", uri}}}, {"position", {{"line", 0}, {"character", 0}}}};
    s = test::serve({test::initialize_request(), test::did_open(uri, text, 1), test::did_change(uri, 2, add_twice),
                     test::request(7, "textDocument/hover", hover),
                     test::did_change(uri, 3, json::array({json{{"text", text}}}))});
    REQUIRE(s.publications(uri) == 2);
    std::size_t first_list = 0, answer = 0;
    for (std::size_t i = 0; i < s.messages.size(); ++i) {
        if (s.messages[i].value("method", "") == "textDocument/publishDiagnostics" && first_list == 0) first_list = i;
        if (s.messages[i].contains("id") && s.messages[i]["id"] == 7) answer = i;
    }
    CHECK(first_list < answer);  // re-checked before the request was answered
    CHECK(s.messages[first_list]["params"]["version"] == 2);
    CHECK(s.messages[first_list]["params"]["diagnostics"].size() == 1);
    CHECK(s.last_published(uri)["diagnostics"].empty());
    CHECK(s.last_published(uri)["version"] == 3);
}

// Issue 45 item 1: an open document's text held in chunks of lines (lsp/document_text.*) gives the
// same text as applying each change to one string (lsp::apply_change), whatever the change: across
// chunk boundaries, "\r\n" lines, multi-byte characters, positions past the end, reversed ranges,
// whole replacements; and it views the opened text without a copy until a change touches it.
namespace {
json chunk_test_change(std::uint32_t l0, std::uint32_t c0, std::uint32_t l1, std::uint32_t c1,
                       const std::string& text) {
    return {{"range", {{"start", {{"line", l0}, {"character", c0}}}, {"end", {{"line", l1}, {"character", c1}}}}},
            {"text", text}};
}

// About `lines` lines of card-like text, with "\r\n" endings and a multi-byte title here and there.
std::string deck_like_text(int lines) {
    std::string text;
    for (int i = 0; i < lines; ++i) {
        if (i % 97 == 0)
            text += "*PART\r\nwasser \xC3\xA9t\xC3\xA9 \xF0\x9F\x8C\x8A\r\n";
        else
            text += std::to_string(i) + "      1.0e-3      2.0e-3      0.0\n";
    }
    return text;
}
}  // namespace

TEST_CASE("document text: chunked edits equal edits of one string, across chunks, then joined once") {
    const std::string original = deck_like_text(12000);  // about 400 KB: several 64 KB chunks
    lsp::DocumentText document(std::make_shared<const std::string>(original));
    CHECK(document.chunk_count() > 4);
    CHECK_FALSE(document.changed());
    std::string expected = original;
    std::mt19937 random(45);
    const auto pick = [&](std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random); };
    const std::string pieces[] = {"",     "x",        "\n",      "a\nb\n",
                                  "\r\n", "\xC3\xA9", "*NODE\n", std::string(70000, 'z') + "\n"};
    for (int step = 0; step < 300; ++step) {
        CAPTURE(step);
        const std::uint32_t lines = 12500;  // a little past the last line: clamped to the end
        std::uint32_t l0 = pick(lines), l1 = l0 + pick(step % 10 == 0 ? 3000 : 3);
        const std::uint32_t c0 = pick(40), c1 = pick(40);
        if (step % 7 == 0) std::swap(l0, l1);  // reversed: taken in order
        const std::string& piece = pieces[step % 50 == 0 ? 7 : pick(7)];
        const json change = chunk_test_change(l0, c0, l1, c1, piece);
        REQUIRE(lsp::apply_change(expected, change));
        REQUIRE(document.apply(change));
        if (step % 25 == 0) REQUIRE(document.joined() == expected);
    }
    CHECK(document.changed());
    CHECK(document.size() == expected.size());
    const auto joined = std::make_shared<const std::string>(document.joined());
    REQUIRE(*joined == expected);
    document.rebase(joined);
    CHECK_FALSE(document.changed());
    CHECK(document.joined() == expected);
    // A malformed change leaves the text alone.
    CHECK_FALSE(document.apply(json{{"range", "x"}, {"text", ""}}));
    CHECK_FALSE(document.changed());
    REQUIRE(document.apply(chunk_test_change(5, 0, 5, 3, "abc")));
    REQUIRE(lsp::apply_change(expected, chunk_test_change(5, 0, 5, 3, "abc")));
    CHECK(document.joined() == expected);
    // A whole replacement, then an empty text and edits of it.
    REQUIRE(document.apply(json{{"text", "*KEYWORD\n*END\n"}}));
    CHECK(document.joined() == "*KEYWORD\n*END\n");
    REQUIRE(document.apply(chunk_test_change(0, 0, 9, 0, "")));
    CHECK(document.joined().empty());
    REQUIRE(document.apply(chunk_test_change(3, 4, 3, 4, "tail")));
    CHECK(document.joined() == "tail");
}

TEST_CASE("document text: joins patch the last check's buffer in place, keeping aside what they replaced") {
    auto opened = std::make_shared<std::string>(deck_like_text(12000));
    std::string expected = *opened;
    lsp::DocumentText document(opened);
    std::shared_ptr<const std::string> last = std::move(opened);  // what the last check read
    std::string last_bytes = *last;                               // and its bytes as it read them
    std::mt19937 random(450);
    const auto pick = [&](std::uint32_t n) { return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random); };
    const std::string pieces[] = {"", "x", "\n", "a\nb\n", "\r\n", "\xC3\xA9", "*NODE\n", "1.5e-3"};
    int in_place = 0, fresh = 0;
    for (int round = 0; round < 60; ++round) {
        CAPTURE(round);
        for (std::uint32_t n = 1 + pick(round % 9 == 0 ? 20 : 3); n > 0; --n) {
            const std::uint32_t l0 = pick(12100), l1 = l0 + pick(round % 13 == 0 ? 500 : 2);
            const json change = chunk_test_change(l0, pick(40), l1, pick(40), pieces[pick(8)]);
            REQUIRE(lsp::apply_change(expected, change));
            REQUIRE(document.apply(change));
        }
        if (round == 30) {  // the whole text replaced: nothing kept to tell
            expected = deck_like_text(3000);
            REQUIRE(document.apply(json{{"text", expected}}));
        }
        const lsp::DocumentText::Joined joined = document.join_for_check();
        REQUIRE(*joined.text == expected);
        CHECK(joined.revision.has_value() == (round != 30));
        if (joined.revision) {
            const grammar::TextRevision& r = *joined.revision;
            CHECK(r.previous_data == last->data());
            CHECK(r.previous_size == last_bytes.size());
            // The bytes it says are kept are: the re-check reads its edit from them.
            const std::size_t shorter = std::min(last_bytes.size(), expected.size());
            REQUIRE(r.same_prefix <= shorter);
            REQUIRE(r.same_suffix <= shorter - r.same_prefix);
            CHECK(last_bytes.compare(0, r.same_prefix, expected, 0, r.same_prefix) == 0);
            CHECK(last_bytes.compare(last_bytes.size() - r.same_suffix, r.same_suffix, expected,
                                     expected.size() - r.same_suffix, r.same_suffix) == 0);
            if (r.replaced) {  // patched in place: the earlier text is read back whole from the revision
                ++in_place;
                CHECK(joined.text->data() == last->data());
                REQUIRE(grammar::EarlierText::consistent(*joined.text, r));
                CHECK(grammar::EarlierText(*joined.text, r).copy(0, r.previous_size) == last_bytes);
            } else {  // a fresh buffer: the one the last check read is left as it was
                ++fresh;
                CHECK(*last == last_bytes);
            }
        }
        last = joined.text;
        last_bytes = *last;
        CHECK_FALSE(document.changed());
        CHECK(document.joined() == expected);
    }
    // The text is held once: nearly every join patched the buffer the check before read.
    CHECK(in_place > 50);
    CHECK(fresh < 5);
}

TEST_CASE("document text: the opened text is viewed, and a change touches only its own chunk") {
    const auto original = std::make_shared<const std::string>(deck_like_text(12000));
    lsp::DocumentText document(original);
    CHECK(original.use_count() == 2);  // held, not copied
    const std::size_t chunks = document.chunk_count();
    REQUIRE(document.apply(chunk_test_change(6000, 2, 6000, 3, "7")));
    CHECK(document.chunk_count() == chunks);
    std::string expected = *original;
    REQUIRE(lsp::apply_change(expected, chunk_test_change(6000, 2, 6000, 3, "7")));
    CHECK(document.joined() == expected);
}
}  // namespace test_lsp_documents_cpp
