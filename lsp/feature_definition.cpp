// textDocument/definition and textDocument/references: ids (a part's SECID -> its *SECTION, a
// Radioss /PART's prop_ID -> its /PROP), `&name` -> its *PARAMETER, an include line -> the file.
#include <algorithm>
#include <cctype>

#include "engine/id_lookup.hpp"
#include "engine/position_index.hpp"
#include "lsp/features.hpp"
#include "lsp/uri.hpp"

namespace sphdeck::lsp {

using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

// Particle lines listed as references of a part at most: a 1M-particle part is no list to read.
constexpr std::size_t kMaxParticleReferences = 10000;

nlohmann::json location(const grammar::SourceMap& sources, const grammar::Span& span) {
    return {{"uri", uri_from_path(sources.file(span.file).path)}, {"range", range_json(sources, span)}};
}

bool definition_same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

}  // namespace

nlohmann::json definition(const CheckedDeck& deck, grammar::FileId file, TextPosition position) {
    const auto& raw = deck.result.deck;
    const auto& sources = raw.sources;
    if (file >= sources.size()) return nullptr;
    const LineColumn at = line_column(sources, file, position);
    if (auto child = included_file(sources, file, at.line))
        return {{"uri", uri_from_path(sources.file(*child).path)},
                {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}}};
    if (auto reference = parameter_reference_at(sources, file, at.line, at.column)) {
        const grammar::Block* block = block_at(raw, file, at.line);
        auto found =
            raw.parameters.find(reference->name, file, block ? block->parameter_epoch : raw.parameters.epoch());
        if (!found.parameter) found = raw.parameters.find(reference->name, file, raw.parameters.epoch());
        if (!found.parameter) return nullptr;
        return location(sources, found.parameter->span);
    }
    if (auto own = parameter_definition_at(raw, file, at.line, at.column)) return location(sources, own->span);
    auto use = id_at(deck.result, file, at.line, at.column);
    if (!use) return nullptr;
    if (use->defines) return location(sources, use->span);
    const auto definitions = find_definitions(deck.result, use->kind, use->id);
    if (definitions.empty()) return nullptr;
    if (definitions.size() == 1) return location(sources, definitions.front().span);
    nlohmann::json out = nlohmann::json::array();
    for (const auto& d : definitions) out.push_back(location(sources, d.span));
    return out;
}

nlohmann::json references(const CheckedDeck& deck, grammar::FileId file, TextPosition position,
                          bool include_declaration) {
    nlohmann::json out = nlohmann::json::array();
    const auto& raw = deck.result.deck;
    const auto& sources = raw.sources;
    if (file >= sources.size()) return out;
    const LineColumn at = line_column(sources, file, position);
    auto reference = parameter_reference_at(sources, file, at.line, at.column);
    if (!reference) reference = parameter_definition_at(raw, file, at.line, at.column);
    if (reference) {
        for (grammar::FileId f = 0; f < sources.size(); ++f) {
            const std::uint32_t lines = sources.line_count(f);
            for (std::uint32_t l = 1; l <= lines; ++l) {
                const std::string_view text = sources.line_text(f, l);
                if (text.find('&') == std::string_view::npos) continue;
                for (const auto& r : parameter_references(text, f, l))
                    if (definition_same_name(r.name, reference->name)) out.push_back(location(sources, r.span));
            }
        }
        if (include_declaration)
            for (const auto& p : raw.parameters.definitions())
                if (definition_same_name(p.name, reference->name)) out.push_back(location(sources, p.span));
        return out;
    }
    auto use = id_at(deck.result, file, at.line, at.column);
    if (!use) return out;
    for (const auto& u : collect_ids(deck.result))
        if (ids_meet(u.kind, use->kind) && u.id == use->id && (include_declaration || !u.defines))
            out.push_back(location(sources, u.span));
    // Nodes are defined in the bulk *NODE blocks, which the walk of the deck leaves out.
    if (include_declaration && use->kind == "NODE")
        for (const auto& d : find_definitions(deck.result, use->kind, use->id))
            out.push_back(location(sources, d.span));
    for (const auto& span : particle_spans(deck.result, use->kind, use->id, kMaxParticleReferences))
        out.push_back(location(sources, span));
    return out;
}

}  // namespace sphdeck::lsp
