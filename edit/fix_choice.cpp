#include "edit/fix_choice.hpp"

#include <algorithm>

#include "grammar/file_paths.hpp"

namespace sphdeck::edit {
namespace {

// An edit's bytes on its line, with columns clamped to the line as text::place_edits clamps them.
struct Placed {
    std::uint32_t line = 0;
    std::size_t begin = 0, end = 0;  // 0-based, within the line's content
    const std::string* replacement = nullptr;
};

bool same(const Placed& a, const Placed& b) {
    return a.line == b.line && a.begin == b.begin && a.end == b.end && *a.replacement == *b.replacement;
}

// Whether `next` touches the text of `taken`, which was taken before it, as place_edits would see
// it: ranges that only touch do not overlap, two insertions at one place do not either.
bool overlaps(const Placed& taken, const Placed& next) {
    if (taken.line != next.line) return false;
    if (taken.begin <= next.begin) return next.begin < taken.end;
    return taken.begin < next.end;
}

using TakenEdits = std::map<std::string, std::vector<Placed>>;  // canonical path -> edits taken on it

// The canonical path of each file (grammar::canonical_path), asked of the system once per file.
class FileKeys {
public:
    explicit FileKeys(const grammar::SourceMap& sources) : sources_(sources), keys_(sources.size()) {}
    const std::string& operator[](grammar::FileId id) {
        if (keys_[id].empty()) keys_[id] = grammar::canonical_path(sources_.file(id).path).string();
        return keys_[id];
    }

private:
    const grammar::SourceMap& sources_;
    std::vector<std::string> keys_;
};

}  // namespace

const diag::Fix* chosen_fix(const diag::Diagnostic& d, FixLevel level) {
    for (const diag::Fix& fix : d.fixes)
        if (!fix.edits.empty() && (fix.safe || level == FixLevel::Unsafe)) return &fix;
    return nullptr;
}

FixRound choose_fixes(const grammar::SourceMap& sources, const std::vector<diag::Diagnostic>& diagnostics,
                      FixLevel level) {
    FixRound round;
    TakenEdits taken;
    FileKeys keys(sources);
    for (const diag::Diagnostic& d : diagnostics) {
        const diag::Fix* fix = chosen_fix(d, level);
        if (!fix) continue;
        // Place every edit of the fix first: a fix is applied whole or not at all.
        std::vector<std::pair<const std::string*, Placed>> placed;
        bool usable = true;
        for (const diag::TextEdit& e : fix->edits) {
            const grammar::Span& s = e.span;
            if (!s.valid() || s.file >= sources.size() || s.line == 0 || s.line > sources.line_count(s.file) ||
                s.column == 0 || s.end_column < s.column ||
                (level == FixLevel::Safe && e.replacement.find_first_of("\r\n") != std::string::npos)) {
                usable = false;
                break;
            }
            const std::size_t length = sources.line_text(s.file, s.line).size();
            placed.push_back({&keys[s.file], Placed{s.line, std::min<std::size_t>(s.column - 1, length),
                                                    std::min<std::size_t>(s.end_column - 1, length), &e.replacement}});
        }
        if (!usable) {
            ++round.unusable;
            continue;
        }
        bool conflict = false, all_known = true;
        for (const auto& [path, p] : placed) {
            bool known = false;
            for (const Placed& t : taken[*path]) {
                if (same(t, p))
                    known = true;
                else if (overlaps(t, p))
                    conflict = true;
            }
            all_known = all_known && known;
        }
        if (conflict) {
            ++round.deferred;
            continue;
        }
        ++round.fixes;
        if (all_known) continue;  // the same fix (two findings of one line, a file included twice): applied once
        for (std::size_t i = 0; i < placed.size(); ++i) {
            const auto& path = placed[i].first;  // plain names: clang 14 lambdas cannot capture bindings
            const auto& p = placed[i].second;
            auto& on_file = taken[*path];
            if (std::any_of(on_file.begin(), on_file.end(), [&](const Placed& t) { return same(t, p); })) continue;
            on_file.push_back(p);
            round.edits[*path].push_back(fix->edits[i]);
        }
    }
    return round;
}

}  // namespace sphdeck::edit
