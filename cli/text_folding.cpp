#include "cli/text_folding.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <utility>

#include "diag/render_text.hpp"

namespace sphdeck::cli {
namespace {

constexpr std::size_t no_block = static_cast<std::size_t>(-1);

// The block whose keyword line or card lines hold a span: per file, line ranges sorted by start.
class BlockOfLine {
public:
    explicit BlockOfLine(const grammar::RawDeck& deck) {
        for (std::size_t i = 0; i < deck.blocks.size(); ++i) {
            const grammar::Block& b = deck.blocks[i];
            if (!b.span.valid()) continue;
            std::uint32_t last = b.span.line;
            for (const grammar::CardLine* l = deck.begin_lines(b); l != deck.end_lines(b); ++l)
                if (l->file == b.span.file) last = std::max(last, l->line);
            ranges_[b.span.file].push_back({b.span.line, last, i});
        }
        for (auto& [file, ranges] : ranges_) std::sort(ranges.begin(), ranges.end());
    }

    std::size_t operator()(const grammar::Span& span) const {
        auto it = ranges_.find(span.file);
        if (!span.valid() || it == ranges_.end()) return no_block;
        const auto& r = it->second;
        auto after = std::upper_bound(r.begin(), r.end(), Range{span.line, UINT32_MAX, no_block});
        if (after == r.begin()) return no_block;
        --after;
        return span.line <= after->last ? after->block : no_block;
    }

private:
    struct Range {
        std::uint32_t first, last;
        std::size_t block;
        bool operator<(const Range& o) const {
            return std::tie(first, last, block) < std::tie(o.first, o.last, o.block);
        }
    };
    std::map<grammar::FileId, std::vector<Range>> ranges_;
};

struct Run {
    std::size_t count = 0, seen = 0;
    std::vector<std::uint32_t> folded_lines;  // the first few lines past kShownPerBlock
};

}  // namespace

std::vector<TextItem> fold_for_text(const std::vector<diag::Diagnostic>& findings, const grammar::RawDeck& deck,
                                    std::size_t max_per_code) {
    std::vector<TextItem> out;
    if (max_per_code == 0) {
        for (const diag::Diagnostic& d : findings) out.push_back({&d, {}});
        return out;
    }
    const BlockOfLine block_of(deck);
    std::vector<std::size_t> block(findings.size());
    std::map<std::pair<std::size_t, std::string>, Run> runs;
    for (std::size_t i = 0; i < findings.size(); ++i) {
        block[i] = block_of(findings[i].span);
        if (block[i] == no_block) continue;
        Run& r = runs[{block[i], findings[i].code}];
        if (++r.count > kShownPerBlock && r.folded_lines.size() < 5) r.folded_lines.push_back(findings[i].span.line);
    }
    std::map<std::string, std::size_t> shown, hidden;
    std::map<std::string, const diag::Diagnostic*> first_hidden;  // where a fold line of a code points
    for (std::size_t i = 0; i < findings.size(); ++i) {
        const diag::Diagnostic& d = findings[i];
        if (block[i] != no_block) {
            Run& r = runs[{block[i], d.code}];
            const std::size_t k = ++r.seen;
            if (r.count > kShownPerBlock + 1 && k > kShownPerBlock) {
                if (k == kShownPerBlock + 1 && shown[d.code] >= max_per_code) {
                    hidden[d.code] += r.count - kShownPerBlock;
                    first_hidden.try_emplace(d.code, &d);
                } else if (k == kShownPerBlock + 1) {
                    std::string lines;
                    for (std::size_t n = 0; n < r.folded_lines.size(); ++n)
                        lines += (n ? ", " : "") + std::to_string(r.folded_lines[n]);
                    if (r.count - kShownPerBlock > r.folded_lines.size()) lines += ", ...";
                    out.push_back(
                        {nullptr, fmt::format("{}: note: {} more {} finding(s) on the lines of this {} "
                                              "block: lines {} (--max-per-code 0 shows all) [{}]\n",
                                              diag::detail::location(d.span, deck.sources), r.count - kShownPerBlock,
                                              d.code, deck.blocks[block[i]].keyword, lines, d.code)});
                }
                continue;
            }
        }
        if (shown[d.code] >= max_per_code) {
            ++hidden[d.code];
            first_hidden.try_emplace(d.code, &d);
            continue;
        }
        ++shown[d.code];
        out.push_back({&d, {}});
    }
    // In the concise pattern (file:line:col: severity: message [CODE]) at the first finding not shown, so
    // that grep, problem matchers and CI parsers read the fold line as any other.
    for (const auto& [code, n] : hidden)
        out.push_back(
            {nullptr, fmt::format("{}: note: {} more {} finding(s) not shown (--max-per-code 0 shows all) "
                                  "[{}]\n",
                                  diag::detail::location(first_hidden.at(code)->span, deck.sources), n, code, code)});
    return out;
}

}  // namespace sphdeck::cli
