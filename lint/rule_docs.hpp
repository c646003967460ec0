// The rules' documentation pages: docs/rules/CODE.md, one per rule, embedded in the binary at build
// time (cmake/embed_rule_docs.cmake writes their text into a generated table) and read here.
//
// A page has a fixed shape, which the reader checks:
//
//   # SPH010 form12-requires-mpp
//   ## What it does      one paragraph
//   ## Why it matters    one paragraph
//   ## How to fix        one paragraph
//   ## Before            one ```text block: a deck fragment that triggers the rule
//   ## After             one ```text block: the same fragment fixed
//
// Paragraphs may be wrapped (lines are joined with one space); Markdown backslash escapes (\*PART)
// are removed outside `code` spans, so RuleDoc holds the plain text the terminal prints. The examples
// are column-exact deck fragments: keep their fields aligned when editing them.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lint/registry.hpp"

namespace sphdeck::lint {

struct RuleDocPage {
    std::string file;  // "docs/rules/SPH010.md"
    std::string code;  // from the file name: "SPH010"
    std::string name;  // from the title: "form12-requires-mpp"
    std::string what, why, fix, before, after;
    std::vector<std::string> problems;  // "docs/rules/SPH010.md:7: ..." where the page breaks its shape

    RuleDoc doc() const { return {what, why, fix, before, after}; }
};

// Reads one page. Never fails: what does not fit the shape is listed in `problems`.
RuleDocPage parse_rule_doc_page(std::string_view file, std::string_view text);

// Every embedded page, parsed once, sorted by code.
std::span<const RuleDocPage> rule_doc_pages();

// The page of a code (exact, upper case), or nullptr.
const RuleDocPage* find_rule_doc_page(std::string_view code);

// Plain text of Markdown prose: drops the backslash of escaped ASCII punctuation outside `code` spans.
std::string markdown_unescaped(std::string_view text);

namespace detail {
// One docs/rules/*.md as it was at build time; defined in the generated rule_docs_embedded.cpp.
struct EmbeddedRuleDoc {
    std::string_view file;  // "docs/rules/SPH010.md"
    std::string_view text;
};
std::span<const EmbeddedRuleDoc> embedded_rule_docs();
}  // namespace detail

}  // namespace sphdeck::lint
