// Inline suppressions: parse "$ sphdeck:" comments ("# sphdeck:" too in Radioss decks), find the
// lines each one covers, drop the diagnostics they silence, report the unused (DK026) and
// malformed (DK028) ones.
#include "lint/suppressions.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <tuple>

#include "grammar/file_paths.hpp"
#include "lint/registry.hpp"
#include "lint/rule_pages.hpp"

namespace sphdeck::lint {
namespace {

constexpr std::string_view kMarker = text::directive_marker;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::uint32_t skip_blanks(std::string_view text, std::uint32_t i) {
    while (i < text.size() && is_blank(text[i])) ++i;
    return i;
}

diag::Diagnostic bad_suppression(grammar::FileId file, std::uint32_t line, std::uint32_t begin, std::uint32_t end,
                                 std::string message) {
    return diag::Diagnostic{"DK028",
                            diag::Severity::Warning,
                            std::move(message),
                            grammar::Span{file, line, begin + 1, std::max(end, begin + 1) + 1},
                            {}};
}

// A directive and the lines of its file it covers (first == 0: none, e.g. at the end of the file).
struct Placed {
    grammar::FileId file = 0;
    Suppression directive;
    std::uint32_t first = 0, last = 0;
    std::vector<bool> used;  // per item
};

// What a line is to the directives: LS-DYNA comments start with '$' and blocks with '*'; Radioss
// comments with '#' or '$' in column 1 (but `#include` and `#enddata` are structural lines) and
// blocks with a '/' header (indented ones too: the reader takes them, with DK020).
struct LineKinds {
    bool radioss = false;

    bool comment(std::string_view line) const {
        if (line.empty()) return false;
        if (line[0] == '$') return true;
        return radioss && line[0] == '#' && !starts_with_word(line, "#include") && !starts_with_word(line, "#enddata");
    }
    bool block_start(std::string_view line) const {
        std::size_t i = 0;
        while (i < line.size() && is_blank(line[i])) ++i;
        return i < line.size() && line[i] == (radioss ? '/' : '*');
    }

private:
    static bool starts_with_word(std::string_view line, std::string_view word) {
        if (line.size() < word.size()) return false;
        for (std::size_t i = 0; i < word.size(); ++i)
            if (std::tolower(static_cast<unsigned char>(line[i])) != word[i]) return false;
        return true;
    }
};

// One pass over a file's lines: each directive waits for the next non-comment line; a block
// directive then stays open until the next keyword line.
void place_directives(const grammar::SourceFile& source, grammar::FileId file, LineKinds kinds,
                      std::vector<Placed>& out, std::vector<diag::Diagnostic>& problems) {
    std::string_view text = source.text;
    std::vector<std::size_t> pending, open;
    std::uint32_t line = 0;
    for (std::size_t pos = 0; pos < text.size();) {
        const char* nl = static_cast<const char*>(std::memchr(text.data() + pos, '\n', text.size() - pos));
        std::size_t end = nl ? static_cast<std::size_t>(nl - text.data()) : text.size();
        std::string_view content = text.substr(pos, end - pos);
        if (!content.empty() && content.back() == '\r') content.remove_suffix(1);
        pos = end + 1;
        ++line;
        if (kinds.comment(content)) {
            Placed placed{file, {}, 0, 0, {}};
            if (parse_suppression(content, file, line, placed.directive, problems)) {
                placed.used.assign(placed.directive.items.size(), false);
                if (placed.directive.scope != Suppression::Scope::File) pending.push_back(out.size());
                out.push_back(std::move(placed));
            }
            continue;
        }
        const bool keyword = kinds.block_start(content);
        if (keyword) {
            for (std::size_t i : open) out[i].last = line - 1;
            open.clear();
        }
        for (std::size_t i : pending) {
            out[i].first = out[i].last = line;
            if (keyword && out[i].directive.scope == Suppression::Scope::NextBlock) open.push_back(i);
        }
        pending.clear();
    }
    for (std::size_t i : open) out[i].last = line;
}

bool covers(const Placed& p, const grammar::Span& span) {
    if (p.file != span.file) return false;
    return p.directive.scope == Suppression::Scope::File ||
           (p.first != 0 && p.first <= span.line && span.line <= p.last);
}

// Marks the items that silence `d`; true if any does.
bool silence(std::vector<Placed>& placed, const diag::Diagnostic& d) {
    bool silenced = false;
    if (!d.span.valid()) return false;
    for (Placed& p : placed) {
        if (!covers(p, d.span)) continue;
        for (std::size_t i = 0; i < p.directive.items.size(); ++i) {
            const std::string& code = p.directive.items[i].code;
            if (code == "all" || code == d.code) p.used[i] = silenced = true;
        }
    }
    return silenced;
}

std::string unused_message(const Placed& p, const SuppressionItem& item) {
    std::string what = item.code == "all" ? std::string("all rules") : item.code;
    if (const RuleInfo* rule = find_rule(item.code)) what += " (" + std::string(rule->name) + ")";
    const char* why = p.directive.scope == Suppression::Scope::File ? "no such finding in this file"
                      : p.first == 0                                ? "no line follows it"
                      : p.directive.scope == Suppression::Scope::NextBlock && p.last > p.first
                          ? "no such finding in the block it covers"
                          : "no such finding on the line it covers";
    return "unused suppression of " + what + ": " + why;
}

}  // namespace

bool parse_suppression(std::string_view comment, grammar::FileId file, std::uint32_t line, Suppression& out,
                       std::vector<diag::Diagnostic>& problems) {
    if (comment.empty() || (comment[0] != '$' && comment[0] != '#')) return false;
    std::uint32_t i = skip_blanks(comment, 1);
    if (comment.substr(i, kMarker.size()) != kMarker) return false;
    i = skip_blanks(comment, static_cast<std::uint32_t>(i + kMarker.size()));
    if (i >= comment.size() || comment[i] != ':') return false;
    out = Suppression{};
    out.line = line;

    const std::uint32_t action_begin = skip_blanks(comment, i + 1);
    std::uint32_t j = action_begin;
    while (j < comment.size() && comment[j] != '=' && !is_blank(comment[j])) ++j;
    const std::string_view action = comment.substr(action_begin, j - action_begin);
    if (action == "disable")
        out.scope = Suppression::Scope::NextBlock;
    else if (action == "disable-next-line")
        out.scope = Suppression::Scope::NextLine;
    else if (action == "disable-file")
        out.scope = Suppression::Scope::File;
    else {
        problems.push_back(bad_suppression(file, line, action_begin, j,
                                           "unknown suppression '" + std::string(action) +
                                               "'; expected disable=, disable-next-line= or disable-file="));
        return true;
    }
    j = skip_blanks(comment, j);
    if (j >= comment.size() || comment[j] != '=') {
        problems.push_back(bad_suppression(file, line, action_begin, j,
                                           "expected '=' and rule codes after '" + std::string(action) + "'"));
        return true;
    }
    // The list runs up to " --" (the reason) or the end of the line.
    std::string_view rest = comment.substr(j + 1);
    std::size_t reason = rest.find("--");
    std::string_view list = rest.substr(0, reason);
    std::uint32_t base = j + 1;
    std::size_t item_begin = 0;
    do {
        std::size_t comma = list.find(',', item_begin);
        std::size_t item_end = comma == std::string_view::npos ? list.size() : comma;
        std::size_t b = item_begin, e = item_end;
        while (b < e && is_blank(list[b])) ++b;
        while (e > b && is_blank(list[e - 1])) --e;
        const std::string_view word = list.substr(b, e - b);
        const auto col = static_cast<std::uint32_t>(base + b), end_col = static_cast<std::uint32_t>(base + e);
        if (word.empty()) {
            problems.push_back(bad_suppression(file, line, col, end_col, "empty rule code in suppression list"));
        } else if (word.find_first_of(" \t") != std::string_view::npos) {
            problems.push_back(bad_suppression(file, line, col, end_col,
                                               "expected ',' between rule codes, or ' -- ' before the reason, in '" +
                                                   std::string(word) + "'"));
        } else if (word == "all") {
            out.items.push_back({"all", col + 1, end_col + 1});
        } else if (const RuleInfo* rule = find_rule(word)) {
            out.items.push_back({std::string(rule->code), col + 1, end_col + 1});
        } else {
            problems.push_back(
                bad_suppression(file, line, col, end_col,
                                "unknown rule '" + std::string(word) + "' in suppression" + did_you_mean_rule(word)));
        }
        item_begin = item_end + 1;
    } while (item_begin <= list.size());
    return true;
}

bool may_hold_suppressions(std::string_view text) { return text.find(kMarker) != std::string_view::npos; }

void apply_suppressions(const grammar::SourceMap& sources, std::vector<diag::Diagnostic>& diagnostics,
                        grammar::DeckFormat format, std::vector<bool>* marker_free,
                        const DirectiveScan& may_hold_directives) {
    const LineKinds kinds{format == grammar::DeckFormat::Radioss};
    std::vector<Placed> placed;
    std::vector<diag::Diagnostic> problems;
    if (marker_free) marker_free->resize(sources.size(), false);
    for (grammar::FileId f = 0; f < sources.size(); ++f) {
        if (marker_free && (*marker_free)[f]) continue;  // known to hold none
        const grammar::SourceFile& source = sources.file(f);
        // The common case: no directive. A directive is a comment line holding the marker (parse_suppression):
        // the reader of a big file looked at each such line already, so its text is not read again.
        const bool none = source.comment_holds_marker ? !*source.comment_holds_marker
                          : may_hold_directives       ? !may_hold_directives(source, kMarker)
                                                      : !source.text.contains(kMarker);
        if (marker_free) (*marker_free)[f] = none;
        if (none) continue;
        place_directives(source, f, kinds, placed, problems);
    }
    if (placed.empty() && problems.empty()) return;

    std::erase_if(diagnostics, [&](const diag::Diagnostic& d) { return silence(placed, d); });

    // A file included twice (by one name or by two: a symbolic link) holds its directives twice: an item
    // counts as used if any copy was, and each finding about a directive is reported once, at its first copy.
    std::map<grammar::FileId, std::string> canonical_paths;
    const auto canonical = [&](grammar::FileId file) -> const std::string& {
        auto [it, fresh] = canonical_paths.try_emplace(file);
        if (fresh) it->second = grammar::canonical_path(sources.file(file).path).string();
        return it->second;
    };
    using Where = std::tuple<std::string, std::uint32_t, std::uint32_t, std::string>;  // path, line, column, code
    std::map<Where, std::pair<diag::Diagnostic, bool>> unused;
    for (const Placed& p : placed) {
        for (std::size_t i = 0; i < p.directive.items.size(); ++i) {
            const SuppressionItem& item = p.directive.items[i];
            Where key{canonical(p.file), p.directive.line, item.column, item.code};
            diag::Diagnostic d{"DK026",
                               diag::Severity::Info,
                               unused_message(p, item),
                               grammar::Span{p.file, p.directive.line, item.column, item.end_column},
                               {}};
            auto [it, fresh] = unused.try_emplace(key, std::move(d), p.used[i]);
            if (!fresh) it->second.second = it->second.second || p.used[i];
        }
    }
    std::map<Where, diag::Diagnostic> reports;
    for (auto& [key, entry] : unused)
        if (!entry.second) reports.emplace(key, std::move(entry.first));
    for (diag::Diagnostic& d : problems)
        reports.emplace(Where{canonical(d.span.file), d.span.line, d.span.column, d.message}, std::move(d));
    // `disable-file=DK026` (or DK028) also silences these reports in its file.
    for (auto& entry : reports) {
        diag::Diagnostic& d = entry.second;
        bool silenced = false;
        for (const Placed& p : placed)
            if (p.directive.scope == Suppression::Scope::File && covers(p, d.span))
                for (const SuppressionItem& item : p.directive.items)
                    silenced |= item.code == "all" || item.code == d.code;
        if (!silenced) diagnostics.push_back(std::move(d));
    }
    diag::sort_by_location(diagnostics);
}

}  // namespace sphdeck::lint
