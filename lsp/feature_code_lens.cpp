// textDocument/codeLens: "used by N" above each definition of a file (a part, section, material,
// curve... and a *PARAMETER), N the places references lists; for a part also its particles, counted,
// not listed. The lens carries its title only (command ""): clients show it as text, and references
// (Shift+F12) lists the places.
#include <string>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "engine/id_lookup.hpp"
#include "engine/position_index.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {
namespace {

bool lens_same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

nlohmann::json lens(const grammar::SourceMap& sources, const grammar::Span& span, const std::string& title) {
    return {{"range", range_json(sources, span)}, {"command", {{"title", title}, {"command", ""}}}};
}

std::string used_by(std::size_t uses, std::size_t particles) {
    std::string title = fmt::format("used by {}", uses);
    if (particles > 0) title += fmt::format(" and {} particle{}", particles, particles == 1 ? "" : "s");
    return title;
}

}  // namespace

nlohmann::json code_lenses(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json&) {
    nlohmann::json out = nlohmann::json::array();
    const auto& raw = deck.result.deck;
    const auto& sources = raw.sources;
    if (file >= sources.size()) return out;
    // Uses by id, one walk of the deck; each definition of the file then reads its bucket.
    const std::vector<engine::IdUse> ids = engine::collect_ids(deck.result);
    std::unordered_map<std::string, std::vector<const engine::IdUse*>> uses;
    for (const auto& u : ids)
        if (!u.defines) uses[u.id].push_back(&u);
    // Particles by part: one pass over the particle array (*ELEMENT_SPH; Radioss names the part in /SPHCEL's header).
    std::unordered_map<long long, std::size_t> particles;
    if (!deck.result.model.radioss)
        for (long long part : deck.result.model.particles.part) ++particles[part];
    for (const auto& d : ids) {
        if (!d.defines || d.span.file != file) continue;
        std::size_t count = 0;
        if (auto bucket = uses.find(d.id); bucket != uses.end())
            for (const engine::IdUse* u : bucket->second) count += engine::ids_meet(u->kind, d.kind);
        std::size_t on_particles = 0;
        if (d.kind == "PART") {
            try {
                if (auto found = particles.find(std::stoll(d.id)); found != particles.end())
                    on_particles = found->second;
            } catch (const std::exception&) {  // a label: no particle names it
            }
        }
        out.push_back(lens(sources, d.span, used_by(count, on_particles)));
    }
    // Parameters: `&name` references of the deck (the lines that hold a '&' only).
    std::vector<const grammar::Parameter*> defined;
    for (const auto& p : raw.parameters.definitions())
        if (p.span.file == file) defined.push_back(&p);
    if (defined.empty()) return out;
    std::vector<std::size_t> counts(defined.size(), 0);
    for (grammar::FileId f = 0; f < sources.size(); ++f) {
        const std::uint32_t lines = sources.line_count(f);
        for (std::uint32_t l = 1; l <= lines; ++l) {
            const std::string_view text = sources.line_text(f, l);
            if (text.find('&') == std::string_view::npos || text.front() == '$') continue;
            for (const auto& r : engine::parameter_references(text, f, l))
                for (std::size_t i = 0; i < defined.size(); ++i) counts[i] += lens_same_name(r.name, defined[i]->name);
        }
    }
    for (std::size_t i = 0; i < defined.size(); ++i)
        out.push_back(lens(sources, defined[i]->span, used_by(counts[i], 0)));
    return out;
}

}  // namespace sphdeck::lsp
