#include "lint/fragment_ids.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <string_view>

#include "grammar/read_deck.hpp"

namespace sphdeck::lint {
namespace {

// The REF codes of a missing definition, with what they count.
constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kUndefined{{
    {"REF001", "node"},
    {"REF002", "part"},
    {"REF003", "section"},
    {"REF004", "material"},
    {"REF005", "equation of state"},
    {"REF008", "set"},
    {"REF009", "curve, box or other id"},
}};

constexpr std::size_t kMostNotes = 20;  // the rest are counted, as text folding does

std::string_view undefined_kind(std::string_view code) {
    for (const auto& [c, kind] : kUndefined)
        if (c == code) return kind;
    return {};
}

bool in_main_file(const diag::Diagnostic& d) { return d.span.valid() && d.span.file == 0; }

std::string plural(std::size_t n, std::string_view word) {
    return fmt::format("{} {}{}", n, word, n == 1 ? "" : (word.back() == 'x' ? "es" : "s"));
}

}  // namespace

bool is_include_fragment(const grammar::RawDeck& deck) {
    if (deck.sources.size() == 0) return false;
    const std::string_view required = grammar::format_of(deck) == grammar::DeckFormat::Radioss ? "/BEGIN" : "*KEYWORD";
    return std::none_of(deck.blocks.begin(), deck.blocks.end(), [&](const grammar::Block& b) {
        return b.span.file == 0 && std::string_view(b.keyword).substr(0, required.size()) == required;
    });
}

void summarize_fragment_ids(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& diagnostics) {
    if (!is_include_fragment(deck)) return;
    // SPH120 (no *CONTROL_SPH) and SPH121 (planar particles in a run 3D by default) judge settings the
    // including deck makes: a fragment without *CONTROL_SPH says nothing about them.
    const auto about_the_deck = [](const diag::Diagnostic& d) { return d.code == "SPH120" || d.code == "SPH121"; };
    std::vector<diag::Diagnostic> folded, kept;
    for (auto& d : diagnostics)
        ((in_main_file(d) && (!undefined_kind(d.code).empty() || d.code == "REF007" || about_the_deck(d))) ? folded
                                                                                                           : kept)
            .push_back(std::move(d));
    if (folded.empty()) {
        diagnostics = std::move(kept);
        return;
    }
    std::map<std::string_view, std::size_t> undefined_by_kind;
    std::size_t unused = 0, settings = 0;
    for (const auto& d : folded) {
        if (d.code == "REF007")
            ++unused;
        else if (about_the_deck(d))
            ++settings;
        else
            ++undefined_by_kind[undefined_kind(d.code)];
    }
    std::string named;
    std::size_t undefined = 0;
    for (const auto& [kind, n] : undefined_by_kind) {
        named += fmt::format("{}{}", named.empty() ? "" : ", ", plural(n, kind));
        undefined += n;
    }
    std::string message = "this file has no ";
    message += grammar::format_of(deck) == grammar::DeckFormat::Radioss ? "/BEGIN" : "*KEYWORD";
    message += ", so it is an include fragment checked on its own:";
    if (undefined > 0)
        message += fmt::format(" {} {} named here {} defined elsewhere ({})", undefined, undefined == 1 ? "id" : "ids",
                               undefined == 1 ? "is" : "are", named);
    if (unused > 0)
        message += fmt::format("{} {} defined here {} used elsewhere", undefined > 0 ? ";" : "", plural(unused, "id"),
                               unused == 1 ? "is" : "are");
    if (settings > 0)
        message += fmt::format("{} the *CONTROL_SPH of its deck is not seen", undefined + unused > 0 ? ";" : "");
    message += "; check the deck that includes it";
    diag::Diagnostic summary{"REF010", diag::Severity::Info, std::move(message), folded.front().span, {}};
    for (std::size_t i = 0; i < folded.size() && i < kMostNotes; ++i)
        summary.notes.push_back({folded[i].span, fmt::format("{} [{}]", folded[i].message, folded[i].code)});
    if (folded.size() > kMostNotes)
        summary.notes.push_back({grammar::Span{}, fmt::format("and {} more", folded.size() - kMostNotes)});
    kept.push_back(std::move(summary));
    diagnostics = std::move(kept);
    diag::sort_by_location(diagnostics);
}

}  // namespace sphdeck::lint
