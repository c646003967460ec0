#include "edit/fix_session.hpp"

#include "text/apply_edits.hpp"
#include "text/line_index.hpp"
#include "text/line_rewrite.hpp"
#include "grammar/file_paths.hpp"

namespace sphdeck::edit {
namespace {

// The first instance of the file whose canonical path is `key` (a file included twice: all read the same).
const grammar::SourceFile* file_of(const grammar::SourceMap& sources, const std::string& key) {
    for (grammar::FileId f = 0; f < sources.size(); ++f)
        if (grammar::canonical_path(sources.file(f).path).string() == key) return &sources.file(f);
    return nullptr;
}

}  // namespace

FixOutcome fix_deck(const std::string& path, engine::Documents& documents, const engine::CheckOptions& options,
                    FixLevel level, std::size_t max_rounds) {
    FixOutcome out;
    std::map<std::string, std::size_t> file_index;  // canonical path -> index in out.files
    engine::CheckResult result = engine::check_deck(path, documents, options);
    for (std::size_t round = 0; round < max_rounds; ++round) {
        const FixRound choice = choose_fixes(result.deck.sources, result.diagnostics, level);
        bool changed = false;
        for (const auto& [key, edits] : choice.edits) {
            const grammar::SourceFile* file = file_of(result.deck.sources, key);
            if (!file) continue;
            const std::string_view current = file->text.view();
            text::AppliedEdits applied = text::apply_edits(current, edits);
            if (applied.text == current) continue;
            auto [at, first_change] = file_index.try_emplace(key, out.files.size());
            if (first_change) out.files.push_back({file->path, std::string(current), {}});
            out.files[at->second].fixed = applied.text;
            documents.set(key, std::move(applied.text));
            changed = true;
        }
        // A round whose fixes change no byte would repeat itself: the findings stay as they are.
        if (!changed) break;
        out.fixed += choice.fixes;
        ++out.rounds;
        result = engine::check_deck(path, documents, options);
    }
    out.remaining = std::move(result);
    std::erase_if(out.files, [](const FixedFile& f) { return f.fixed == f.original; });
    return out;
}

std::vector<diag::TextEdit> line_edits_between(std::string_view original, std::string_view fixed) {
    std::vector<diag::TextEdit> edits;
    const text::LineIndex before(original), after(fixed);
    const std::uint32_t n = before.count(), m = after.count();
    if (m < n) return edits;  // fixes never remove a line
    const auto old_line = [&](std::uint32_t line) {
        return original.substr(before.begin(line), before.content_end(line) - before.begin(line));
    };
    const auto new_line = [&](std::uint32_t line) {
        return fixed.substr(after.begin(line), after.content_end(line) - after.begin(line));
    };
    // Each old line becomes one new line or more (lines a fix inserted above it): where an old line
    // differs from the next new line, the fewest inserted lines after which the next old line reads
    // again are given to it.
    for (std::uint32_t i = 1, j = 1; i <= n; ++i) {
        const std::uint32_t spare = (m - j) - (n - i);  // new lines not yet given to an old one
        std::uint32_t taken = 0;
        if (i == n) {
            taken = spare;
        } else if (spare > 0 && old_line(i) != new_line(j)) {
            for (std::uint32_t k = 0; k <= spare; ++k)
                if (new_line(j + 1 + k) == old_line(i + 1)) {
                    taken = k;
                    break;
                }
        }
        const std::string_view a = old_line(i);
        const std::string_view b = fixed.substr(after.begin(j), after.content_end(j + taken) - after.begin(j));
        if (a != b) edits.push_back(text::whole_line_edit(0, i, a.size(), std::string(b)));
        j += taken + 1;
    }
    return edits;
}

}  // namespace sphdeck::edit
