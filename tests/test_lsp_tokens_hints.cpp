// Issue 29: semantic tokens, inlay hints, hover and completion on every column of a field, and the
// server's settings and file watching for them.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "engine/check.hpp"
#include "lsp/features.hpp"
#include "lsp/semantic_tokens.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"
#include "lsp_session.hpp"

namespace test_lsp_tokens_hints_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::string kDeck = R"(*KEYWORD
*PARAMETER
R rho         1000.0
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0   1.0e+20         3         0        12
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start
         3                 0.2       2.0       0.0   1.0e+20       0.0
*PART
$#                                                               title
water
$#     pid     secid       mid     eosid
         1         3         5         7
*MAT_NULL
$ the fluid
         5      &rho
*EOS_MURNAGHAN
         7       7.0  340000.0
*NODE
       1           0.010           0.030             0.0
       2           0.030           0.030             0.0
*END
)";

lsp::CheckedDeck check(const std::string& text, const std::string& name = "main.k",
                       std::optional<grammar::DeckFormat> format = grammar::DeckFormat::LsDyna) {
    lsp::CheckedDeck deck;
    deck.main = name;
    deck.result = engine::check_buffer(text, name, {}, format);
    return deck;
}

std::uint32_t line_of(const std::string& text, std::string_view needle) {
    const auto at = text.find(needle);
    REQUIRE(at != std::string::npos);
    return static_cast<std::uint32_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

nlohmann::json ask(const lsp::CheckedDeck& deck, std::string_view method, nlohmann::json params) {
    auto answer = lsp::answer_feature(method, deck, 0, params);
    REQUIRE(answer.handled);
    return answer.result;
}

// Decoded tokens: 0-based line and character, length, type name, modifier bits.
struct Token {
    std::uint32_t line, character, length;
    std::string type;
    std::uint32_t modifiers;
};
std::vector<Token> decode(const nlohmann::json& result) {
    std::vector<Token> out;
    const auto& data = result["data"];
    REQUIRE(data.size() % 5 == 0);
    std::uint32_t line = 0, character = 0;
    for (std::size_t i = 0; i < data.size(); i += 5) {
        const auto delta_line = data[i].get<std::uint32_t>();
        character = delta_line == 0 ? character + data[i + 1].get<std::uint32_t>() : data[i + 1].get<std::uint32_t>();
        line += delta_line;
        out.push_back({line, character, data[i + 2].get<std::uint32_t>(),
                       std::string(lsp::kTokenTypes.at(data[i + 3].get<std::size_t>())),
                       data[i + 4].get<std::uint32_t>()});
    }
    return out;
}
const Token* token_at(const std::vector<Token>& tokens, std::uint32_t line, std::uint32_t character) {
    for (const auto& t : tokens)
        if (t.line == line && character >= t.character && character < t.character + t.length) return &t;
    return nullptr;
}

nlohmann::json range(std::uint32_t first, std::uint32_t last) {
    return {{"start", {{"line", first}, {"character", 0}}}, {"end", {{"line", last}, {"character", 200}}}};
}

std::vector<std::string> hint_labels(const nlohmann::json& hints, std::uint32_t line) {
    std::vector<std::string> out;
    for (const auto& h : hints)
        if (h["position"]["line"] == line) out.push_back(h["label"].get<std::string>());
    return out;
}
bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

TEST_CASE("lsp hover: every column of a right-aligned field answers, blank part included (issue 29)") {
    const auto deck = check(kDeck);
    const std::uint32_t card = line_of(kDeck, "         1         0   1.0e+20");
    for (std::uint32_t character = 50; character < 60; ++character) {  // FORM, columns 51-60: "        12"
        auto result = ask(deck, "textDocument/hover", {{"position", {{"line", card}, {"character", character}}}});
        REQUIRE(result.is_object());
        CHECK(result["contents"]["value"].get<std::string>().find("**FORM**") != std::string::npos);
    }
    // The blank CSLH of *SECTION_SPH, between two written values.
    const std::uint32_t section = line_of(kDeck, "         3                 0.2");
    auto result = ask(deck, "textDocument/hover", {{"position", {{"line", section}, {"character", 14}}}});
    REQUIRE(result.is_object());
    CHECK(result["contents"]["value"].get<std::string>().find("**CSLH**") != std::string::npos);
    // Free format: the blank after a comma belongs to the field after it.
    const std::string free = "*KEYWORD\n*SECTION_SPH\n3,  1.2,0.2\n*END\n";
    const auto free_deck = check(free);
    result = ask(free_deck, "textDocument/hover", {{"position", {{"line", 2}, {"character", 3}}}});
    REQUIRE(result.is_object());
    CHECK(result["contents"]["value"].get<std::string>().find("**CSLH**") != std::string::npos);
}

TEST_CASE("lsp completion: enum values with their meaning beside them, on the blank part of a field") {
    const auto deck = check(kDeck);
    const std::uint32_t card = line_of(kDeck, "         1         0   1.0e+20");
    auto list = ask(deck, "textDocument/completion", {{"position", {{"line", card}, {"character", 52}}}});
    REQUIRE(list["items"].size() > 1);
    const auto& first = list["items"][0];
    CHECK(first["kind"] == 20);
    CHECK(first["labelDetails"]["description"].get<std::string>() == first["detail"].get<std::string>());
    CHECK(first["documentation"].get<std::string>().rfind("FORM = ", 0) == 0);
}

TEST_CASE("lsp semantic tokens: keywords, comments, headers, ids, enums, reals, parameters, alternating fields") {
    const auto deck = check(kDeck);
    const auto tokens = decode(ask(deck, "textDocument/semanticTokens/full", nlohmann::json::object()));
    const Token* t = token_at(tokens, line_of(kDeck, "*CONTROL_SPH"), 1);
    REQUIRE(t);
    CHECK(t->type == "keyword");
    t = token_at(tokens, line_of(kDeck, "$#    ncbs"), 3);
    REQUIRE(t);
    CHECK(t->type == "comment");
    CHECK((t->modifiers & lsp::kHeader) != 0);
    t = token_at(tokens, line_of(kDeck, "$ the fluid"), 3);
    REQUIRE(t);
    CHECK(t->type == "comment");
    CHECK((t->modifiers & lsp::kHeader) == 0);
    const std::uint32_t control = line_of(kDeck, "         1         0   1.0e+20");
    t = token_at(tokens, control, 9);  // NCBS, field 0
    REQUIRE(t);
    CHECK((t->modifiers & lsp::kOddField) == 0);
    t = token_at(tokens, control, 25);  // DT, field 2: a real
    REQUIRE(t);
    CHECK(t->type == "real");
    t = token_at(tokens, control, 59);  // FORM, field 5: odd, one of its allowed values
    REQUIRE(t);
    CHECK(t->type == "enumMember");
    CHECK((t->modifiers & lsp::kOddField) != 0);
    CHECK(token_at(tokens, control, 55) == nullptr);  // blanks are not coloured
    const std::uint32_t part = line_of(kDeck, "         1         3         5");
    t = token_at(tokens, part, 9);  // PID: defines a part
    REQUIRE(t);
    CHECK(t->type == "variable");
    CHECK((t->modifiers & lsp::kDeclaration) != 0);
    t = token_at(tokens, part, 19);  // SECID: names a section
    REQUIRE(t);
    CHECK(t->type == "variable");
    CHECK((t->modifiers & lsp::kDeclaration) == 0);
    t = token_at(tokens, line_of(kDeck, "water"), 0);
    REQUIRE(t);
    CHECK(t->type == "string");
    t = token_at(tokens, line_of(kDeck, "      &rho"), 17);
    REQUIRE(t);
    CHECK(t->type == "parameter");
    t = token_at(tokens, line_of(kDeck, "R rho"), 3);
    REQUIRE(t);
    CHECK(t->type == "parameter");
    CHECK((t->modifiers & lsp::kDeclaration) != 0);
    // A range request colours only its lines; an unchanged delta has no edits.
    const auto part_only = decode(ask(deck, "textDocument/semanticTokens/range", {{"range", range(part, part)}}));
    REQUIRE_FALSE(part_only.empty());
    for (const auto& token : part_only) CHECK(token.line == part);
    auto full = ask(deck, "textDocument/semanticTokens/full", nlohmann::json::object());
    auto delta = ask(deck, "textDocument/semanticTokens/full/delta", {{"previousResultId", full["resultId"]}});
    CHECK(delta["edits"].empty());
    delta = ask(deck, "textDocument/semanticTokens/full/delta", {{"previousResultId", "other"}});
    CHECK(delta["data"] == full["data"]);
}

TEST_CASE("lsp semantic tokens on an OpenRadioss deck: headers, titles, ids, reals, comments") {
    const std::string rad = R"(#RADIOSS STARTER
/BEGIN
LSP
      2026
                  kg                  mm                  ms
                  kg                  mm                  ms
/PART/2
water
#  prop_ID    mat_ID subset_ID
         2         3         0
/END
)";
    const auto deck = check(rad, "lsp_0000.rad", std::nullopt);
    REQUIRE(deck.result.model.radioss);
    const auto tokens = decode(ask(deck, "textDocument/semanticTokens/full", nlohmann::json::object()));
    const Token* t = token_at(tokens, line_of(rad, "/PART/2"), 1);
    REQUIRE(t);
    CHECK(t->type == "keyword");
    t = token_at(tokens, line_of(rad, "water"), 1);
    REQUIRE(t);
    CHECK(t->type == "string");
    t = token_at(tokens, line_of(rad, "#  prop_ID"), 3);
    REQUIRE(t);
    CHECK(t->type == "comment");
    const std::uint32_t ids = line_of(rad, "         2         3         0");
    t = token_at(tokens, ids, 9);
    REQUIRE(t);
    CHECK(t->type == "variable");
    t = token_at(tokens, ids, 19);
    REQUIRE(t);
    CHECK((t->modifiers & lsp::kOddField) != 0);
}

TEST_CASE("lsp inlay hints: field names, blank defaults, parameter values; bulk blocks off by default") {
    const auto deck = check(kDeck);
    const std::uint32_t last = line_of(kDeck, "*END");
    auto hints = ask(deck, "textDocument/inlayHint", {{"range", range(0, last)}});
    const std::uint32_t control = line_of(kDeck, "         1         0   1.0e+20");
    auto labels = hint_labels(hints, control);
    CHECK(has(labels, "NCBS:"));
    CHECK(has(labels, "FORM:"));
    CHECK(labels.size() == 6);  // START and MAXV lie past the line's end
    labels = hint_labels(hints, line_of(kDeck, "         3                 0.2"));
    CHECK(std::any_of(labels.begin(), labels.end(), [](const std::string& l) { return l.rfind("CSLH=", 0) == 0; }));
    labels = hint_labels(hints, line_of(kDeck, "      &rho"));
    CHECK(has(labels, "= 1000"));
    CHECK(hint_labels(hints, line_of(kDeck, "       1           0.010")).empty());
    // The range limits them; the settings turn bulk blocks on, or every hint off.
    hints = ask(deck, "textDocument/inlayHint", {{"range", range(control, control)}});
    for (const auto& h : hints) CHECK(h["position"]["line"] == control);
    hints = ask(deck, "textDocument/inlayHint", {{"range", range(0, last)}, {"settings", {{"bulkBlocks", true}}}});
    CHECK(has(hint_labels(hints, line_of(kDeck, "       1           0.010")), "NID:"));
    hints = ask(deck, "textDocument/inlayHint", {{"range", range(0, last)}, {"settings", {{"enable", false}}}});
    CHECK(hints.empty());
}

TEST_CASE("lsp server: tokens legend, inlay hint settings from initializationOptions, watched include files") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "sphdeck_lsp_watched";
    fs::create_directories(dir);
    const std::string main_text = "*KEYWORD\n*INCLUDE\nsection.k\n*END\n";
    std::ofstream(dir / "main.k") << main_text;
    std::ofstream(dir / "section.k") << "*SECTION_SPH\n         3       1.2\n";
    const std::string uri = lsp::uri_from_path(dir / "main.k");
    const std::string include_uri = lsp::uri_from_path(dir / "section.k");
    const nlohmann::json init =
        test::request(1, "initialize",
                      {{"capabilities", {{"workspace", {{"didChangeWatchedFiles", {{"dynamicRegistration", true}}}}}}},
                       {"initializationOptions", {{"inlayHints", {{"enable", false}}}}}});
    // First pass: the include is fine. Then it is broken on disk and the watcher says so.
    auto served = test::serve(
        {init, test::notify("initialized"), test::did_open(uri, main_text),
         test::request(2, "textDocument/inlayHint", {{"textDocument", {{"uri", include_uri}}}, {"range", range(0, 2)}}),
         test::request(3, "shutdown"), test::notify("exit")});
    const auto capabilities = served.answer(1)["result"]["capabilities"];
    CHECK(capabilities["semanticTokensProvider"]["legend"]["tokenTypes"][0] == "keyword");
    CHECK(capabilities["semanticTokensProvider"]["range"] == true);
    CHECK(capabilities["inlayHintProvider"] == true);
    INFO(served.answer(2).dump());
    REQUIRE(served.answer(2)["result"].is_array());
    CHECK(served.answer(2)["result"].empty());
    bool registered = false;
    for (const auto& m : served.messages) registered |= m.value("method", "") == "client/registerCapability";
    CHECK(registered);

    // The include's file name is coloured as one.
    lsp::CheckedDeck on_disk;
    on_disk.main = dir / "main.k";
    on_disk.result = engine::check_file((dir / "main.k").string());
    const auto tokens = decode(ask(on_disk, "textDocument/semanticTokens/full", nlohmann::json::object()));
    const Token* name = token_at(tokens, 2, 0);
    REQUIRE(name);
    CHECK(name->type == "string");
    CHECK(name->length == 9);
    CHECK((name->modifiers & lsp::kInclude) != 0);
    // The include is broken on disk while the deck is open: the watcher's notice re-checks it.
    std::vector<nlohmann::json> published;
    lsp::Workspace workspace([&](const nlohmann::json& params) { published.push_back(params); });
    REQUIRE(workspace.open(uri, main_text, 1));
    workspace.flush();
    const auto bad_real =
        [&](const std::string& file_uri) {  // DK003 (not a number) in the last publication of the file
            nlohmann::json last;
            for (const auto& p : published)
                if (p["uri"] == file_uri) last = p["diagnostics"];
            return std::any_of(last.begin(), last.end(), [](const nlohmann::json& d) { return d["code"] == "DK003"; });
        };
    CHECK_FALSE(bad_real(include_uri));
    std::ofstream(dir / "section.k") << "*SECTION_SPH\n         3       abc\n";
    workspace.flush();
    CHECK_FALSE(bad_real(include_uri));  // nobody said the file changed
    CHECK(workspace.changed_on_disk(include_uri));
    workspace.flush();
    CHECK(bad_real(include_uri));
    fs::remove_all(dir);
}

TEST_CASE("lsp semantic tokens and inlay hints on every test deck: ordered, on the line, range equals full") {
    namespace fs = std::filesystem;
    std::size_t decks = 0;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(SPHDECK_SOURCE_DIR) / "decks" / "tests")) {
        const auto ext = entry.path().extension();
        if (!entry.is_regular_file() || (ext != ".k" && ext != ".rad")) continue;
        lsp::CheckedDeck deck;
        deck.main = entry.path();
        try {
            deck.result = engine::check_file(entry.path().string());
        } catch (const std::exception&) {
            continue;
        }
        ++decks;
        const auto& sources = deck.result.deck.sources;
        for (grammar::FileId file = 0; file < sources.size(); ++file) {
            INFO(entry.path().string() << " file " << file);
            const std::uint32_t lines = sources.line_count(file);
            const auto full =
                lsp::answer_feature("textDocument/semanticTokens/full", deck, file, nlohmann::json::object());
            const auto whole =
                lsp::answer_feature("textDocument/semanticTokens/range", deck, file, {{"range", range(0, lines)}});
            REQUIRE(full.result.contains("data"));
            CHECK(full.result["data"] == whole.result["data"]);
            const auto tokens = decode(full.result);
            for (std::size_t i = 0; i < tokens.size(); ++i) {
                const auto& t = tokens[i];
                CHECK(t.length > 0);
                CHECK(t.line < lines);
                CHECK(t.character + t.length <= sources.line_text(file, t.line + 1).size());  // ASCII decks
                if (i > 0 && tokens[i - 1].line == t.line)
                    CHECK(tokens[i - 1].character + tokens[i - 1].length <= t.character);
            }
            const auto hints = lsp::answer_feature("textDocument/inlayHint", deck, file,
                                                   {{"range", range(0, lines)}, {"settings", {{"bulkBlocks", true}}}});
            REQUIRE(hints.result.is_array());
            for (const auto& h : hints.result) {
                const auto line = h["position"]["line"].get<std::uint32_t>();
                CHECK(line < lines);
                CHECK(h["position"]["character"].get<std::size_t>() <= sources.line_text(file, line + 1).size());
            }
        }
    }
    CHECK(decks > 100);
}

TEST_CASE("lsp semantic tokens: a range inside a big *NODE block equals those lines of the full answer") {
    std::string text = "*KEYWORD\n*NODE\n";
    for (int n = 1; n <= 700; ++n) text += fmt::format("{:8d}{:16.3f}{:16.3f}{:16.3f}\n", n, n * 0.01, 0.5, 0.0);
    text += "*END\n";
    const auto deck = check(text);
    const auto full = decode(ask(deck, "textDocument/semanticTokens/full", nlohmann::json::object()));
    const auto part = decode(ask(deck, "textDocument/semanticTokens/range", {{"range", range(400, 409)}}));
    std::vector<Token> expected;
    for (const auto& t : full)
        if (t.line >= 400 && t.line <= 409) expected.push_back(t);
    REQUIRE(part.size() == expected.size());
    REQUIRE(part.size() == 40);  // NID, X, Y, Z on each of 10 lines
    for (std::size_t i = 0; i < part.size(); ++i) {
        CHECK(part[i].line == expected[i].line);
        CHECK(part[i].character == expected[i].character);
        CHECK(part[i].type == expected[i].type);
        CHECK(part[i].modifiers == expected[i].modifiers);
    }
    CHECK(part[0].type == "variable");
    CHECK(part[1].type == "real");
}

TEST_CASE("lsp signature help: the card's fields, the one under the cursor active (blank part included)") {
    const auto deck = check(kDeck);
    const std::uint32_t card = line_of(kDeck, "         1         0   1.0e+20");
    auto help = ask(deck, "textDocument/signatureHelp", {{"position", {{"line", card}, {"character", 53}}}});
    REQUIRE(help.is_object());
    const auto& sig = help["signatures"][0];
    CHECK(sig["label"].get<std::string>().rfind("*CONTROL_SPH", 0) == 0);
    REQUIRE(help.contains("activeParameter"));
    const auto active = help["activeParameter"].get<std::size_t>();
    const auto span = sig["parameters"][active]["label"];
    CHECK(sig["label"].get<std::string>().substr(span[0].get<std::size_t>(),
                                                 span[1].get<std::size_t>() - span[0].get<std::size_t>()) == "FORM");
    // Free format: the field after the commas typed so far.
    const std::string typing = "*KEYWORD\n*SECTION_SPH\n         3,\n*END\n";
    const auto typed = check(typing);
    help = ask(typed, "textDocument/signatureHelp", {{"position", {{"line", 2}, {"character", 11}}}});
    REQUIRE(help.is_object());
    CHECK(help["activeParameter"] == 1);  // after the comma: CSLH
    CHECK(ask(deck, "textDocument/signatureHelp",
              {{"position", {{"line", line_of(kDeck, "$#    ncbs")}, {"character", 3}}}})
              .is_null());
}

TEST_CASE("lsp definition, references and completion: every column of an id field, blank part included (issue 29)") {
    const auto deck = check(kDeck);
    const std::uint32_t part = line_of(kDeck, "         1         3         5         7");
    const std::uint32_t section = line_of(kDeck, "         3                 0.2");
    const std::uint32_t material = line_of(kDeck, "         5      &rho");
    // SECID: columns 11-20, "         3": every column leads to the section, blanks included.
    for (std::uint32_t character = 10; character < 20; ++character) {
        CAPTURE(character);
        auto location =
            ask(deck, "textDocument/definition", {{"position", {{"line", part}, {"character", character}}}});
        REQUIRE(location.is_object());
        CHECK(location["range"]["start"]["line"] == section);
    }
    // MID on its first blank column: the material; references of the section from a blank of SECID.
    auto location = ask(deck, "textDocument/definition", {{"position", {{"line", part}, {"character", 20}}}});
    REQUIRE(location.is_object());
    CHECK(location["range"]["start"]["line"] == material);
    auto refs = ask(deck, "textDocument/references",
                    {{"position", {{"line", part}, {"character", 12}}}, {"context", {{"includeDeclaration", false}}}});
    REQUIRE(refs.size() == 1);  // the part's SECID
    CHECK(refs[0]["range"]["start"]["line"] == part);
    // Completion on the blank part of SECID offers the sections (id 3), not the field before it.
    auto list = ask(deck, "textDocument/completion", {{"position", {{"line", part}, {"character", 12}}}});
    REQUIRE(list["items"].is_array());
    REQUIRE_FALSE(list["items"].empty());
    CHECK(list["items"][0]["label"] == "3");
    // Free format: the blank after a comma belongs to the field after it.
    const std::string free = "*KEYWORD\n*SECTION_SPH\n3\n*PART\nwater\n1,  3\n*END\n";
    const auto free_deck = check(free);
    location = ask(free_deck, "textDocument/definition", {{"position", {{"line", 5}, {"character", 3}}}});
    REQUIRE(location.is_object());
    CHECK(location["range"]["start"]["line"] == 2);
}
}  // namespace test_lsp_tokens_hints_cpp
