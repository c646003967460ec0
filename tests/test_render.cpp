// Concise and full text renderers of diagnostics: exact output on small in-memory decks.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <sstream>
#include <string>

#include "diag/render_text.hpp"

namespace test_render_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;
using diag::Diagnostic;
using diag::Severity;
using grammar::SourceFile;
using grammar::Span;

namespace {

grammar::FileId add(grammar::SourceMap& map, std::string name, std::string text,
                    grammar::FileId parent = grammar::no_file, std::uint32_t include_line = 0) {
    return map.add(SourceFile{.path = "/decks/" + name,
                              .display_name = name,
                              .text = std::move(text),
                              .parent = parent,
                              .include_line = include_line,
                              .depth = 0,
                              .line_starts = {},
                              .comment_holds_marker = {}});
}

std::string full(const Diagnostic& d, const grammar::SourceMap& map, bool colour = false) {
    return diag::render_full(d, map, diag::RenderOptions{.colour = colour});
}

std::size_t longest_line(const std::string& text) {
    std::istringstream in(text);
    std::size_t longest = 0;
    for (std::string line; std::getline(in, line);) longest = std::max(longest, line.size());
    return longest;
}

}  // namespace

TEST_CASE("render: concise form with notes") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", "*KEYWORD\n*SECTION_SPH\n1,1.2\n");
    Diagnostic d{"SPH030", Severity::Warning, "cslh 1.2 outside [1.05, 1.3]", Span{main, 3, 3, 6}, {}};
    CHECK(diag::render_concise(d, map) == "main.k:3:3: warning: cslh 1.2 outside [1.05, 1.3] [SPH030]\n");

    d.notes = {{Span{main, 2, 1, 13}, "section defined here"}, {Span{}, "the default is 1.2"}};
    CHECK(diag::render_concise(d, map) ==
          "main.k:3:3: warning: cslh 1.2 outside [1.05, 1.3] [SPH030]\n"
          "main.k:2:1: note: section defined here\n");

    map.file(main).display_name.clear();  // falls back to the path
    d.notes.clear();
    CHECK(diag::render_concise(d, map) == "/decks/main.k:3:3: warning: cslh 1.2 outside [1.05, 1.3] [SPH030]\n");
}

TEST_CASE("render: invalid span has no location") {
    grammar::SourceMap map;
    Diagnostic d{"DK001", Severity::Error, "no *END keyword", Span{}, {{Span{}, "the deck ends at line 40"}}};
    CHECK(diag::render_concise(d, map) == "sphdeck: error: no *END keyword [DK001]\n");
    CHECK(full(d, map) ==
          "error[DK001]: no *END keyword\n"
          "  = note: the deck ends at line 40\n");
    d.span = Span{7, 1, 1, 2};  // a file the map does not hold
    d.code.clear();
    d.severity = Severity::Info;
    CHECK(diag::render_concise(d, map) == "sphdeck: info: no *END keyword\n");
}

TEST_CASE("render: full form with an include chain of two levels") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", "*KEYWORD\n*INCLUDE\nmesh.k\n");
    const auto mesh = add(map, "mesh.k", "*INCLUDE\nmesh/a.k\n", main, 2);
    const auto part = add(map, "mesh/a.k", std::string(11, '\n') + "parts.k\n", mesh, 1);
    Diagnostic d{"DK010", Severity::Error, "include file 'parts.k' not found", Span{part, 12, 1, 8}, {}};
    CHECK(full(d, map) ==
          "error[DK010]: include file 'parts.k' not found\n"
          "  --> mesh/a.k:12:1\n"
          "   |\n"
          "12 | parts.k\n"
          "   | ^^^^^^^\n"
          "   = note: included from mesh.k:1\n"
          "   = note: included from main.k:2\n");
}

TEST_CASE("render: full form with notes and an adaptive gutter") {
    grammar::SourceMap map;
    std::string text;
    for (int i = 1; i <= 120; ++i) text += i == 9 ? "   1     0.5\n" : i == 120 ? "*SECTION_SPH\n" : "$\n";
    const auto main = add(map, "main.k", text);
    Diagnostic d{"SPH012",
                 Severity::Warning,
                 "section 1 is not an SPH section",
                 Span{main, 9, 4, 5},
                 {{Span{main, 120, 1, 13}, "section 1 is defined here"}, {Span{}, "expected *SECTION_SPH"}}};
    CHECK(full(d, map) ==
          "warning[SPH012]: section 1 is not an SPH section\n"
          "   --> main.k:9:4\n"
          "    |\n"
          "  9 |    1     0.5\n"
          "    |    ^\n"
          "note: section 1 is defined here\n"
          "   --> main.k:120:1\n"
          "    |\n"
          "120 | *SECTION_SPH\n"
          "    | ^^^^^^^^^^^^\n"
          "    = note: expected *SECTION_SPH\n");
}

TEST_CASE("render: carets at least one wide, also past the line end") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", "1,2\n");
    Diagnostic d{"X1", Severity::Info, "m", Span{main, 1, 2, 2}, {}};
    CHECK(full(d, map) == "info[X1]: m\n --> main.k:1:2\n  |\n1 | 1,2\n  |  ^\n");
    d.span = Span{main, 1, 5, 3};
    CHECK(full(d, map) == "info[X1]: m\n --> main.k:1:5\n  |\n1 | 1,2\n  |     ^\n");
    d.span = Span{main, 1, 3, 7};  // a blank field after the text
    CHECK(full(d, map) == "info[X1]: m\n --> main.k:1:3\n  |\n1 | 1,2\n  |   ^^^^\n");
}

TEST_CASE("render: tabs expand alike in excerpt and carets") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", "\t1\t2.5e3\n");
    Diagnostic d{"DK020", Severity::Warning, "tab in a fixed-format card", Span{main, 1, 3, 4}, {}};
    CHECK(full(d, map) ==
          "warning[DK020]: tab in a fixed-format card\n"
          " --> main.k:1:3\n"
          "  |\n"
          "1 |         1       2.5e3\n"
          "  |          ^^^^^^^\n");
    d.span = Span{main, 1, 4, 9};
    CHECK(full(d, map).ends_with("1 |         1       2.5e3\n  |                 ^^^^^\n"));
}

TEST_CASE("render: control bytes, invalid UTF-8 and CRLF") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", std::string("a\0b\x1b[31m\xff\xc3\xa9x\r\n*END\r\n", 20));
    Diagnostic d{"DK002", Severity::Error, "bad\nbyte", Span{main, 1, 12, 13}, {}};
    CHECK(full(d, map) ==
          "error[DK002]: bad?byte\n"
          " --> main.k:1:12\n"
          "  |\n"
          "1 | a?b?[31m?\xc3\xa9x\n"
          "  |           ^\n");
    d.span = Span{main, 1, 10, 11};  // inside the two-byte character: caret under the whole of it
    CHECK(full(d, map).ends_with("  |          ^\n"));
    d.span = Span{main, 2, 1, 5};
    CHECK(full(d, map).ends_with("2 | *END\n  | ^^^^\n"));
    CHECK(diag::render_concise(d, map) == "main.k:2:1: error: bad?byte [DK002]\n");
}

TEST_CASE("render: long lines are windowed around the span") {
    grammar::SourceMap map;
    std::string line(10'000'000, 'x');
    line.replace(5'000'000, 4, "1.5e");
    const auto main = add(map, "big.k", line + "\n" + std::string(300, 'y') + "\n");
    Diagnostic d{"DK030", Severity::Error, "value overflows its field", Span{main, 1, 5'000'001, 5'000'005}, {}};
    const std::string out = full(d, map);
    CHECK(longest_line(out) <= 220);
    CHECK(out.find("1 | ...xxxxxxxx") != std::string::npos);
    CHECK(out.find("xxx1.5exxx") != std::string::npos);
    CHECK(out.find("xxx...\n") != std::string::npos);
    const auto excerpt = out.find("1 | ...");
    const auto carets = out.find("^^^^\n");
    const auto number = out.find("1.5e");
    REQUIRE(carets != std::string::npos);
    CHECK(carets - out.rfind('\n', carets) - 1 == number - excerpt);  // aligned under "1.5e"

    d.span = Span{main, 1, 1, 20'000'000};  // a huge span is capped too
    CHECK(longest_line(full(d, map)) <= 220);
    d.span = Span{main, 2, 1, 2};  // a 300-column line: kept from its start, cut at the end
    const std::string head = full(d, map);
    CHECK(head.find("2 | yyy") != std::string::npos);
    CHECK(head.find("yyy...\n") != std::string::npos);
    CHECK(longest_line(head) <= 220);
    d.span = Span{main, 2, 300, 301};  // near its end: cut at the start only
    CHECK(full(d, map).find("2 | ...yyy") != std::string::npos);
    CHECK(full(d, map).find("yyy...") == std::string::npos);
}

TEST_CASE("render: colour only when asked") {
    grammar::SourceMap map;
    const auto main = add(map, "main.k", "*SECTION_SPH\n");
    Diagnostic d{"SPH001", Severity::Error, "m", Span{main, 1, 1, 13}, {{Span{main, 1, 2, 3}, "n"}, {Span{}, "o"}}};
    CHECK(full(d, map, false).find('\x1b') == std::string::npos);
    CHECK(diag::render_concise(d, map).find('\x1b') == std::string::npos);
    const std::string coloured = full(d, map, true);
    CHECK(coloured.starts_with("\x1b[1;31merror\x1b[0m\x1b[1m[SPH001]\x1b[0m: m\n"));
    CHECK(coloured.find("\x1b[34m-->\x1b[0m main.k:1:1") != std::string::npos);
    CHECK(coloured.find("\x1b[1;31m^^^^^^^^^^^^\x1b[0m") != std::string::npos);
    d.severity = Severity::Warning;
    CHECK(full(d, map, true).find("\x1b[1;33m^^^^^^^^^^^^\x1b[0m") != std::string::npos);
}

TEST_CASE("render: colour_wanted needs a terminal and no NO_COLOR") {
    int pipe_fds[2];
    REQUIRE(pipe(pipe_fds) == 0);
    CHECK_FALSE(diag::colour_wanted(pipe_fds[1]));
    close(pipe_fds[0]);
    close(pipe_fds[1]);

    const int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) return;  // no pseudo-terminals here
    const int tty = open(ptsname(master), O_RDWR | O_NOCTTY);
    if (tty >= 0) {
        const char* saved = getenv("NO_COLOR");
        const std::string saved_value = saved ? saved : "";
        unsetenv("NO_COLOR");
        CHECK(diag::colour_wanted(tty));
        setenv("NO_COLOR", "", 1);
        CHECK(diag::colour_wanted(tty));
        setenv("NO_COLOR", "1", 1);
        CHECK_FALSE(diag::colour_wanted(tty));
        if (saved)
            setenv("NO_COLOR", saved_value.c_str(), 1);
        else
            unsetenv("NO_COLOR");
        close(tty);
    }
    close(master);
}
}  // namespace test_render_cpp
