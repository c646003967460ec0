// Reads the embedded docs/rules/CODE.md pages into their sections (shape in lint/rule_docs.hpp).
#include "lint/rule_docs.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include <fmt/format.h>

namespace sphdeck::lint {
namespace {

constexpr std::array<std::string_view, 5> kSections = {"What it does", "Why it matters", "How to fix", "Before",
                                                       "After"};

struct Line {
    std::size_t number;  // 1-based
    std::string_view text;
};

struct DocSection {
    std::string_view heading;
    std::size_t number;  // the heading's line
    std::vector<Line> body;
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool opens_fence(std::string_view line) { return line.starts_with("```"); }
bool closes_fence(std::string_view line) { return trimmed(line) == "```"; }

// Lines without their end ("\n" or "\r\n": a checkout with Windows line ends reads the same).
std::vector<Line> lines_of(std::string_view text) {
    std::vector<Line> lines;
    for (std::size_t number = 1; !text.empty(); ++number) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (line.ends_with('\r')) line.remove_suffix(1);
        lines.push_back({number, line});
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    }
    return lines;
}

// "docs/rules/SPH010.md" -> "SPH010"
std::string code_of(std::string_view file) {
    const std::size_t slash = file.find_last_of("/\\");
    if (slash != std::string_view::npos) file.remove_prefix(slash + 1);
    if (file.ends_with(".md")) file.remove_suffix(3);
    return std::string(file);
}

class PageReader {
public:
    explicit PageReader(RuleDocPage& page) : page_(page) {}

    void problem(std::size_t line, std::string_view what) {
        page_.problems.push_back(fmt::format("{}:{}: {}", page_.file, line, what));
    }

    void title(const Line& line) {
        std::string_view rest = trimmed(line.text.substr(2));
        const std::size_t space = rest.find(' ');
        const std::string_view code = rest.substr(0, space);
        page_.name = space == std::string_view::npos ? "" : std::string(trimmed(rest.substr(space + 1)));
        if (code != page_.code)
            problem(line.number, fmt::format("the title's code '{}' is not the file's '{}'", code, page_.code));
        if (page_.name.empty() || page_.name.find(' ') != std::string::npos)
            problem(line.number, "the title must be '# CODE name', the name in kebab-case");
    }

    // One paragraph, its lines joined with one space, Markdown escapes removed.
    std::string paragraph(const DocSection& section) {
        std::string out;
        bool gap = false;
        for (const Line& line : section.body) {
            const std::string_view text = trimmed(line.text);
            if (text.empty()) {
                gap = !out.empty();
                continue;
            }
            if (gap) {
                problem(line.number, "one paragraph only: the terminal page wraps it as one");
                break;
            }
            if (!out.empty()) out += ' ';
            out += text;
        }
        if (out.empty()) problem(section.number, "the section is empty");
        return markdown_unescaped(out);
    }

    // The text of the section's one fenced block, each line ending in '\n'.
    std::string example(const DocSection& section) {
        enum { Before, Inside, After } state = Before;
        std::string out;
        for (const Line& line : section.body) {
            const bool blank = trimmed(line.text).empty();
            if (state == Before && blank) continue;
            if (state == Before && !opens_fence(line.text)) {
                problem(line.number, "expected a ```text block");
                return out;
            }
            if (state == Before) {
                state = Inside;
            } else if (state == Inside && closes_fence(line.text)) {
                state = After;
            } else if (state == Inside) {
                out += line.text;
                out += '\n';
            } else if (!blank) {
                problem(line.number, "nothing may follow the ```text block");
                break;
            }
        }
        if (state == Before)
            problem(section.number, "expected a ```text block");
        else if (state == Inside)
            problem(section.number, "the ```text block is not closed");
        else if (out.empty())
            problem(section.number, "the example is empty");
        return out;
    }

private:
    RuleDocPage& page_;
};

}  // namespace

std::string markdown_unescaped(std::string_view text) {
    std::string out;
    bool code = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (!code && c == '\\' && i + 1 < text.size() && std::ispunct(static_cast<unsigned char>(text[i + 1]))) {
            out += text[++i];
            continue;
        }
        if (c == '`') code = !code;
        out += c;
    }
    return out;
}

RuleDocPage parse_rule_doc_page(std::string_view file, std::string_view text) {
    RuleDocPage page;
    page.file = file;
    page.code = code_of(file);
    PageReader reader(page);

    // Split at the title and the "## " headings; inside a fenced block a '#' line is deck text
    // (an OpenRadioss comment), not a heading.
    std::vector<DocSection> sections;
    bool titled = false, fenced = false;
    const std::vector<Line> lines = lines_of(text);
    for (const Line& line : lines) {
        if (!fenced && !titled && sections.empty() && line.text.starts_with("# ")) {
            reader.title(line);
            titled = true;
        } else if (!fenced && line.text.starts_with("## ")) {
            sections.push_back({trimmed(line.text.substr(3)), line.number, {}});
        } else {
            if (fenced ? closes_fence(line.text) : opens_fence(line.text)) fenced = !fenced;
            if (!sections.empty())
                sections.back().body.push_back(line);
            else if (!trimmed(line.text).empty())
                reader.problem(line.number, "text before the first '## ' section");
        }
    }
    if (!titled) reader.problem(1, "the page must start with '# CODE name'");

    const std::size_t last = lines.empty() ? 1 : lines.back().number;
    for (std::size_t i = 0; i < std::max(kSections.size(), sections.size()); ++i) {
        if (i >= sections.size()) {
            reader.problem(last, fmt::format("no '## {}' section", kSections[i]));
            continue;
        }
        const DocSection& section = sections[i];
        if (i >= kSections.size() || section.heading != kSections[i]) {
            reader.problem(section.number, fmt::format("'## {}' out of place: the sections are '{}'", section.heading,
                                                       fmt::join(kSections, "', '")));
            continue;
        }
        switch (i) {
            case 0: page.what = reader.paragraph(section); break;
            case 1: page.why = reader.paragraph(section); break;
            case 2: page.fix = reader.paragraph(section); break;
            case 3: page.before = reader.example(section); break;
            default: page.after = reader.example(section); break;
        }
    }
    return page;
}

std::span<const RuleDocPage> rule_doc_pages() {
    static const std::vector<RuleDocPage> pages = [] {
        std::vector<RuleDocPage> out;
        for (const detail::EmbeddedRuleDoc& doc : detail::embedded_rule_docs())
            out.push_back(parse_rule_doc_page(doc.file, doc.text));
        std::sort(out.begin(), out.end(), [](const RuleDocPage& a, const RuleDocPage& b) { return a.code < b.code; });
        return out;
    }();
    return pages;
}

const RuleDocPage* find_rule_doc_page(std::string_view code) {
    for (const RuleDocPage& page : rule_doc_pages())
        if (page.code == code) return &page;
    return nullptr;
}

}  // namespace sphdeck::lint
