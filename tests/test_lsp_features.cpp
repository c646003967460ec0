// The editor server's request features (lsp/features.hpp) on small checked decks: hover,
// definition, references, completion, outline, folding and code actions, as LSP JSON.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"
#include "grammar/realign.hpp"
#include "lsp/uri.hpp"
#include "tests/lsp_radioss_deck.hpp"

namespace test_lsp_features_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// Line 0-based of the first line containing `needle` (after line `from`), and its column.
struct At {
    std::uint32_t line = 0, character = 0;
};
At find(const std::string& text, std::string_view needle, std::uint32_t from = 0) {
    std::uint32_t line = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string_view l(text.data() + start, end - start);
        if (line >= from)
            if (auto at = l.find(needle); at != std::string_view::npos) return {line, static_cast<std::uint32_t>(at)};
        start = end + 1;
        ++line;
    }
    FAIL("not found: " << needle);
    return {};
}

lsp::CheckedDeck check(const std::string& text, const std::string& name = "main.k",
                       std::optional<grammar::DeckFormat> format = grammar::DeckFormat::LsDyna) {
    lsp::CheckedDeck deck;
    deck.main = name;
    deck.result = engine::check_buffer(text, name, {}, format);
    return deck;
}

nlohmann::json position(At at) { return {{"line", at.line}, {"character", at.character}}; }

nlohmann::json ask(const lsp::CheckedDeck& deck, std::string_view method, nlohmann::json params) {
    auto answer = lsp::answer_feature(method, deck, 0, params);
    REQUIRE(answer.handled);
    return answer.result;
}

std::string hover_text(const lsp::CheckedDeck& deck, At at) {
    auto result = ask(deck, "textDocument/hover", {{"position", position(at)}});
    if (result.is_null()) return {};
    return result["contents"]["value"].get<std::string>();
}

std::vector<std::string> labels(const nlohmann::json& list) {
    std::vector<std::string> out;
    for (const auto& item : list["items"]) out.push_back(item["label"].get<std::string>());
    return out;
}

bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

// Applies TextEdits (ASCII text: characters are bytes), last first.
std::string apply(std::string text, nlohmann::json edits) {
    std::vector<nlohmann::json> sorted(edits.begin(), edits.end());
    std::sort(sorted.begin(), sorted.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
        auto key = [](const nlohmann::json& e) {
            return std::make_pair(e["range"]["start"]["line"].get<int>(), e["range"]["start"]["character"].get<int>());
        };
        return key(a) > key(b);
    });
    auto offset = [&](const nlohmann::json& p) {
        std::size_t at = 0;
        for (int l = 0; l < p["line"].get<int>(); ++l) at = text.find('\n', at) + 1;
        return at + p["character"].get<std::size_t>();
    };
    for (const auto& e : sorted) {
        const std::size_t begin = offset(e["range"]["start"]), end = offset(e["range"]["end"]);
        text.replace(begin, end - begin, e["newText"].get<std::string>());
    }
    return text;
}

// The diagnostics of a check as publishDiagnostics gives them (code, source, range).
std::vector<nlohmann::json> published(const lsp::CheckedDeck& deck) {
    std::vector<nlohmann::json> out;
    for (const auto& d : deck.result.diagnostics)
        out.push_back({{"range", lsp::range_json(deck.result.deck.sources, d.span)},
                       {"code", d.code},
                       {"source", "sphdeck"},
                       {"message", d.message}});
    return out;
}

std::size_t count_code(const lsp::CheckedDeck& deck, std::string_view code) {
    return static_cast<std::size_t>(std::count_if(deck.result.diagnostics.begin(), deck.result.diagnostics.end(),
                                                  [&](const diag::Diagnostic& d) { return d.code == code; }));
}

const std::string kDeck = R"(*KEYWORD
*PARAMETER
R rho         1000.0
*CONTROL_SPH
$#    ncbs     boxid        dt      idim    memory      form     start      maxv
         1         0   1.0e+20         3         0         1
*SECTION_SPH
$#   secid      cslh      hmin      hmax    sphini     death     start
         3       1.2       0.2       2.0       0.0   1.0e+20       0.0
*PART
$#                                                               title
water
$#     pid     secid       mid     eosid
         1         3         5         7
*MAT_NULL
$#     mid        ro
         5      &rho
*EOS_MURNAGHAN
$#   eosid     gamma        k0
         7       7.0  340000.0
*NODE
       1           0.010           0.030             0.0
       2           0.030           0.030             0.0
*ELEMENT_SPH
       1       1   0.001
       2       1   0.001
*END
)";

}  // namespace

TEST_CASE("lsp hover: a field's name, columns, default, allowed values and effective value") {
    const auto deck = check(kDeck);
    const At card = find(kDeck, "   1.0e+20         3");
    // FORM 1 written in columns 51-60.
    std::string text = hover_text(deck, {card.line, 59});
    CHECK(text.find("**FORM**") != std::string::npos);
    CHECK(text.find("columns 51-60") != std::string::npos);
    CHECK(text.find("default 0") != std::string::npos);
    CHECK(text.find("allowed values") != std::string::npos);
    CHECK(text.find("value: 1") != std::string::npos);
    // MEMORY written as 0, which means the default 150.
    text = hover_text(deck, {card.line, 49});
    CHECK(text.find("**MEMORY**") != std::string::npos);
    CHECK(text.find("value: 150 (default: 0 means the default)") != std::string::npos);
    // START left blank (the line stops before column 61).
    text = hover_text(deck, {card.line, 65});
    CHECK(text.find("**START**") != std::string::npos);
    CHECK(text.find("value: 0 (default: left blank)") != std::string::npos);
}

TEST_CASE("lsp hover: a value beyond any integer in a field with allowed values (issue 32)") {
    // FORM written as 1e20: the hover names the value without converting it to an integer (that
    // conversion is undefined behaviour; the sanitizer build of this test catches it).
    std::string deck_text = kDeck;
    const std::string form_one = "         0         1\n";
    deck_text.replace(deck_text.find(form_one), form_one.size(), "         0    1.0e20\n");
    const auto deck = check(deck_text);
    const At card = find(deck_text, "    1.0e20");
    const std::string text = hover_text(deck, {card.line, card.character + 5});
    CHECK(text.find("**FORM**") != std::string::npos);
    CHECK(text.find("allowed values") != std::string::npos);
}

TEST_CASE("lsp hover: keywords, ids and parameters") {
    const auto deck = check(kDeck);
    const At section = find(kDeck, "*SECTION_SPH");
    std::string text = hover_text(deck, section);
    CHECK(text.find("`*SECTION_SPH`") != std::string::npos);
    text = hover_text(deck, find(kDeck, "*CONTROL_SPH"));
    CHECK(text.find("cards:") != std::string::npos);
    CHECK(text.find(": NCBS, BOXID, DT, IDIM, MEMORY, FORM, START, MAXV") != std::string::npos);
    const At part = find(kDeck, "         1         3         5         7");
    text = hover_text(deck, {part.line, 19});  // SECID 3
    CHECK(text.find("**SECID**") != std::string::npos);
    CHECK(text.find("names SECTION 3: `*SECTION_SPH 3, line 9`") != std::string::npos);
    text = hover_text(deck, {part.line, 9});  // PID 1
    CHECK(text.find("defines PART 1") != std::string::npos);
    const At rho = find(kDeck, "&rho");
    text = hover_text(deck, {rho.line, rho.character + 2});
    CHECK(text.find("parameter **rho** = 1000") != std::string::npos);
    CHECK(hover_text(deck, {find(kDeck, "R rho").line, 3}).find("parameter **rho** = 1000 (real)") !=
          std::string::npos);
    // A comment line says nothing.
    CHECK(ask(deck, "textDocument/hover", {{"position", position(find(kDeck, "$#   secid"))}}).is_null());
}

TEST_CASE("lsp definition and references: part -> section, material, EOS; parameters") {
    const auto deck = check(kDeck);
    const At part = find(kDeck, "         1         3         5         7");
    auto location = ask(deck, "textDocument/definition", {{"position", position({part.line, 29})}});  // MID 5
    REQUIRE(location.is_object());
    CHECK(location["range"]["start"]["line"] == find(kDeck, "         5      &rho").line);
    CHECK(location["uri"].get<std::string>().find("main.k") != std::string::npos);
    location = ask(deck, "textDocument/definition", {{"position", position({part.line, 39})}});  // EOSID 7
    CHECK(location["range"]["start"]["line"] == find(kDeck, "         7       7.0").line);
    const At rho = find(kDeck, "&rho");
    location = ask(deck, "textDocument/definition", {{"position", position({rho.line, rho.character + 1})}});
    CHECK(location["range"]["start"]["line"] == find(kDeck, "R rho").line);
    // From the definition's name: its one use, and itself with the declaration.
    auto uses =
        ask(deck, "textDocument/references",
            {{"position", position({find(kDeck, "R rho").line, 3})}, {"context", {{"includeDeclaration", true}}}});
    REQUIRE(uses.size() == 2);
    CHECK(uses[0]["range"]["start"]["line"] == rho.line);

    // Part 1: named by the PID of both particles.
    auto refs = ask(deck, "textDocument/references",
                    {{"position", position({part.line, 9})}, {"context", {{"includeDeclaration", false}}}});
    CHECK(refs.size() == 2);
    refs = ask(deck, "textDocument/references",
               {{"position", position({part.line, 9})}, {"context", {{"includeDeclaration", true}}}});
    CHECK(refs.size() == 3);
    // A particle's NID -> its *NODE line (with the node's coordinates in the hover); node 2 is
    // named by particle 2.
    const At particle = find(kDeck, "       1       1   0.001");
    location = ask(deck, "textDocument/definition", {{"position", position({particle.line, 7})}});
    CHECK(location["range"]["start"]["line"] == find(kDeck, "       1           0.010").line);
    CHECK(hover_text(deck, {particle.line, 7}).find("names NODE 1: `node 1 at (0.01, 0.03, 0), line 22`") !=
          std::string::npos);
    const At node2 = find(kDeck, "       2           0.030");
    refs = ask(deck, "textDocument/references",
               {{"position", position({node2.line, 7})}, {"context", {{"includeDeclaration", false}}}});
    REQUIRE(refs.size() == 1);
    CHECK(refs[0]["range"]["start"]["line"] == find(kDeck, "       2       1   0.001").line);
    // Section 3 from its definition: the part's SECID.
    const At secid = find(kDeck, "         3       1.2");
    refs = ask(deck, "textDocument/references",
               {{"position", position({secid.line, 9})}, {"context", {{"includeDeclaration", false}}}});
    REQUIRE(refs.size() == 1);
    CHECK(refs[0]["range"]["start"]["line"] == part.line);
    CHECK(refs[0]["range"]["start"]["character"] == 19);
}

TEST_CASE("lsp completion: keyword names, enum values, ids that exist") {
    const std::string typing = kDeck + "*CONTROL_S\n";
    const auto deck = check(typing);
    const At keyword = find(typing, "*CONTROL_S", find(typing, "*END").line);
    auto list = ask(deck, "textDocument/completion", {{"position", position({keyword.line, 10})}});
    auto names = labels(list);
    CHECK(has(names, "*CONTROL_SPH"));
    CHECK_FALSE(has(names, "*SECTION_SPH"));
    // Every name starting "*C" is more than the list holds.
    const std::string many = kDeck + "*C\n";
    const auto many_deck = check(many);
    list = ask(many_deck, "textDocument/completion", {{"position", position({find(many, "*END").line + 1, 2})}});
    CHECK(list["isIncomplete"] == true);
    CHECK(list["items"].size() == 200);

    const At card = find(kDeck, "   1.0e+20         3");
    list = ask(deck, "textDocument/completion", {{"position", position({card.line, 59})}});  // FORM
    names = labels(list);
    CHECK(has(names, "0"));
    CHECK(has(names, "1"));
    const At part = find(kDeck, "         1         3         5         7");
    list = ask(deck, "textDocument/completion", {{"position", position({part.line, 19})}});  // SECID
    names = labels(list);
    REQUIRE(names.size() == 1);
    CHECK(names[0] == "3");
}

TEST_CASE("lsp on an OpenRadioss deck: generated layouts hover and complete") {
    const std::string rad = R"(#RADIOSS STARTER
/BEGIN
LSP
      2026
                  kg                  mm                  ms
                  kg                  mm                  ms
/SHELL/1
         7         1         2         3         4
/SHE
/END
)";
    const auto deck = check(rad, "lsp_0000.rad", std::nullopt);
    const At shell = find(rad, "         7         1");
    const std::string text = hover_text(deck, {shell.line, 15});
    CHECK(text.find("**node_ID1** (`/SHELL`") != std::string::npos);
    const At typing = find(rad, "/SHE", shell.line);
    auto names = labels(ask(deck, "textDocument/completion", {{"position", position({typing.line, 4})}}));
    CHECK(has(names, "/SHELL"));
}

TEST_CASE("lsp outline and folding: one symbol and one range per keyword block, parts as children") {
    const auto deck = check(kDeck);
    auto symbols = ask(deck, "textDocument/documentSymbol", nlohmann::json::object());
    REQUIRE(symbols.size() == deck.result.deck.blocks.size());
    const auto part = std::find_if(symbols.begin(), symbols.end(), [](const auto& s) { return s["name"] == "*PART"; });
    REQUIRE(part != symbols.end());
    REQUIRE((*part)["children"].size() == 1);
    CHECK((*part)["children"][0]["name"] == "part 1");
    CHECK((*part)["children"][0]["detail"] == "water");
    auto folds = ask(deck, "textDocument/foldingRange", nlohmann::json::object());
    const At control = find(kDeck, "*CONTROL_SPH");
    const bool found = std::any_of(folds.begin(), folds.end(), [&](const auto& f) {
        return f["startLine"] == control.line && f["endLine"] == control.line + 2;
    });
    CHECK(found);
}

TEST_CASE("lsp code actions: suppression comments and the realignment of a value over its columns") {
    // ENDTIM "1.0E-3" starts in column 7 of its 10 columns: the field holds "1.0E" and ENDCYC "-3", one
    // value pushed across its field's end (DK029, the DK003 folded into it), whose fix moves the line back.
    const std::string text = "*KEYWORD\n*CONTROL_TERMINATION\n      1.0E-3\n*END\n";
    const auto deck = check(text);
    REQUIRE(count_code(deck, "DK029") == 1);
    nlohmann::json diagnostic;
    for (const auto& d : published(deck))
        if (d["code"] == "DK029") diagnostic = d;
    auto actions = ask(deck, "textDocument/codeAction",
                       {{"textDocument", {{"uri", "file:///tmp/main.k"}}},
                        {"range", diagnostic["range"]},
                        {"context", {{"diagnostics", {diagnostic}}}}});
    REQUIRE(actions.size() == 3);
    for (const auto& a : actions) {
        CHECK(a["kind"] == "quickfix");
        CHECK(a["diagnostics"][0]["code"] == "DK029");
        REQUIRE(a["edit"]["changes"].contains("file:///tmp/main.k"));
    }
    auto edited = [&](std::size_t i) { return apply(text, actions[i]["edit"]["changes"]["file:///tmp/main.k"]); };

    CHECK(actions[0]["title"] == "Move the line 2 columns left: '1.0E-3' then ends at column 10, the end of ENDTIM");
    CHECK(edited(0) == "*KEYWORD\n*CONTROL_TERMINATION\n    1.0E-3\n*END\n");
    auto fixed = check(edited(0));
    CHECK(count_code(fixed, "DK029") == 0);
    CHECK(fixed.result.model.controls.endtim.value == doctest::Approx(1.0e-3));

    CHECK(actions[1]["title"] == "Suppress DK029 for this card");
    CHECK(edited(1) == "*KEYWORD\n*CONTROL_TERMINATION\n$ sphdeck: disable=DK029\n      1.0E-3\n*END\n");
    auto silenced = check(edited(1));
    CHECK(count_code(silenced, "DK029") == 0);
    CHECK(count_code(silenced, "DK026") == 0);

    CHECK(actions[2]["title"] == "Suppress DK029 in this file");
    CHECK(edited(2) == "$ sphdeck: disable-file=DK029\n" + text);
    silenced = check(edited(2));
    CHECK(count_code(silenced, "DK029") == 0);
    CHECK(count_code(silenced, "DK026") == 0);

    // A second code joins the file's directive instead of adding a line.
    const std::string with_directive = "$ sphdeck: disable-file=DK003 -- legacy\n" + text.substr(0);
    const auto deck2 = check(with_directive + "");
    nlohmann::json other = {{"range",
                             {{"start", {{"line", 3}, {"character", 0}}}, {"end", {{"line", 3}, {"character", 1}}}}},
                            {"code", "DK004"},
                            {"source", "sphdeck"}};
    actions = ask(deck2, "textDocument/codeAction",
                  {{"textDocument", {{"uri", "file:///tmp/main.k"}}}, {"context", {{"diagnostics", {other}}}}});
    REQUIRE(actions.size() == 2);
    CHECK(apply(with_directive, actions[1]["edit"]["changes"]["file:///tmp/main.k"])
              .rfind("$ sphdeck: disable-file=DK003,DK004 -- legacy\n", 0) == 0);
    // And one above the card.
    const std::string with_card_directive =
        "*KEYWORD\n$ sphdeck: disable=DK002\n*CONTROL_TERMINATION\n      1.0E-3\n*END\n";
    const auto deck3 = check(with_card_directive);
    other["range"]["start"]["line"] = 2;
    actions = ask(deck3, "textDocument/codeAction",
                  {{"textDocument", {{"uri", "file:///tmp/main.k"}}}, {"context", {{"diagnostics", {other}}}}});
    REQUIRE(actions.size() == 2);
    CHECK(actions[0]["title"] == "Suppress DK004 for this keyword block");
    CHECK(apply(with_card_directive, actions[0]["edit"]["changes"]["file:///tmp/main.k"]) ==
          "*KEYWORD\n$ sphdeck: disable=DK002,DK004\n*CONTROL_TERMINATION\n      1.0E-3\n*END\n");
}

TEST_CASE("lsp code actions: a finding's own fix (DK029: the shifted line moved back)") {
    const std::string text = "*KEYWORD\n*CONTROL_TERMINATION\n       1.0E-3         0       0.0\n*END\n";
    const auto deck = check(text);
    REQUIRE(count_code(deck, "DK029") == 1);
    nlohmann::json diagnostic;
    for (const auto& d : published(deck))
        if (d["code"] == "DK029") diagnostic = d;
    auto actions = ask(deck, "textDocument/codeAction",
                       {{"textDocument", {{"uri", "file:///tmp/main.k"}}},
                        {"range", diagnostic["range"]},
                        {"context", {{"diagnostics", {diagnostic}}}}});
    REQUIRE(actions.size() == 3);  // the fix, then the two suppressions
    CHECK(actions[0]["title"] == "Move the values 3 columns left into their fields");
    CHECK(actions[0]["isPreferred"] == true);
    const std::string edited = apply(text, actions[0]["edit"]["changes"]["file:///tmp/main.k"]);
    CHECK(edited == "*KEYWORD\n*CONTROL_TERMINATION\n    1.0E-3         0       0.0\n*END\n");
    auto fixed = check(edited);
    CHECK(fixed.result.diagnostics.empty());
    CHECK(fixed.result.model.controls.endtim.value == doctest::Approx(1.0e-3));
}

TEST_CASE("lsp realign: only when the result is certain") {
    keywords::CardSpec card{.fields = {{.name = "A", .column = 1, .width = 10, .type = keywords::FieldType::Real},
                                       {.name = "B", .column = 11, .width = 10, .type = keywords::FieldType::Real}}};
    using grammar::CardFormat;
    CHECK(grammar::realign_card("      1.0E-3      2.5", card, CardFormat::Standard) == "    1.0E-3       2.5");
    CHECK_FALSE(grammar::realign_card("       1.0       2.0", card, CardFormat::Standard));  // nothing strays
    CHECK_FALSE(grammar::realign_card("   1.23456789012", card, CardFormat::Standard));      // wider than its field
    CHECK_FALSE(grammar::realign_card("       1.0E-3", card, CardFormat::Standard));         // 3 and 3 columns: a tie
    CHECK_FALSE(grammar::realign_card("      1.0,2.0", card, CardFormat::Standard));         // free format
    CHECK_FALSE(grammar::realign_card("   1.0 2.0  3.0", card, CardFormat::Standard));       // two values for one field
}

TEST_CASE("lsp features on an OpenRadioss deck: header hover, field hover, /PART -> /PROP, /MAT") {
    const std::string rad{test::lsp_radioss_deck};
    const auto deck = check(rad, "lsp_0000.rad", std::nullopt);
    REQUIRE(deck.result.model.radioss);
    const At prop = find(rad, "/PROP/SPH/2");
    std::string text = hover_text(deck, prop);
    CHECK(text.find("`/PROP/SPH`") != std::string::npos);
    const At ids = find(rad, "         2         3         0");
    text = hover_text(deck, {ids.line, 9});
    CHECK(text.find("**prop_ID**") != std::string::npos);
    CHECK(text.find("names PROP 2") != std::string::npos);
    const At h = find(rad, "         0                 2.4");
    text = hover_text(deck, {h.line, 15});  // in h's cell, on a blank before the value
    CHECK(text.find("**h** (`/PROP/SPH`, format 2026): real, columns 11-30") != std::string::npos);
    CHECK(text.find("value: 2.4") != std::string::npos);
    auto location = ask(deck, "textDocument/definition", {{"position", position({ids.line, 9})}});
    CHECK(location["range"]["start"]["line"] == prop.line);
    location = ask(deck, "textDocument/definition", {{"position", position({ids.line, 19})}});
    CHECK(location["range"]["start"]["line"] == find(rad, "/MAT/LAW6/3").line);
    // Part 2 is named by /SPHCEL/2's header.
    const At part = find(rad, "/PART/2");
    auto refs = ask(deck, "textDocument/references",
                    {{"position", position({part.line, 6})}, {"context", {{"includeDeclaration", false}}}});
    REQUIRE(refs.size() == 1);
    CHECK(refs[0]["range"]["start"]["line"] == find(rad, "/SPHCEL/2").line);
    // A cell's node_ID -> its /NODE line.
    const At cell = find(rad, "      1001         0");
    location = ask(deck, "textDocument/definition", {{"position", position({cell.line, 8})}});
    CHECK(location["range"]["start"]["line"] == find(rad, "      1001                 1.0").line);
    auto symbols = ask(deck, "textDocument/documentSymbol", nlohmann::json::object());
    CHECK(symbols.size() == deck.result.deck.blocks.size());
    // A suppression in a Radioss deck uses '#', after the #RADIOSS line.
    nlohmann::json d = {
        {"range", {{"start", {{"line", ids.line}, {"character", 0}}}, {"end", {{"line", ids.line}, {"character", 1}}}}},
        {"code", "RAD001"},
        {"source", "sphdeck"}};
    auto actions = ask(deck, "textDocument/codeAction",
                       {{"textDocument", {{"uri", "file:///tmp/lsp_0000.rad"}}}, {"context", {{"diagnostics", {d}}}}});
    REQUIRE(actions.size() == 2);
    CHECK(actions[0]["edit"]["changes"]["file:///tmp/lsp_0000.rad"][0]["newText"] == "# sphdeck: disable=RAD001\n");
    CHECK(actions[1]["edit"]["changes"]["file:///tmp/lsp_0000.rad"][0]["range"]["start"]["line"] == 1);
}

TEST_CASE("lsp hover on /INISPHCEL/FULL: the LIST lines of nvarsph values, then the next particle") {
    // Particle 1001 has nvarsph 7: two lines of values (5 + 2) follow its Epsp card; 1002 has none.
    const std::string rad = R"(#RADIOSS STARTER
/BEGIN
LSP
      2026
                  kg                  mm                  ms
                  kg                  mm                  ms
/INISPHCEL/FULL
      1001         7
                 5.0              1.0E-6                 2.4
                -1.0                -2.0                -3.0
                 0.1
                11.0                12.0                13.0                14.0                15.0
                16.0                17.0
      1002         0
                 6.0              2.0E-6                 3.0
                -4.0
                 0.2
      1003         0
/END
)";
    const auto deck = check(rad, "lsp_0000.rad", std::nullopt);
    REQUIRE(deck.result.model.radioss);
    std::string text = hover_text(deck, {find(rad, "                11.0").line, 15});
    CHECK(text.find("**V** (`/INISPHCEL`, format 2024): real, columns 1-20") != std::string::npos);
    text = hover_text(deck, {find(rad, "                16.0").line, 30});
    CHECK(text.find("**V** (`/INISPHCEL`, format 2024): real, columns 21-40") != std::string::npos);
    text = hover_text(deck, {find(rad, "      1002").line, 8});
    CHECK(text.find("**sphcel_ID**") != std::string::npos);
    text = hover_text(deck, {find(rad, "      1002").line, 18});
    CHECK(text.find("**nvarsph**") != std::string::npos);
    text = hover_text(deck, {find(rad, "                -4.0").line, 15});
    CHECK(text.find("**Sigma1**") != std::string::npos);
    text = hover_text(deck, {find(rad, "                 0.2").line, 15});
    CHECK(text.find("**Epsp**") != std::string::npos);
    // nvarsph 0: no LIST line, the next particle follows Epsp.
    text = hover_text(deck, {find(rad, "      1003").line, 8});
    CHECK(text.find("**sphcel_ID**") != std::string::npos);
}

TEST_CASE("lsp features: the server's table answers every feature and announces it") {
    const auto capabilities = lsp::feature_capabilities();
    for (const char* key : {"hoverProvider", "definitionProvider", "referencesProvider", "completionProvider",
                            "documentSymbolProvider", "foldingRangeProvider", "codeActionProvider"})
        CHECK(capabilities.contains(key));
    const auto deck = check(kDeck);
    CHECK_FALSE(lsp::answer_feature("textDocument/typeDefinition", deck, 0, nlohmann::json::object()).handled);
    // A request without a position is answered, with nothing.
    CHECK(ask(deck, "textDocument/hover", nlohmann::json::object()).is_null());
    CHECK(ask(deck, "textDocument/definition", {{"position", "x"}}).is_null());
}

TEST_CASE("lsp definition: an *INCLUDE file name opens the file; ids defined in an include") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "sphdeck_lsp_features_include";
    fs::create_directories(dir);
    const std::string main_text = "*KEYWORD\n*INCLUDE\nsection.k\n*PART\nwater\n         1         3         5\n*END\n";
    {
        std::ofstream(dir / "main.k") << main_text;
        std::ofstream(dir / "section.k") << "*KEYWORD\n*SECTION_SPH\n         3       1.2\n*END\n";
    }
    lsp::CheckedDeck deck;
    deck.main = dir / "main.k";
    deck.result = engine::check_file((dir / "main.k").string());
    REQUIRE(deck.result.deck.sources.size() == 2);
    auto location = ask(deck, "textDocument/definition", {{"position", position(find(main_text, "section.k"))}});
    CHECK(location["uri"] == lsp::uri_from_path(dir / "section.k"));
    CHECK(location["range"]["start"]["line"] == 0);
    CHECK(hover_text(deck, find(main_text, "section.k"))
              .find("includes `" + (dir / "section.k").string() + "` (4 lines)") != std::string::npos);
    const At part = find(main_text, "         1         3");
    location = ask(deck, "textDocument/definition", {{"position", position({part.line, 19})}});
    CHECK(location["uri"] == lsp::uri_from_path(dir / "section.k"));
    CHECK(location["range"]["start"]["line"] == 2);
    // A request about the include file itself.
    auto hover = lsp::answer_feature("textDocument/hover", deck, 1, {{"position", {{"line", 2}, {"character", 9}}}});
    REQUIRE(hover.result.is_object());
    CHECK(hover.result["contents"]["value"].get<std::string>().find("**SECID**") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("lsp definition: ids named by the generated layouts (a *LOAD_BODY_Z curve)") {
    const std::string text =
        "*KEYWORD\n*DEFINE_CURVE\n         9\n       0.0       1.0\n*LOAD_BODY_Z\n         9\n*END\n";
    const auto deck = check(text);
    const At load = find(text, "         9", find(text, "*LOAD_BODY_Z").line);
    auto location = ask(deck, "textDocument/definition", {{"position", position({load.line, 9})}});
    REQUIRE(location.is_object());
    CHECK(location["range"]["start"]["line"] == 2);
    auto refs = ask(deck, "textDocument/references",
                    {{"position", position({2, 9})}, {"context", {{"includeDeclaration", false}}}});
    REQUIRE(refs.size() == 1);
    CHECK(refs[0]["range"]["start"]["line"] == load.line);
    CHECK(hover_text(deck, {load.line, 9}).find("names DEFINE_CURVE 9") != std::string::npos);
}

TEST_CASE("lsp features: every request on every line of the test decks answers valid JSON") {
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
            continue;  // a deck the tests expect to be refused
        }
        ++decks;
        const auto& sources = deck.result.deck.sources;
        nlohmann::json diagnostics = nlohmann::json::array();
        for (const auto& d : deck.result.diagnostics)
            if (d.span.valid() && d.span.file == 0)
                diagnostics.push_back({{"range", lsp::range_json(sources, d.span)}, {"code", d.code}});
        // One check per deck: the answers' JSON must dump (strictly: valid UTF-8) and be handled.
        std::size_t failed = 0;
        for (grammar::FileId file = 0; file < sources.size(); ++file) {
            const std::uint32_t lines = sources.line_count(file);
            int renames = 0;
            for (std::uint32_t line = 0; line <= lines; ++line)
                for (std::uint32_t character : {0u, 9u, 19u, 200u}) {
                    const nlohmann::json params = {{"position", {{"line", line}, {"character", character}}},
                                                   {"context", {{"includeDeclaration", true}}}};
                    for (const char* method : {"textDocument/hover", "textDocument/definition",
                                               "textDocument/references", "textDocument/completion"}) {
                        try {
                            auto answer = lsp::answer_feature(method, deck, file, params);
                            failed += !answer.handled || answer.result.dump().empty();
                        } catch (const std::exception&) {
                            ++failed;
                        }
                    }
                    // Rename: a refusal is a FeatureError with its reason; a few renames a file are carried out.
                    try {
                        auto prepared = lsp::answer_feature("textDocument/prepareRename", deck, file, params);
                        failed += !prepared.handled || prepared.result.dump().empty();
                        if (!prepared.result.is_null() && renames < 3) {
                            ++renames;
                            nlohmann::json with_name = params;
                            with_name["newName"] = "77";
                            auto renamed = lsp::answer_feature("textDocument/rename", deck, file, with_name);
                            failed += !renamed.result.contains("changes");
                        }
                    } catch (const lsp::FeatureError& e) {
                        failed += std::string(e.what()).empty();
                    } catch (const std::exception&) {
                        ++failed;
                    }
                }
            for (const char* method : {"textDocument/documentSymbol", "textDocument/foldingRange",
                                       "textDocument/documentLink", "textDocument/codeLens"})
                try {
                    failed += lsp::answer_feature(method, deck, file, nlohmann::json::object()).result.dump().empty();
                } catch (const std::exception&) {
                    ++failed;
                }
        }
        auto actions =
            lsp::answer_feature("textDocument/codeAction", deck, 0, {{"context", {{"diagnostics", diagnostics}}}});
        CHECK_MESSAGE(failed == 0, entry.path().string());
        CHECK(actions.result.is_array());
    }
    CHECK(decks > 100);
}

TEST_CASE("lsp features: Latin-1 deck text reaches the client as UTF-8") {
    std::string text = kDeck;
    text.replace(text.find("water"), 5, "d\xE9p\xF4t");
    const auto deck = check(text);
    const At part = find(text, "         1         3         5         7");
    const std::string hover = hover_text(deck, {part.line, 19});
    CHECK_NOTHROW((void)nlohmann::json(hover).dump());
    const At particle = find(text, "       1       1   0.001");
    CHECK(hover_text(deck, {particle.line, 15}).find("\"d\xC3\xA9p\xC3\xB4t\"") != std::string::npos);
    auto symbols = ask(deck, "textDocument/documentSymbol", nlohmann::json::object());
    CHECK_NOTHROW((void)symbols.dump());
    // A surrogate's bytes (ED A0 80) are no UTF-8: three Latin-1 characters.
    CHECK(lsp::display_text("a\xC3\xA9\xE9\xED\xA0\x80") == "a\xC3\xA9\xC3\xA9\xC3\xAD\xC2\xA0\xC2\x80");
    CHECK(lsp::display_text("\xED\x9F\xBF") == "\xED\x9F\xBF");  // U+D7FF, the last before the surrogates
}
}  // namespace test_lsp_features_cpp
