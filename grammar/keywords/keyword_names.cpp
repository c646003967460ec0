// DK001's sources of names beyond the layouts: the spellings LS-DYNA reads as a laid-out keyword, the
// names known without a layout, and the option grammar (keyword_names.hpp).
#include "grammar/keywords/keyword_names.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::keywords {

namespace {
using namespace std::string_view_literals;

// Legacy names LS-DYNA still reads as another keyword (name or name + options): the manual's blank option
// of *SET_SHELL_{OPTION} and *SET_NODE_{OPTION} is LIST (*SET_NODE_COLLECT is *SET_NODE_LIST_COLLECT), and
// *BOUNDARY_PRESCRIBED_MOTION_NODES is the plural the R6-era decks (and LS-PrePost's own readers) accept for
// _NODE.
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kLegacyNames = {{
    {"*BOUNDARY_PRESCRIBED_MOTION_NODES"sv, "*BOUNDARY_PRESCRIBED_MOTION_NODE"sv},
    {"*SET_NODE"sv, "*SET_NODE_LIST"sv},
    {"*SET_SHELL"sv, "*SET_SHELL_LIST"sv},
}};

// Names LS-DYNA writes itself and reads back, that no table lays out: *RVE_ANALYSIS_FEM writes *RVE_INFO
// into the mesh files it generates and reads them back (manual, *RVE_ANALYSIS_FEM).
constexpr std::array kWrittenByLsDyna = {"*RVE_INFO"sv};

// Options LS-DYNA gives keywords of many families, so that a known keyword followed by them may well be a
// name LS-DYNA reads though no table lists the combination: the id/title card (_ID, _TITLE), the MPP card
// and contact options (_MPP, _OFFSET, _BEAM_OFFSET, _CONSTRAINED_OFFSET, _THERMAL, _THERMAL_FRICTION,
// _ORTHO_FRICTION, _MORTAR, _SMOOTH), joints (_LOCAL, _FAILURE), sets (_COLLECT), 2D variants (_2D).
// Two-token options first: they are matched before their last token alone.
constexpr std::array kGrammarOptions = {
    "BEAM_OFFSET"sv,
    "CONSTRAINED_OFFSET"sv,
    "THERMAL_FRICTION"sv,
    "ORTHO_FRICTION"sv,
    "ID"sv,
    "TITLE"sv,
    "MPP"sv,
    "OFFSET"sv,
    "COLLECT"sv,
    "2D"sv,
    "LOCAL"sv,
    "THERMAL"sv,
    "MORTAR"sv,
    "SMOOTH"sv,
    "FAILURE"sv,
};

// Options moved to the end by respellings: LS-DYNA reads them wherever they stand among the options.
constexpr std::array kMovableOptions = {"ID"sv, "TITLE"sv, "MPP"sv};

std::vector<std::string_view> tokens_of(std::string_view name) {
    std::vector<std::string_view> out;
    for (std::size_t pos = 0; pos <= name.size();) {
        const std::size_t end = std::min(name.find('_', pos), name.size());
        out.push_back(name.substr(pos, end - pos));
        pos = end + 1;
    }
    return out;
}

std::string joined(const std::vector<std::string_view>& tokens, std::size_t from, std::size_t to) {
    std::string out;
    for (std::size_t i = from; i < to; ++i) {
        if (i > from) out += '_';
        out += tokens[i];
    }
    return out;
}

// `key` with its movable options (not the first token) moved to the end, in the order written.
std::string options_last(std::string_view key) {
    const std::vector<std::string_view> tokens = tokens_of(key);
    std::vector<std::string_view> kept, moved;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const bool movable =
            i > 0 && std::find(kMovableOptions.begin(), kMovableOptions.end(), tokens[i]) != kMovableOptions.end();
        (movable ? moved : kept).push_back(tokens[i]);
    }
    kept.insert(kept.end(), moved.begin(), moved.end());
    return joined(kept, 0, kept.size());
}

// Known to the layouts as a whole: every token after the base name is an option of its keyword.
bool laid_out(std::string_view name) {
    const auto match = find_keyword(name);
    return match && match->unknown_options.empty();
}

// The options of `tokens[from..]`, when every one is an option of the grammar.
std::optional<std::vector<std::string>> grammar_options(const std::vector<std::string_view>& tokens, std::size_t from) {
    std::vector<std::string> out;
    for (std::size_t i = from; i < tokens.size();) {
        std::size_t taken = 0;
        for (std::string_view o : kGrammarOptions) {
            const std::size_t n = static_cast<std::size_t>(std::count(o.begin(), o.end(), '_')) + 1;
            if (i + n <= tokens.size() && joined(tokens, i, i + n) == o) {
                taken = n;
                break;
            }
        }
        if (taken == 0) return std::nullopt;
        out.push_back(joined(tokens, i, i + taken));
        i += taken;
    }
    return out;
}

}  // namespace

std::vector<std::string> respellings(std::string_view key) {
    std::vector<std::string> out;
    const auto add = [&](std::string s) {
        if (s != key && std::find(out.begin(), out.end(), s) == out.end()) out.push_back(std::move(s));
    };
    for (const auto& [legacy, name] : kLegacyNames) {
        if (key.substr(0, legacy.size()) != legacy || (key.size() > legacy.size() && key[legacy.size()] != '_'))
            continue;
        const std::string renamed = std::string(name) + std::string(key.substr(legacy.size()));
        add(renamed);
        add(options_last(renamed));
    }
    add(options_last(key));
    return out;
}

bool is_keyword971_name(std::string_view upper_name) {
    const auto names = generated::keyword971_names();
    return std::binary_search(names.begin(), names.end(), upper_name);
}

bool known_by_name(std::string_view upper_name) {
    return is_known_without_layout(upper_name) || is_keyword971_name(upper_name) ||
           std::find(kWrittenByLsDyna.begin(), kWrittenByLsDyna.end(), upper_name) != kWrittenByLsDyna.end();
}

std::optional<NameWithOptions> known_with_options(std::string_view upper_name) {
    const std::vector<std::string_view> tokens = tokens_of(upper_name);
    // Longest known base first: *CONTACT_2D_AUTOMATIC_SURFACE_TO_SURFACE_MORTAR + TITLE, not ... + MORTAR_TITLE.
    for (std::size_t n = tokens.size() - 1; n >= 1; --n) {
        auto options = grammar_options(tokens, n);
        if (!options) continue;
        const std::string base = joined(tokens, 0, n);
        if (base.size() > 1 && (laid_out(base) || known_by_name(base)))
            return NameWithOptions{base, std::move(*options)};
    }
    return std::nullopt;
}

}  // namespace sphdeck::keywords
