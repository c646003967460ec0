#include "cli/text_folding.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <utility>

#include "diag/render_text.hpp"

namespace sphdeck::cli {
namespace {

constexpr std::size_t no_block = static_cast<std::size_t>(-1);

// The block whose keyword line or card lines hold a span: per file, the blocks sorted by their keyword
// line. A block's last line is found when a span falls after its keyword line, once: a pass over every
// card line of a deck (two million for a 1M-particle mesh) for a handful of findings costs more than
// the folding (the decks of a run over one mesh each paid it).
class BlockOfLine {
public:
    explicit BlockOfLine(const grammar::RawDeck& deck) : deck_(deck), last_(deck.blocks.size(), unknown) {
        for (std::size_t i = 0; i < deck.blocks.size(); ++i) {
            const grammar::Block& b = deck.blocks[i];
            if (b.span.valid()) starts_[b.span.file].push_back({b.span.line, i});
        }
        for (auto& [file, starts] : starts_) std::sort(starts.begin(), starts.end());
    }

    std::size_t operator()(const grammar::Span& span) const {
        auto it = starts_.find(span.file);
        if (!span.valid() || it == starts_.end()) return no_block;
        const auto& r = it->second;
        auto after = std::upper_bound(r.begin(), r.end(), Start{span.line, no_block});
        if (after == r.begin()) return no_block;
        --after;
        return span.line <= last_line(after->block) ? after->block : no_block;
    }

private:
    static constexpr std::uint32_t unknown = UINT32_MAX;
    struct Start {
        std::uint32_t line;  // the keyword line: one block a line in a file
        std::size_t block;
        bool operator<(const Start& o) const { return std::tie(line, block) < std::tie(o.line, o.block); }
    };
    // The last line of block `i` in its keyword's file.
    std::uint32_t last_line(std::size_t i) const {
        if (last_[i] != unknown) return last_[i];
        const grammar::Block& b = deck_.blocks[i];
        std::uint32_t last = b.span.line;
        for (grammar::CardLinePtr l = deck_.begin_lines(b); l != deck_.end_lines(b); ++l)
            if (l->file == b.span.file) last = std::max(last, l->line);
        return last_[i] = last;
    }
    const grammar::RawDeck& deck_;
    std::map<grammar::FileId, std::vector<Start>> starts_;
    mutable std::vector<std::uint32_t> last_;  // by block; `unknown` until asked
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
