// edit/: placing and applying text edits, and the unified diff printed from them, compared with
// `diff -u` itself (diffutils is Essential on Debian).
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "text/apply_edits.hpp"
#include "edit/unified_diff.hpp"

namespace test_edit_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

diag::TextEdit edit_at(std::uint32_t line, std::uint32_t column, std::uint32_t end_column, std::string text) {
    return diag::TextEdit{grammar::Span{0, line, column, end_column}, std::move(text)};
}

void write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// `diff -u a b` with its two header lines replaced by ours, as our diff names the file a/PATH, b/PATH.
std::string diff_u(const std::string& before, const std::string& after) {
    const auto dir = std::filesystem::temp_directory_path() / "sphdeck_test_edit";
    std::filesystem::create_directories(dir);
    write_file(dir / "a", before);
    write_file(dir / "b", after);
    const std::string command = "diff -u " + (dir / "a").string() + " " + (dir / "b").string();
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    REQUIRE(pipe);
    std::string out;
    std::array<char, 4096> buffer{};
    while (const auto n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) out.append(buffer.data(), n);
    if (out.empty()) return out;
    out.erase(0, out.find('\n') + 1);  // "--- a<tab>date"
    out.erase(0, out.find('\n') + 1);  // "+++ b<tab>date"
    return "--- a/deck.k\n+++ b/deck.k\n" + out;
}

}  // namespace

TEST_CASE("edit: edits apply by line and column, clamped to the line, keeping line breaks") {
    const std::string text = "*KEYWORD\n  1.0  2\r\nlast";
    const auto result =
        text::apply_edits(text, {edit_at(2, 1, 99, "1.0       2"), edit_at(3, 5, 5, "!"), edit_at(1, 1, 2, "$")});
    CHECK(result.text == "$KEYWORD\n1.0       2\r\nlast!");
    CHECK(result.applied == 3);
    CHECK(result.skipped == 0);
}

TEST_CASE("edit: an edit overlapping one taken before it is skipped, touching ones are not") {
    const std::string text = "abcdefghij\n";
    const auto result = text::apply_edits(text, {edit_at(1, 3, 6, "X"), edit_at(1, 5, 8, "Y"), edit_at(1, 6, 7, "Z"),
                                                 edit_at(1, 1, 1, "<")});
    CHECK(result.text == "<abXZghij\n");
    CHECK(result.applied == 3);
    CHECK(result.skipped == 1);
}

TEST_CASE("edit: edits on lines that do not exist or with reversed columns are skipped") {
    const auto result =
        text::apply_edits("a\nb\n", {edit_at(0, 1, 2, "x"), edit_at(4, 1, 2, "x"), edit_at(1, 3, 2, "x")});
    CHECK(result.text == "a\nb\n");
    CHECK(result.skipped == 3);
}

TEST_CASE("edit: the unified diff equals diff -u's, hunks merged and split as diff merges them") {
    std::string text;
    for (int i = 1; i <= 40; ++i) text += "line " + std::to_string(i) + "\n";
    const std::vector<diag::TextEdit> edits{edit_at(2, 1, 5, "LINE"), edit_at(8, 6, 7, "eight"),
                                            edit_at(9, 1, 1, "$# a header\n"), edit_at(30, 1, 99, ""),
                                            edit_at(40, 6, 8, "forty")};
    const auto after = text::apply_edits(text, edits).text;
    CHECK(edit::unified_diff("deck.k", text, edits) == diff_u(text, after));
}

TEST_CASE("edit: a last line without a line break is marked as diff marks it") {
    const std::string text = "one\ntwo\nthree";
    const std::vector<diag::TextEdit> edits{edit_at(3, 1, 6, "THREE")};
    CHECK(edit::unified_diff("deck.k", text, edits) == diff_u(text, text::apply_edits(text, edits).text));
}

TEST_CASE("edit: an absolute path is named as git names it, without a doubled slash") {
    const std::string diff = edit::unified_diff("/tmp/deck.k", "a\nb\n", {edit_at(1, 1, 2, "A")});
    CHECK(diff.starts_with("--- a/tmp/deck.k\n+++ b/tmp/deck.k\n@@ "));
}

TEST_CASE("edit: no diff when the edits change nothing") {
    CHECK(edit::unified_diff("deck.k", "a\nb\n", {edit_at(1, 1, 2, "a")}).empty());
}

TEST_CASE("edit: random edits give the diff diff -u gives") {
    std::uint32_t state = 12345;  // a fixed linear congruential sequence: the same cases every run
    const auto next = [&](std::uint32_t bound) {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) % bound;
    };
    for (int trial = 0; trial < 60; ++trial) {
        std::string text;
        const std::uint32_t line_count = 1 + next(60);
        for (std::uint32_t i = 1; i <= line_count; ++i) text += "line " + std::to_string(i) + "\n";
        if (next(4) == 0) text.pop_back();  // sometimes no final line break
        std::vector<diag::TextEdit> edits;
        const std::uint32_t edit_count = 1 + next(6);
        for (std::uint32_t e = 0; e < edit_count; ++e) {
            const std::uint32_t line = 1 + next(line_count);
            const std::string unique = "edit " + std::to_string(trial) + "." + std::to_string(e);
            switch (next(3)) {
                case 0: edits.push_back(edit_at(line, 1, 99, unique)); break;                // replace the line
                case 1: edits.push_back(edit_at(line, 1, 1, "$# " + unique + "\n")); break;  // a header above
                default: edits.push_back(edit_at(line, 6, 6, unique)); break;                // insert inside
            }
        }
        CAPTURE(trial);
        CHECK(edit::unified_diff("deck.k", text, edits) == diff_u(text, text::apply_edits(text, edits).text));
    }
}
}  // namespace test_edit_cpp
