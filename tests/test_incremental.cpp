// Issue 29 item 5: the editor's re-check after an edit (engine/recheck.hpp, lsp::Workspace) keeps
// what the last check computed and the edit left alone, and its findings equal a full check of the
// same text: message, code, range, severity and order, on random edits of several decks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "engine/check.hpp"
#include "engine/preview_reuse.hpp"
#include "engine/recheck.hpp"
#include "grammar/deck_splice.hpp"
#include "grammar/read_deck.hpp"
#include "text/text_file.hpp"
#include "workspace_check.hpp"
#include "lsp/uri.hpp"
#include "lsp/workspace.hpp"
#include "same_model.hpp"
#include "test_support.hpp"

namespace test_incremental_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

const std::filesystem::path kSource = SPHDECK_SOURCE_DIR;

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string::npos) {
            lines.push_back(text.substr(start));
            return lines;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
}

std::string join_lines(const std::vector<std::string>& lines) {
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (i) out += '\n';
        out += lines[i];
    }
    return out;
}

// The lines of the bulk blocks (*NODE, *ELEMENT_SPH) and the keyword lines of `lines`.
struct Places {
    std::vector<std::uint32_t> bulk, keywords;
};
Places places_of(const std::vector<std::string>& lines) {
    Places out;
    bool bulk = false;
    for (std::uint32_t i = 0; i < lines.size(); ++i) {
        if (!lines[i].empty() && lines[i][0] == '*') {
            out.keywords.push_back(i);
            bulk = lines[i].rfind("*NODE", 0) == 0 || lines[i].rfind("*ELEMENT_SPH", 0) == 0;
        } else if (bulk && !lines[i].empty() && lines[i][0] != '$') {
            out.bulk.push_back(i);
        }
    }
    return out;
}

// One random edit of `lines` as an LSP change; `lines` becomes the edited text. `outside_bulk`: on a
// line of the small blocks (a title, a setting: the bulk blocks' columns are then taken whole).
nlohmann::json random_edit(std::vector<std::string>& lines, std::mt19937& random, bool outside_bulk = false) {
    const auto pick = [&](std::size_t n) {
        return static_cast<std::uint32_t>(std::uniform_int_distribution<std::size_t>(0, n - 1)(random));
    };
    const Places places = places_of(lines);
    // Where: anywhere, inside a bulk block, or on or next to a keyword line.
    std::uint32_t line = pick(lines.size());
    const std::uint32_t where = pick(3);
    if (where == 1 && !places.bulk.empty()) line = places.bulk[pick(places.bulk.size())];
    if (where == 2 && !places.keywords.empty())
        line = std::min<std::uint32_t>(places.keywords[pick(places.keywords.size())] + pick(3),
                                       static_cast<std::uint32_t>(lines.size() - 1));
    if (outside_bulk) {
        std::vector<std::uint32_t> small;
        for (std::uint32_t i = 0; i < lines.size(); ++i)
            if (!std::binary_search(places.bulk.begin(), places.bulk.end(), i) &&
                !std::binary_search(places.keywords.begin(), places.keywords.end(), i))
                small.push_back(i);
        if (!small.empty()) line = small[pick(small.size())];
    }
    static const std::vector<std::string> pieces = {"0",     "1",        "7",         "-1",  "2.5e-3", " ",
                                                    "     ", "12345678", "&rho",      "abc", ",",      "1.0e+20",
                                                    "*NODE", "*PART",    "$ comment", ""};
    const auto range = [](std::uint32_t l1, std::uint32_t c1, std::uint32_t l2, std::uint32_t c2) {
        return nlohmann::json{{"start", {{"line", l1}, {"character", c1}}}, {"end", {{"line", l2}, {"character", c2}}}};
    };
    std::string& text = lines[line];
    switch (pick(7)) {
        case 0: {  // replace a few characters of the line
            const std::uint32_t from = text.empty() ? 0 : pick(text.size() + 1);
            const std::uint32_t to = std::min<std::uint32_t>(static_cast<std::uint32_t>(text.size()), from + pick(12));
            const std::string piece = pieces[pick(pieces.size())];
            text = text.substr(0, from) + piece + text.substr(to);
            return {{"range", range(line, from, line, to)}, {"text", piece}};
        }
        case 1: {  // one digit of the line changed (a coordinate, an id, a mass)
            std::vector<std::uint32_t> digits;
            for (std::uint32_t i = 0; i < text.size(); ++i)
                if (text[i] >= '0' && text[i] <= '9') digits.push_back(i);
            const std::uint32_t at = digits.empty() ? 0 : digits[pick(digits.size())];
            const std::string digit(1, static_cast<char>('0' + pick(10)));
            const std::uint32_t end = digits.empty() ? 0 : at + 1;
            text = text.substr(0, at) + digit + text.substr(end);
            return {{"range", range(line, at, line, end)}, {"text", digit}};
        }
        case 2: {  // a whole line deleted
            if (lines.size() < 3 || line + 1 >= lines.size()) return nlohmann::json();
            lines.erase(lines.begin() + line);
            return {{"range", range(line, 0, line + 1, 0)}, {"text", ""}};
        }
        case 3: {  // a copy of another line inserted (a node or particle twice, a card too many)
            const std::string copy = lines[pick(lines.size())];
            lines.insert(lines.begin() + line, copy);
            return {{"range", range(line, 0, line, 0)}, {"text", copy + "\n"}};
        }
        case 4: {  // a keyword line inserted: a block split in two, a bulk block cut short
            static const std::vector<std::string> keywords = {"*NODE",        "*ELEMENT_SPH", "*PART",
                                                              "*SECTION_SPH", "*CONTROL_SPH", "*MAT_NULL"};
            const std::string keyword = keywords[pick(keywords.size())];
            lines.insert(lines.begin() + line, keyword);
            return {{"range", range(line, 0, line, 0)}, {"text", keyword + "\n"}};
        }
        case 5: {  // a keyword line retyped: a letter or its end changed (its block read as another)
            if (places.keywords.empty()) return nlohmann::json();
            const std::uint32_t at = places.keywords[pick(places.keywords.size())];
            std::string& keyword = lines[at];
            const std::uint32_t column = 1 + pick(keyword.size() > 1 ? keyword.size() - 1 : 1);
            const std::string piece = pick(2) ? std::string("_X") : std::string();
            const std::uint32_t end = std::min<std::uint32_t>(static_cast<std::uint32_t>(keyword.size()), column + 1);
            keyword = keyword.substr(0, column) + piece + keyword.substr(end);
            return {{"range", range(at, column, at, end)}, {"text", piece}};
        }
        default: {  // text across lines removed, keyword lines included
            const std::uint32_t last =
                std::min<std::uint32_t>(static_cast<std::uint32_t>(lines.size() - 1), line + 1 + pick(4));
            const std::uint32_t from =
                std::min<std::uint32_t>(pick(11), static_cast<std::uint32_t>(lines[line].size()));
            const std::uint32_t to = std::min<std::uint32_t>(pick(11), static_cast<std::uint32_t>(lines[last].size()));
            lines[line] = lines[line].substr(0, from) + lines[last].substr(to);
            lines.erase(lines.begin() + line + 1, lines.begin() + last + 1);
            return {{"range", range(line, from, last, to)}, {"text", ""}};
        }
    }
}

// One digit of a random line of a bulk block changed to another digit, as an LSP change.
nlohmann::json digit_edit_in_bulk(std::vector<std::string>& lines, std::mt19937& random) {
    const auto pick = [&](std::size_t n) {
        return static_cast<std::uint32_t>(std::uniform_int_distribution<std::size_t>(0, n - 1)(random));
    };
    const std::vector<std::uint32_t> bulk = places_of(lines).bulk;
    if (bulk.empty()) return nlohmann::json();
    const std::uint32_t line = bulk[pick(bulk.size())];
    std::string& text = lines[line];
    std::vector<std::uint32_t> digits;
    for (std::uint32_t i = 0; i < text.size(); ++i)
        if (text[i] >= '0' && text[i] <= '9') digits.push_back(i);
    if (digits.empty()) return nlohmann::json();
    const std::uint32_t at = digits[pick(digits.size())];
    text[at] = static_cast<char>('0' + (text[at] - '0' + 1 + pick(9)) % 10);
    return {{"range",
             {{"start", {{"line", line}, {"character", at}}}, {"end", {{"line", line}, {"character", at + 1}}}}},
            {"text", std::string(1, text[at])}};
}

// A deck of n x n particles in a plane (a bulk *NODE and *ELEMENT_SPH), with a title and controls.
std::string lattice_deck(int n) {
    std::string deck =
        "*KEYWORD\n*CONTROL_SPH\n         1         0   1.0e+20         2       150         0\n*SECTION_SPH\n"
        "         1       1.2       0.2       2.0\n*PART\nwater\n         1         1         1         1\n"
        "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0  357142.9       1.0\n*NODE\n";
    char line[96];
    for (int i = 0; i < n * n; ++i) {
        std::snprintf(line, sizeof line, "%8d%16.8e%16.8e%16.8e\n", i + 1, 0.01 * (i % n), 0.01 * (i / n), 0.0);
        deck += line;
    }
    deck += "*ELEMENT_SPH\n";
    for (int i = 0; i < n * n; ++i) {
        std::snprintf(line, sizeof line, "%8d%8d%16.8e\n", i + 1, 1, 0.1);
        deck += line;
    }
    return deck + "*END\n";
}

}  // namespace

TEST_CASE(
    "recheck: the geometry preview is kept when an edit leaves its inputs alone, and findings equal a full check") {
    const std::filesystem::path path = std::filesystem::absolute("incremental_lattice.k");
    const std::string text = lattice_deck(20);
    engine::Documents documents;
    documents.set(path, text);
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const engine::CheckResult first = engine::check_deck(path.string(), documents, options);
    REQUIRE(first.preview);
    // The deck views the document's own text (an editor's 100 MB buffer is not copied), and keeps it
    // alive when the document is replaced.
    CHECK(first.deck.sources.file(0).text.data() == documents.find(path)->data());

    // The part's title: the same particles, controls and parts.
    std::string retitled = text;
    retitled.replace(retitled.find("water"), 5, "water, renamed");
    documents.set(path, retitled);
    const engine::CheckResult again = engine::recheck_deck(path.string(), documents, options, first);
    CHECK(first.deck.sources.file(0).text.view() == text);
    CHECK(again.preview == first.preview);
    CHECK(engine::same_geometry_inputs(first.model, again.model));
    const engine::CheckResult full = engine::check_deck(path.string(), documents);
    REQUIRE(again.diagnostics.size() == full.diagnostics.size());
    for (std::size_t i = 0; i < full.diagnostics.size(); ++i) {
        CHECK(again.diagnostics[i].code == full.diagnostics[i].code);
        CHECK(again.diagnostics[i].message == full.diagnostics[i].message);
        CHECK(again.diagnostics[i].span.line == full.diagnostics[i].span.line);
        CHECK(again.diagnostics[i].span.column == full.diagnostics[i].span.column);
    }

    // A coordinate, a mass and CSLH change the preview's inputs: computed again.
    // Pairs, not structured bindings: clang does not let doctest's macros capture a binding.
    for (const auto& change : std::vector<std::pair<std::string, std::string>>{{"1.00000000e-02", "1.50000000e-02"},
                                                                               {"1.00000000e-01\n", "2.00000000e-01\n"},
                                                                               {"1.2", "1.3"}}) {
        const std::string& from = change.first;
        const std::string& to = change.second;
        std::string edited = retitled;
        edited.replace(edited.find(from), from.size(), to);
        documents.set(path, edited);
        const engine::CheckResult changed = engine::recheck_deck(path.string(), documents, options, again);
        CHECK_MESSAGE(changed.preview != again.preview, from);
        CHECK_FALSE(engine::same_geometry_inputs(again.model, changed.model));
    }
}

TEST_CASE("recheck: random edits in and out of the bulk blocks, across keyword lines: incremental equals full") {
    // Shipped decks (2D and 3D, with particles, parameters and mistakes) and a generated lattice.
    std::vector<std::pair<std::filesystem::path, std::string>> decks;
    for (const char* name : {"decks/demo/sph_mistakes_2d.k", "decks/run/water_column_2d.k",
                             "decks/verification/hydrostatic_2d_quick.k", "decks/tests/preview/SPH118_fires.k",
                             "decks/tests/preview/SPH114_fires.k", "decks/tests/dk/DK003_fires_flood.k"}) {
        const std::filesystem::path path = kSource / name;
        decks.emplace_back(path, text::read_text_file(path.string()));
    }
    decks.emplace_back(std::filesystem::absolute("incremental_random_lattice.k"), lattice_deck(12));
    std::mt19937 random(29);
    for (const auto& deck : decks) {
        const std::filesystem::path& path = deck.first;
        const std::string& original = deck.second;
        CAPTURE(path.string());
        const std::string uri = lsp::uri_from_path(path);
        nlohmann::json published;
        lsp::Workspace workspace([&](const nlohmann::json& params) {
            if (params["uri"] == uri) published = params["diagnostics"];
        });
        workspace.open(uri, original, 1);
        workspace.flush();
        std::vector<std::string> lines = split_lines(original);
        for (int edit = 0; edit < 24; ++edit) {
            const nlohmann::json change = random_edit(lines, random);
            if (change.is_null()) continue;
            CAPTURE(edit);
            CAPTURE(change.dump());
            REQUIRE(workspace.change(uri, edit + 2, nlohmann::json::array({change})));
            workspace.flush();
            const std::string text = join_lines(lines);
            REQUIRE(*workspace.text(uri) == text);
            const nlohmann::json full = test::published_by_full_check(path, text);
            REQUIRE(published.size() == full.size());
            for (std::size_t i = 0; i < full.size(); ++i) CHECK(published[i] == full[i]);
        }
    }
}

TEST_CASE("deck splice: an edit's lines read again and spliced in equal a full reading, or no splice") {
    const std::string name = "splice_lattice.k";
    std::vector<std::string> lines = split_lines(lattice_deck(6));
    grammar::RawDeck previous = grammar::read_deck_buffer(join_lines(lines), name);
    std::mt19937 random(7);
    int spliced = 0;
    for (int edit = 0; edit < 200; ++edit) {
        if (random_edit(lines, random).is_null()) continue;
        const std::string text = join_lines(lines);
        CAPTURE(edit);
        CAPTURE(text);
        grammar::RawDeck full = grammar::read_deck_buffer(text, name);
        // What an editor tells of the change (lsp::DocumentText): fewer kept bytes than there are, at
        // times none; the splice then reads what it would after comparing the texts, or reads in full.
        const std::string_view before = previous.sources.file(0).text.view();
        std::size_t prefix = 0, suffix = 0;
        while (prefix < std::min(before.size(), text.size()) && before[prefix] == text[prefix]) ++prefix;
        while (suffix < std::min(before.size(), text.size()) - prefix &&
               before[before.size() - 1 - suffix] == text[text.size() - 1 - suffix])
            ++suffix;
        const grammar::TextRevision told{before.data(), before.size(), prefix - prefix * (edit % 3) / 3,
                                         suffix - suffix * (edit % 4) / 4, nullptr};
        auto splice = grammar::splice_edit(previous, grammar::SourceText(text), edit % 2 ? &told : nullptr);
        if (splice) {
            ++spliced;
            const grammar::RawDeck& deck = splice->deck;
            REQUIRE(deck.lines.size() == full.lines.size());
            for (std::size_t i = 0; i < full.lines.size(); ++i) {
                CHECK(deck.lines[i].line == full.lines[i].line);
                CHECK(deck.lines[i].offset == full.lines[i].offset);
            }
            REQUIRE(deck.blocks.size() == full.blocks.size());
            for (std::size_t i = 0; i < full.blocks.size(); ++i) {
                CHECK(deck.blocks[i].keyword == full.blocks[i].keyword);
                CHECK(deck.blocks[i].first_line == full.blocks[i].first_line);
                CHECK(deck.blocks[i].line_count == full.blocks[i].line_count);
                CHECK(deck.blocks[i].span.line == full.blocks[i].span.line);
            }
            REQUIRE(deck.diagnostics.size() == full.diagnostics.size());
            for (std::size_t i = 0; i < full.diagnostics.size(); ++i) {
                CHECK(deck.diagnostics[i].message == full.diagnostics[i].message);
                CHECK(deck.diagnostics[i].span.line == full.diagnostics[i].span.line);
            }
            CHECK(deck.stats.lines == full.stats.lines);
            CHECK(deck.stats.cards == full.stats.cards);
        }
        previous = std::move(full);
    }
    CHECK(spliced > 60);  // most edits change data lines inside one block
}

TEST_CASE("recheck: bulk blocks the edit left alone are copied, not decoded; random edits equal a full check") {
    // 91 x 91 particles: *NODE and *ELEMENT_SPH long enough for the bulk path (model/bulk_reuse.hpp).
    const std::filesystem::path path = std::filesystem::absolute("incremental_bulk_lattice.k");
    const std::string text = lattice_deck(91);
    engine::Documents documents;
    documents.set(path, text);
    engine::CheckOptions options;
    options.rules.geometry = false;  // the decoding is what this looks at
    const engine::CheckResult first = engine::check_deck(path.string(), documents, options);
    REQUIRE(first.bulk_blocks.size() == 2);  // both decoded cleanly: the next re-check may copy them
    // A line added above the bulk blocks: both copied, the particles' lines shifted with the deck's.
    std::string retitled = text;
    retitled.replace(retitled.find("water"), 5, "water\n$ a comment\n");
    documents.set(path, retitled);
    const engine::CheckResult again = engine::recheck_deck(path.string(), documents, options, first);
    const engine::CheckResult full = engine::check_deck(path.string(), documents, options);
    CHECK(again.bulk_blocks.size() == 2);
    CHECK(again.model.nodes.x == full.model.nodes.x);
    CHECK(again.model.particles.line == full.model.particles.line);
    CHECK(again.model.particles.mass == full.model.particles.mass);
    // A parameter in a node line: that block is decoded again and not kept (its values depend on more
    // than its text); the particles are still copied.
    std::string with_parameter = retitled;
    with_parameter.replace(with_parameter.find("*NODE\n") + 6 + 8, 16, "&x              ");
    with_parameter.replace(with_parameter.find("*NODE"), 0, "*PARAMETER\nR x              0.5\n");
    documents.set(path, with_parameter);
    const engine::CheckResult third = engine::recheck_deck(path.string(), documents, options, again);
    REQUIRE(third.bulk_blocks.size() == 1);
    CHECK(third.bulk_blocks[0].keyword == "*ELEMENT_SPH");
    CHECK(third.model.nodes.x == engine::check_deck(path.string(), documents, options).model.nodes.x);
}

TEST_CASE(
    "recheck: random edits of a deck with bulk blocks (copied, spliced, decoded around an edit) equal a full check") {
    const std::filesystem::path path = std::filesystem::absolute("incremental_random_bulk_lattice.k");
    const std::string text = lattice_deck(91);
    const std::string uri = lsp::uri_from_path(path);
    nlohmann::json published;
    lsp::Workspace workspace([&](const nlohmann::json& params) {
        if (params["uri"] == uri) published = params["diagnostics"];
    });
    workspace.open(uri, text, 1);
    workspace.flush();
    std::vector<std::string> lines = split_lines(text);
    std::mt19937 random(91);
    for (int edit = 0; edit < 15; ++edit) {
        // One edit in three one digit of a bulk line (the same length: its block's size does not tell it
        // apart), one in three on a line of the small blocks (the bulk columns moved, not copied).
        const nlohmann::json change = edit % 3 == 0   ? digit_edit_in_bulk(lines, random)
                                      : edit % 3 == 1 ? random_edit(lines, random)
                                                      : random_edit(lines, random, true);
        if (change.is_null()) continue;
        CAPTURE(edit);
        CAPTURE(change.dump());
        REQUIRE(workspace.change(uri, edit + 2, nlohmann::json::array({change})));
        workspace.flush();
        const nlohmann::json expected = test::published_by_full_check(path, join_lines(lines));
        REQUIRE(published.size() == expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) CHECK(published[i] == expected[i]);
        // The model too: a value copied from the last check where it changed need not change a finding.
        engine::Documents documents;
        documents.set(path, join_lines(lines));
        engine::CheckOptions options;
        options.rules.geometry = false;
        const engine::CheckResult full = engine::check_deck(path.string(), documents, options);
        REQUIRE(workspace.checked_decks().size() == 1);
        const model::Model& model = workspace.checked_decks()[0]->result.model;
        CHECK(model.nodes.id == full.model.nodes.id);
        CHECK(model.nodes.x == full.model.nodes.x);
        CHECK(model.nodes.y == full.model.nodes.y);
        CHECK(model.particles.node == full.model.particles.node);
        CHECK(model.particles.mass == full.model.particles.mass);
        CHECK(model.particles.line == full.model.particles.line);
    }
}

TEST_CASE("recheck: a suppression directive typed into a big block is seen, and removed again, as by a full check") {
    // The re-check looks for directives only in the lines an edit spliced in when the last text held none.
    const std::filesystem::path path = std::filesystem::absolute("incremental_directive_lattice.k");
    const std::string uri = lsp::uri_from_path(path);
    nlohmann::json published;
    lsp::Workspace workspace([&](const nlohmann::json& params) {
        if (params["uri"] == uri) published = params["diagnostics"];
    });
    std::vector<std::string> lines = split_lines(lattice_deck(91));
    workspace.open(uri, join_lines(lines), 1);
    workspace.flush();
    const auto node = static_cast<std::uint32_t>(std::find(lines.begin(), lines.end(), "*NODE") - lines.begin());
    const auto change_at = [](std::uint32_t l0, std::uint32_t l1, const std::string& text) {
        return nlohmann::json::array(
            {{{"range", {{"start", {{"line", l0}, {"character", 0}}}, {"end", {{"line", l1}, {"character", 0}}}}},
              {"text", text}}});
    };
    const std::string directive = "$ sphdeck: disable=SPH110 -- test";
    // Typed in, then a node line edited below it (the text holds a directive now), then removed.
    lines.insert(lines.begin() + node + 500, directive);
    REQUIRE(workspace.change(uri, 2, change_at(node + 500, node + 500, directive + "\n")));
    workspace.flush();
    nlohmann::json expected = test::published_by_full_check(path, join_lines(lines));
    CHECK(std::any_of(expected.begin(), expected.end(), [](const nlohmann::json& d) { return d["code"] == "DK026"; }));
    CHECK(published == expected);
    lines[node + 900][12] = lines[node + 900][12] == '9' ? '8' : '9';  // a digit of x
    REQUIRE(workspace.change(uri, 3, change_at(node + 900, node + 901, lines[node + 900] + "\n")));
    workspace.flush();
    CHECK(published == test::published_by_full_check(path, join_lines(lines)));
    lines.erase(lines.begin() + node + 500);
    REQUIRE(workspace.change(uri, 4, change_at(node + 500, node + 501, "")));
    workspace.flush();
    expected = test::published_by_full_check(path, join_lines(lines));
    CHECK(std::none_of(expected.begin(), expected.end(), [](const nlohmann::json& d) { return d["code"] == "DK026"; }));
    CHECK(published == expected);
}

namespace {
// A deck whose part, section, material and controls lie in an include, its particles in the main file.
const char* const kIncludeMain = "incremental_with_include.k";
const char* const kIncludeName = "incremental_parts.inc";
std::string included_parts() {
    return "*CONTROL_SPH\n         1         0   1.0e+20         2       150         0\n*SECTION_SPH\n"
           "         1       1.2       0.2       2.0\n*PART\nwater\n         1         1         1         1\n"
           "*MAT_NULL\n         1    1000.0\n*EOS_MURNAGHAN\n         1       7.0  357142.9       1.0\n";
}
std::string main_with_include() {
    std::string lattice = lattice_deck(8);
    // The lattice's settings go to the include: the main file keeps the bulk blocks.
    const std::size_t from = lattice.find("*CONTROL_SPH"), to = lattice.find("*NODE");
    return lattice.substr(0, from) + "*INCLUDE\n" + kIncludeName + "\n" + lattice.substr(to);
}

// The diagnostics a workspace holding only these open texts publishes, by URI: a full check.
std::map<std::string, nlohmann::json> full_check_of(const std::vector<std::pair<std::string, std::string>>& texts) {
    std::map<std::string, nlohmann::json> published;
    lsp::Workspace workspace([&](const nlohmann::json& params) { published[params["uri"]] = params["diagnostics"]; });
    int version = 1;
    for (const auto& text : texts) workspace.open(text.first, text.second, version++);
    workspace.flush();
    return published;
}
}  // namespace

TEST_CASE("recheck: random edits of an open include and of its deck: incremental equals full") {
    // A project folder of its own (its .git marks the root): an include no deck reads any more is
    // looked for in that folder only, which holds no deck on disk.
    const test::TempDir folder;
    std::filesystem::create_directories(folder.path() / ".git");
    const std::filesystem::path main = folder.path() / kIncludeMain;
    const std::filesystem::path include = folder.path() / kIncludeName;
    const std::string main_uri = lsp::uri_from_path(main), include_uri = lsp::uri_from_path(include);
    std::map<std::string, nlohmann::json> published;
    lsp::Workspace workspace([&](const nlohmann::json& params) { published[params["uri"]] = params["diagnostics"]; });
    std::vector<std::string> main_lines = split_lines(main_with_include());
    std::vector<std::string> include_lines = split_lines(included_parts());
    workspace.open(main_uri, join_lines(main_lines), 1);
    workspace.open(include_uri, join_lines(include_lines), 1);
    workspace.flush();
    REQUIRE(workspace.deck_mains().size() == 1);  // the include is checked as part of its deck
    std::mt19937 random(45);
    for (int edit = 0; edit < 30; ++edit) {
        // Two edits in three in the include: its settings feed the rules of the particles next door.
        const bool in_include = edit % 3 != 2;
        std::vector<std::string>& lines = in_include ? include_lines : main_lines;
        const nlohmann::json change = random_edit(lines, random);
        if (change.is_null()) continue;
        CAPTURE(edit);
        CAPTURE(in_include);
        CAPTURE(change.dump());
        REQUIRE(workspace.change(in_include ? include_uri : main_uri, edit + 2, nlohmann::json::array({change})));
        workspace.flush();
        const auto full = full_check_of({{main_uri, join_lines(main_lines)}, {include_uri, join_lines(include_lines)}});
        for (const std::string& uri : {main_uri, include_uri}) {
            CAPTURE(uri);
            const nlohmann::json expected = full.count(uri) ? full.at(uri) : nlohmann::json::array();
            const nlohmann::json got = published.count(uri) ? published.at(uri) : nlohmann::json::array();
            REQUIRE(got.size() == expected.size());
            for (std::size_t i = 0; i < expected.size(); ++i) CHECK(got[i] == expected[i]);
        }
    }
}

TEST_CASE("recheck: the bulk blocks' columns an edit left alone are moved out of the last check") {
    // 91 x 91 particles: one *NODE and one *ELEMENT_SPH block on the bulk path, each all of its column.
    const std::filesystem::path path = std::filesystem::absolute("incremental_taken_lattice.k");
    const std::string text = lattice_deck(91);
    engine::Documents documents;
    documents.set(path, text);
    engine::CheckOptions options;
    options.rules.keep_preview = true;
    const auto same_as_full = [&](const engine::CheckResult& result) {
        const engine::CheckResult full = engine::check_deck(path.string(), documents, options);
        test::check_same_bulk_columns(result.model, full.model);
        REQUIRE(result.deck.lines.size() == full.deck.lines.size());
        for (std::size_t i = 0; i < full.deck.lines.size(); ++i) {
            const grammar::CardLine &a = result.deck.lines[i], &b = full.deck.lines[i];
            if (a.file != b.file || a.line != b.line || a.offset != b.offset) FAIL_CHECK("card line " << i);
        }
        test::check_same_findings(result.diagnostics, full.diagnostics);
    };
    engine::CheckResult first = engine::check_deck(path.string(), documents, options);
    REQUIRE(first.bulk_blocks.size() == 2);
    const double* first_x = first.model.nodes.x.data();

    // The title retyped and a comment line added under it: both blocks taken whole (the same arrays),
    // their lines moved by one, the preview kept as it was.
    std::string retitled = text;
    retitled.replace(retitled.find("water"), 5, "water 2\n$ the part's cards");
    documents.set(path, retitled);
    engine::CheckResult again = engine::recheck_deck_taking(path.string(), documents, options, first);
    CHECK(first.taken.nodes);
    CHECK(first.taken.particles);
    CHECK(first.model.nodes.x.empty());
    CHECK(first.model.particles.size() == 0);
    CHECK(again.model.nodes.x.data() == first_x);
    CHECK(again.preview == first.preview);
    same_as_full(again);

    // CSLH after a take: the preview's settings computed again over the taken places.
    std::string cslh = retitled;
    cslh.replace(cslh.find("       1.2"), 10, "       1.5");
    documents.set(path, cslh);
    engine::CheckResult third = engine::recheck_deck_taking(path.string(), documents, options, again);
    CHECK(again.taken.nodes);
    CHECK(third.preview != again.preview);
    same_as_full(third);

    // An edit inside *NODE: followed by the preview from the last model, so nothing is taken.
    std::string moved = cslh;
    moved.replace(moved.find("*NODE\n") + 6 + 8 + 4, 1, "7");
    documents.set(path, moved);
    const engine::CheckResult fourth = engine::recheck_deck_taking(path.string(), documents, options, third);
    CHECK_FALSE(third.taken.any());
    CHECK(fourth.preview != third.preview);
    same_as_full(fourth);

    // A re-check from a check whose columns went: decoded again, not read from the empty columns.
    const engine::CheckResult from_emptied = engine::recheck_deck(path.string(), documents, options, first);
    same_as_full(from_emptied);
}

TEST_CASE(
    "recheck: a text patched in place and read in full again reuses a bulk block only where its old bytes match") {
    // 91 x 91 particles: *NODE and *ELEMENT_SPH on the bulk path. One change in each at once spans a
    // keyword line, so the deck is read in full; the editor patched the buffer the last check read in
    // place (lsp/document_text.hpp), so that check's blocks are compared with the bytes it held, not
    // with what its reading views now (the same bytes as the new text's).
    const std::filesystem::path path = std::filesystem::absolute("incremental_patched_lattice.k");
    const int n = 91;
    const std::string original = lattice_deck(n);
    const std::string uri = lsp::uri_from_path(path);
    lsp::Workspace workspace([](const nlohmann::json&) {});
    REQUIRE(workspace.open(uri, original, 1));
    workspace.flush();
    std::mt19937 random(4545);
    const auto pick = [&](int count) { return std::uniform_int_distribution<int>(0, count - 1)(random); };
    const auto digit = [](int line, int character, int value) {
        return nlohmann::json{{"range",
                               {{"start", {{"line", line}, {"character", character}}},
                                {"end", {{"line", line}, {"character", character + 1}}}}},
                              {"text", std::string(1, static_cast<char>('0' + value))}};
    };
    const int first_node_line = 13, first_particle_line = first_node_line + n * n + 1;
    for (int round = 0; round < 4; ++round) {
        CAPTURE(round);
        // A node's x and a particle's mass, each one digit of its mantissa (the same length).
        const nlohmann::json changes =
            nlohmann::json::array({digit(first_node_line + pick(n * n), 12, 1 + pick(9)),
                                   digit(first_particle_line + pick(n * n), 20, 1 + pick(9))});
        REQUIRE(workspace.change(uri, round + 2, changes));
        workspace.flush();
        const auto located = workspace.locate(path);
        REQUIRE(located);
        const engine::CheckResult& result = located->deck->result;
        engine::Documents documents;
        documents.set(path, *workspace.text(uri));
        const engine::CheckResult full = engine::check_deck(path.string(), documents, engine::CheckOptions{});
        REQUIRE(full.bulk_blocks.size() == 2);
        test::check_same_bulk_columns(result.model, full.model);
    }
}

}  // namespace test_incremental_cpp
