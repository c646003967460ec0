#include "text/apply_edits.hpp"

#include <algorithm>
#include <optional>

#include "text/line_index.hpp"

namespace sphdeck::text {
namespace {

// The bytes an edit replaces, or nothing when its line does not exist or its columns are reversed.
std::optional<PlacedEdit> place(const LineIndex& lines, const TextEdit& edit) {
    const auto& span = edit.span;
    if (span.line == 0 || span.line > lines.count() || span.column == 0 || span.end_column < span.column)
        return std::nullopt;
    const std::size_t line_begin = lines.begin(span.line);
    const std::size_t length = lines.content_end(span.line) - line_begin;
    const auto clamp = [&](std::uint32_t column) { return line_begin + std::min<std::size_t>(column - 1, length); };
    return PlacedEdit{clamp(span.column), clamp(span.end_column), span.line, &edit.replacement};
}

}  // namespace

PlacedEdits place_edits(std::string_view text, const std::vector<TextEdit>& edits) {
    const LineIndex lines(text);
    struct Candidate {
        PlacedEdit edit;
        std::size_t order;
    };
    PlacedEdits result;
    std::vector<Candidate> candidates;
    candidates.reserve(edits.size());
    for (std::size_t i = 0; i < edits.size(); ++i) {
        if (const auto placed = place(lines, edits[i]))
            candidates.push_back({*placed, i});
        else
            ++result.skipped;
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.edit.begin != b.edit.begin ? a.edit.begin < b.edit.begin : a.order < b.order;
    });
    std::size_t taken_to = 0;  // end of the last edit taken
    for (const auto& candidate : candidates) {
        // Ranges that only touch (one ends where the next begins) do not overlap.
        if (!result.edits.empty() && candidate.edit.begin < taken_to) {
            ++result.skipped;
            continue;
        }
        result.edits.push_back(candidate.edit);
        taken_to = candidate.edit.end;
    }
    return result;
}

AppliedEdits apply_edits(std::string_view text, const std::vector<TextEdit>& edits) {
    const auto placed = place_edits(text, edits);
    AppliedEdits result;
    result.text.reserve(text.size());
    std::size_t copied_to = 0;
    for (const auto& edit : placed.edits) {
        result.text.append(text.substr(copied_to, edit.begin - copied_to));
        result.text.append(*edit.replacement);
        copied_to = edit.end;
    }
    result.text.append(text.substr(copied_to));
    result.applied = placed.edits.size();
    result.skipped = placed.skipped;
    return result;
}

}  // namespace sphdeck::text
