// Rule documentation as terminal pages, a table, and Markdown (docs/rules.md, SARIF help).
#include "lint/rule_pages.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace sphdeck::lint {
namespace {

constexpr std::size_t kWidth = 80;

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

// Greedy word wrap of one paragraph, every line indented.
std::string wrap(std::string_view text, std::size_t indent) {
    std::string out, line(indent, ' ');
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view word = text.substr(start, end - start);
        start = end + 1;
        if (word.empty()) continue;
        if (line.size() > indent && line.size() + 1 + word.size() > kWidth) {
            out += line + '\n';
            line.assign(indent, ' ');
        }
        if (line.size() > indent) line += ' ';
        line += word;
    }
    if (line.size() > indent) out += line + '\n';
    return out;
}

std::string indented(std::string_view block, std::size_t indent) {
    std::string out;
    while (!block.empty()) {
        std::size_t nl = block.find('\n');
        std::string_view line = block.substr(0, nl);
        out += line.empty() ? std::string() : std::string(indent, ' ') + std::string(line);
        out += '\n';
        if (nl == std::string_view::npos) break;
        block.remove_prefix(nl + 1);
    }
    return out;
}

// Backslash-escapes what Markdown would read as markup ("*PART ... *MAT_" as emphasis), except
// inside `code` spans; `table` also escapes the cell separator.
std::string md(std::string_view text, bool table = false) {
    std::string out;
    bool code = false;
    char previous = ' ';
    for (char c : text) {
        if (c == '`') code = !code;
        // '_' only opens emphasis at the start of a word: CONTROL_SPH stays readable.
        bool word_start_underscore = c == '_' && !std::isalnum(static_cast<unsigned char>(previous));
        if (!code && (c == '*' || c == '<' || c == '\\' || word_start_underscore || (table && c == '|'))) out += '\\';
        out += c;
        previous = c;
    }
    return out;
}

std::string fenced_text(std::string_view deck) {
    std::string out = "```text\n" + std::string(deck);
    if (!out.ends_with('\n')) out += '\n';
    return out + "```\n";
}

// The table's word: blank for none, so the rules that can fix stand out.
std::string_view fix_column(Fixable f) {
    switch (f) {
        case Fixable::None: return "";
        case Fixable::Mixed: return "mixed";
        default: return to_string(f);
    }
}

std::string fix_sentence(Fixable f) {
    switch (f) {
        case Fixable::Safe: return "safe (applied by `sphdeck check --fix` where the finding carries one)";
        case Fixable::Unsafe: return "unsafe (a judgement: applied by `sphdeck check --fix --unsafe-fixes` only)";
        case Fixable::Mixed: return "safe or unsafe, per finding (`--fix` applies the safe ones)";
        case Fixable::None: break;
    }
    return "none";
}

}  // namespace

std::string did_you_mean_rule(std::string_view query) {
    std::string list;
    for (std::string_view s : similar_rules(query)) list += (list.empty() ? "'" : ", '") + std::string(s) + "'";
    return list.empty() ? list : "; did you mean " + list + "?";
}

std::string rule_url(const RuleInfo& rule) { return std::string(rules_doc_url) + "#" + lower(rule.code); }

std::string rule_text_body(const RuleInfo& rule) {
    std::string out;
    out += "What it does\n" + wrap(rule.doc.what, 2);
    out += "\nWhy it matters\n" + wrap(rule.doc.why, 2);
    out += "\nHow to fix\n" + wrap(rule.doc.fix, 2);
    out += "\nExample\n  Triggers the rule:\n" + indented(rule.doc.before, 4);
    out += "  Fixed:\n" + indented(rule.doc.after, 4);
    return out;
}

std::string render_rule_page(const RuleInfo& rule) {
    std::string out = fmt::format("{} {} ({})\n", rule.code, rule.name, diag::to_string(rule.severity));
    out += wrap(rule.summary, 0) + "\n" + rule_text_body(rule);
    out += fmt::format("\nFix: {}.\nSource: {}; since {}. Silence it with `$ sphdeck: disable={}`.\n{}\n",
                       fix_sentence(rule.fix), rule.source, rule.since, rule.code, rule_url(rule));
    return out;
}

std::string render_rules_table() {
    std::size_t name_width = 4;
    for (const RuleInfo& rule : all_rules()) name_width = std::max(name_width, rule.name.size());
    std::string out =
        fmt::format("{:<7} {:<{}} {:<8} {:<6} {}\n", "CODE", "NAME", name_width, "SEVERITY", "FIX", "SUMMARY");
    for (const RuleInfo& rule : all_rules())
        out += fmt::format("{:<7} {:<{}} {:<8} {:<6} {}\n", rule.code, rule.name, name_width,
                           diag::to_string(rule.severity), fix_column(rule.fix), rule.summary);
    return out;
}

std::string rule_markdown_body(const RuleInfo& rule) {
    std::string out = fmt::format("**Severity:** {} · **Fix:** {} · **Source:** {} · **Since:** {}\n\n{}{}\n",
                                  diag::to_string(rule.severity), to_string(rule.fix), md(rule.source), rule.since,
                                  md(rule.summary), rule.summary.ends_with('.') ? "" : ".");
    out += "\n### What it does\n\n" + md(rule.doc.what) + "\n";
    out += "\n### Why it matters\n\n" + md(rule.doc.why) + "\n";
    out += "\n### How to fix\n\n" + md(rule.doc.fix) + "\n";
    out += "\n### Example\n\nTriggers the rule:\n\n" + fenced_text(rule.doc.before);
    out += "\nFixed:\n\n" + fenced_text(rule.doc.after);
    return out;
}

std::string render_rules_markdown() {
    std::string out =
        "# sphdeck rules\n\n"
        "<!-- Generated by `sphdeck rules --format markdown` from the registry (lint/registry_rows.cpp) and\n"
        "     the pages docs/rules/CODE.md: edit those, then regenerate this file. A test fails when the two\n"
        "     differ. -->\n\n"
        "Every rule `sphdeck check` reports, with its code, name and default severity. `sphdeck rule CODE`\n"
        "prints one section in the terminal. Silence a rule in a deck with `$ sphdeck: disable=CODE -- reason`\n"
        "on the comment line before the keyword or line, or for a whole project in `sphdeck.toml`.\n\n"
        "The fix column says whether findings carry a fix that `sphdeck check --fix` applies (safe) or that\n"
        "`--unsafe-fixes` adds (unsafe, a judgement); the editor offers the same fixes as code actions.\n\n"
        "| code | name | severity | fix | summary |\n|---|---|---|---|---|\n";
    for (const RuleInfo& rule : all_rules())
        out += fmt::format("| [{}](#{}) | {} | {} | {} | {} |\n", rule.code, lower(rule.code), rule.name,
                           diag::to_string(rule.severity), fix_column(rule.fix), md(rule.summary, true));
    for (const RuleInfo& rule : all_rules())
        out += fmt::format("\n<a id=\"{}\"></a>\n\n## {} {}\n\n", lower(rule.code), rule.code, rule.name) +
               rule_markdown_body(rule);
    return out;
}

}  // namespace sphdeck::lint
