#include "engine/mended_consequences.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "text/apply_edits.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::engine {
namespace {

// A cause whose mend is a judgement (unsafe fix) yet whose consequences the deck shows the same way: a
// stray *END (DK017 warning: the blocks after it are read once it is gone), a *PART heading line
// missing (DK032), a keyword line that lost its '*' (DK033), a blank line read as a card (DK034), a card cut
// above a line (DK035), a line pasted twice (DK036), two lines joined (DK037), a line broken in two (DK038).
bool judged_cause(const diag::Diagnostic& d) {
    return (d.code == "DK017" && d.severity == diag::Severity::Warning) || d.code == "DK032" || d.code == "DK033" ||
           d.code == "DK034" || d.code == "DK035" || d.code == "DK036" || d.code == "DK037" || d.code == "DK038";
}

bool is_cause(const diag::Diagnostic& d) {
    const bool shift = d.code == "DK029" && d.severity == diag::Severity::Error;
    return ((shift || d.code == "DK030") || judged_cause(d)) && !d.fixes.empty() &&
           (d.fixes.front().safe || judged_cause(d)) && !d.fixes.front().edits.empty();
}

using Place = std::tuple<std::string, grammar::FileId, std::uint32_t, std::uint32_t>;
Place place_of(const diag::Diagnostic& d) { return {d.code, d.span.file, d.span.line, d.span.column}; }

// Where the mended files' lines were in the deck as read: a fix that inserts lines (DK032's blank heading,
// DK035's cards of defaults) moves every line after them down, and a finding there has not gone, it moved.
class MendedLines {
public:
    explicit MendedLines(const diag::Fix& fix) {
        for (const diag::TextEdit& e : fix.edits)
            if (const auto added =
                    static_cast<std::uint32_t>(std::count(e.replacement.begin(), e.replacement.end(), '\n')))
                inserted_[e.span.file].push_back({e.span.line, added});
        for (auto& [file, lines] : inserted_) std::sort(lines.begin(), lines.end());
    }
    // The deck's line of line `mended` of `file` after the fix (an inserted line: the line it was inserted on).
    std::uint32_t original(grammar::FileId file, std::uint32_t mended) const {
        const auto found = inserted_.find(file);
        if (found == inserted_.end()) return mended;
        std::uint32_t moved = 0;
        for (const auto& [line, added] : found->second) {
            if (mended < line + moved) break;
            if (mended <= line + moved + added) return line;
            moved += added;
        }
        return mended - moved;
    }
    Place place_of(const diag::Diagnostic& d) const {
        return {d.code, d.span.file, original(d.span.file, d.span.line), d.span.column};
    }

private:
    std::map<grammar::FileId, std::vector<std::pair<std::uint32_t, std::uint32_t>>> inserted_;  // line, lines added
};

// The deck's files with the cause's fix applied, over the caller's documents.
grammar::FileOverlay mended_files(const grammar::RawDeck& deck, const diag::Fix& fix,
                                  const grammar::FileOverlay* documents) {
    grammar::FileOverlay mended = documents ? *documents : grammar::FileOverlay{};
    std::map<grammar::FileId, std::vector<diag::TextEdit>> by_file;
    for (const diag::TextEdit& e : fix.edits)
        if (e.span.valid()) by_file[e.span.file].push_back(e);
    for (const auto& [file, edits] : by_file) {
        const grammar::SourceFile& source = deck.sources.file(file);
        mended.set(source.path, text::apply_edits(std::string_view(source.text), edits).text);
    }
    return mended;
}

// The lines a cause stands for: its own line, or (DK030) the lines its fix rewrites. Not the line of DK035,
// DK036, DK037 or DK038: it is read as the wrong card (or as two), so the findings on it are as much its
// consequences as those after it.
bool on_cause_lines(const diag::Diagnostic& d, const std::vector<const diag::Diagnostic*>& causes) {
    return std::any_of(causes.begin(), causes.end(), [&](const diag::Diagnostic* c) {
        if (c->code == "DK035" || c->code == "DK036" || c->code == "DK037" || c->code == "DK038") return false;
        if (c->span.file == d.span.file && c->span.line == d.span.line) return true;
        const auto& edits = c->fixes.front().edits;
        return std::any_of(edits.begin(), edits.end(), [&](const diag::TextEdit& e) {
            return e.span.file == d.span.file && e.span.line == d.span.line;
        });
    });
}

}  // namespace

void fold_mended_consequences(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics,
                              const grammar::FileOverlay* documents, const RecheckMended& recheck) {
    std::vector<std::size_t> cause_at;
    for (std::size_t i = 0; i < diagnostics.size(); ++i)
        if (is_cause(diagnostics[i])) cause_at.push_back(i);
    if (cause_at.empty() || cause_at.size() > max_mended_causes || deck.lines.size() > max_mended_deck_lines) return;
    std::vector<const diag::Diagnostic*> causes;
    for (std::size_t i : cause_at) causes.push_back(&diagnostics[i]);
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < diagnostics.size(); ++i) {
        const diag::Diagnostic& d = diagnostics[i];
        if (model::misreading_cause(d.code) || is_cause(d) || on_cause_lines(d, causes)) continue;
        candidates.push_back(i);
    }
    if (candidates.empty()) return;

    std::vector<int> folded_into(diagnostics.size(), -1);
    for (std::size_t k = 0; k < cause_at.size(); ++k) {
        std::multiset<Place> after;
        // A finding the re-check folds into a cause of its own line (a shift the mended deck's habit now shows)
        // is not gone: it stays, on that line.
        std::set<std::pair<grammar::FileId, std::uint32_t>> cause_lines;
        const diag::Fix& fix = diagnostics[cause_at[k]].fixes.front();
        const MendedLines lines(fix);
        for (const diag::Diagnostic& d : recheck(mended_files(deck, fix, documents))) {
            after.insert(lines.place_of(d));
            if (model::misreading_cause(d.code) || is_cause(d))
                cause_lines.insert({d.span.file, lines.original(d.span.file, d.span.line)});
        }
        for (std::size_t i : candidates)
            if (folded_into[i] < 0 && after.count(place_of(diagnostics[i])) == 0 &&
                cause_lines.count({diagnostics[i].span.file, diagnostics[i].span.line}) == 0)
                folded_into[i] = static_cast<int>(cause_at[k]);
    }
    for (std::size_t i : candidates)
        if (folded_into[i] >= 0) {
            diag::Diagnostic& cause = diagnostics[static_cast<std::size_t>(folded_into[i])];
            // A cause is as grave as what it brings about (an *END that drops a part the particles name).
            cause.severity = std::max(cause.severity, diagnostics[i].severity);
            model::fold_into(cause, std::move(diagnostics[i]));
        }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < diagnostics.size(); ++i)
        if (folded_into[i] < 0) {
            if (kept != i) diagnostics[kept] = std::move(diagnostics[i]);
            ++kept;
        }
    diagnostics.resize(kept);
}

}  // namespace sphdeck::engine
