#include "lint/fold_causes.hpp"

#include <algorithm>
#include <cstdlib>
#include <tuple>
#include <optional>

#include "model/shift_diagnosis.hpp"

namespace sphdeck::lint {
namespace {

struct Cause {
    std::size_t index = 0;  // in the diagnostics
    grammar::FileId file = 0;
    std::uint32_t first = 0, last = 0;  // lines it explains
};

// The lines of the block whose first data line is `at` (DK030's place).
std::optional<std::pair<std::uint32_t, std::uint32_t>> block_lines(const grammar::RawDeck& deck,
                                                                   const grammar::Span& at) {
    for (const grammar::Block& b : deck.blocks) {
        if (b.line_count == 0) continue;
        const grammar::CardLine& first = deck.lines[b.first_line];
        if (first.file == at.file && first.line == at.line)
            return std::pair{first.line, deck.lines[b.first_line + b.line_count - 1].line};
    }
    return std::nullopt;
}

// Remarks first (how the line reads, the header), then the folded findings of the line by column, then
// those of other lines in order.
void sort_notes(std::vector<diag::Note>& notes) {
    auto key = [](const diag::Note& n) {
        if (n.span.valid()) return std::tuple{2, n.span.line, n.span.column};
        if (n.message.rfind("column ", 0) == 0)
            return std::tuple{1, 0u, static_cast<std::uint32_t>(std::strtoul(n.message.c_str() + 7, nullptr, 10))};
        return std::tuple{0, 0u, 0u};
    };
    std::stable_sort(notes.begin(), notes.end(),
                     [&](const diag::Note& a, const diag::Note& b) { return key(a) < key(b); });
}

}  // namespace

void fold_into_causes(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics) {
    std::vector<Cause> causes;
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        const diag::Diagnostic& d = diagnostics[i];
        if (d.code == "DK029" && d.severity == diag::Severity::Error) {
            causes.push_back({i, d.span.file, d.span.line, d.span.line});
        } else if (d.code == "DK030") {
            if (auto lines = block_lines(deck, d.span)) causes.push_back({i, d.span.file, lines->first, lines->second});
        }
    }
    if (causes.empty()) return;
    std::vector<bool> folded(diagnostics.size(), false);
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        diag::Diagnostic& d = diagnostics[i];
        // Causes (model::misreading_cause: a keyword line without its '*', a missing heading, a blank line read as
        // a card, a card cut, a line pasted twice, a shift itself) are not a shift's symptoms.
        if (model::misreading_cause(d.code) || !d.span.valid()) continue;
        auto cause = std::find_if(causes.begin(), causes.end(), [&](const Cause& c) {
            return c.file == d.span.file && d.span.line >= c.first && d.span.line <= c.last;
        });
        if (cause == causes.end()) continue;
        model::fold_into(diagnostics[cause->index], std::move(d));
        folded[i] = true;
    }
    for (const Cause& c : causes) sort_notes(diagnostics[c.index].notes);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < diagnostics.size(); ++i)
        if (!folded[i]) {
            if (kept != i) diagnostics[kept] = std::move(diagnostics[i]);
            ++kept;
        }
    diagnostics.resize(kept);
}

}  // namespace sphdeck::lint
