#include "grammar/dropped_after_end.hpp"

#include <algorithm>
#include <cctype>

namespace sphdeck::grammar {
namespace {

// Blocks that define or load nothing: text, the deck's frame, and *INCLUDE (PRIMER's "post END" includes).
bool dyna_counts(std::string_view keyword) {
    for (std::string_view inert : {"*END", "*KEYWORD", "*COMMENT", "*TITLE"})
        if (keyword == inert || (keyword.starts_with(inert) && keyword.substr(inert.size()).starts_with("_")))
            return false;
    return !keyword.starts_with("*INCLUDE") && keyword.size() > 1 &&
           std::isalpha(static_cast<unsigned char>(keyword[1]));
}

// HyperMesh's dummy-positioning metadata after /END, and the deck's frame.
bool radioss_counts(std::string_view header) {
    for (std::string_view inert : {"/DUMMY", "/ASSEMBLY", "/POSITION", "/END", "/TITLE"})
        if (header.starts_with(inert)) return false;
    return true;
}

// "/MAT/LAW6/2" -> "/MAT/LAW6": the kind, without its id.
std::string radioss_kind(std::string_view header) {
    while (true) {
        const std::size_t slash = header.rfind('/');
        if (slash == 0 || slash == std::string_view::npos) break;
        const std::string_view last = header.substr(slash + 1);
        if (last.empty() ||
            !std::all_of(last.begin(), last.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
            break;
        header = header.substr(0, slash);
    }
    return std::string(header);
}

}  // namespace

void DroppedAfterEnd::add(std::string kind) {
    ++count_;
    if (kinds_.size() < max_kinds && std::find(kinds_.begin(), kinds_.end(), kind) == kinds_.end())
        kinds_.push_back(std::move(kind));
}

void DroppedAfterEnd::note_dyna(std::string_view keyword) {
    if (ended() && dyna_counts(keyword)) add(std::string(keyword));
}

void DroppedAfterEnd::note_radioss(std::string_view header, bool known) {
    if (ended() && known && radioss_counts(header)) add(radioss_kind(header));
}

std::optional<diag::Diagnostic> DroppedAfterEnd::finding(std::string_view end_word, bool include) const {
    if (count_ == 0) return std::nullopt;
    std::string kinds;
    for (const std::string& k : kinds_) kinds += (kinds.empty() ? "" : ", ") + k;
    if (count_ > kinds_.size()) kinds += ", ...";
    const bool dyna = end_word.starts_with("*");
    std::string where = dyna ? (include ? "LS-DYNA stops reading this include file here (and goes on with the file "
                                          "that included it)"
                                        : "LS-DYNA stops reading the deck here")
                             : "the starter stops reading the deck here";
    diag::Diagnostic d{"DK017",
                       diag::Severity::Warning,
                       std::string(end_word) + " before " + std::to_string(count_) + " keyword block" +
                           (count_ == 1 ? "" : "s") + ": " + where + "; " + (count_ == 1 ? "it is" : "they are") +
                           " never read (" + kinds + ")",
                       end_,
                       {}};
    constexpr std::uint32_t whole_line = 1u << 30;  // clamped to the line's end (text/apply_edits.hpp)
    // Judgement: the blocks after it may be meant to be dropped (a deck kept for reference).
    d.fixes.push_back(
        {"comment out the " + std::string(end_word) + " line, so that the blocks after it are read",
         false,
         {{Span{end_.file, end_.line, 1, whole_line}, std::string(dyna ? "$ " : "# ") + std::string(end_word)}}});
    return d;
}

void DroppedAfterEnd::report(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view end_word,
                             bool include) const {
    auto found = finding(end_word, include);
    if (!found) return;
    for (std::size_t i = from; i < out.size(); ++i) {
        if (out[i].code == "DK017" && out[i].span.file == found->span.file && out[i].severity == diag::Severity::Info) {
            out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
            break;
        }
    }
    out.push_back(std::move(*found));
}

}  // namespace sphdeck::grammar
