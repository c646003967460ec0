#include "engine/id_lookup.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fmt/format.h>

#include "grammar/keywords/id_kinds.hpp"
#include "grammar/radioss/id_kinds.hpp"
#include "grammar/value.hpp"
#include "engine/position_index.hpp"
#include "model/model.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::engine {
namespace {

namespace rad = grammar::radioss;

bool lookup_starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// A Radioss header's id with its role (grammar/radioss/id_kinds.hpp) and its columns.
struct HeaderId {
    IdRole role;
    std::string id;
    grammar::Span span;
};
std::optional<HeaderId> header_id(const grammar::Block& block) {
    const auto found = rad::header_id(block.keyword);
    if (!found || !found->role) return std::nullopt;
    return HeaderId{IdRole{std::string(found->role->kind), found->role->defines}, std::to_string(found->id),
                    grammar::Span{block.span.file, block.span.line,
                                  block.span.column + static_cast<std::uint32_t>(found->begin),
                                  block.span.column + static_cast<std::uint32_t>(found->end)}};
}

// Bulk blocks: millions of lines whose ids are nodes and particles.
bool bulk_block(const grammar::Block& block) {
    const std::string& k = block.keyword;
    return k == "*NODE" || lookup_starts_with(k, "*ELEMENT_SPH") || k == "/NODE" || lookup_starts_with(k, "/NODE/") ||
           lookup_starts_with(k, "/SPHCEL") || lookup_starts_with(k, "/BRICK") || lookup_starts_with(k, "/TETRA");
}

std::string field_title(std::string_view name, std::string_view text) {
    return keywords::is_title_field(name) ? std::string(grammar::trim_blanks(text)) : std::string();
}

void collect_dyna(const CheckResult& deck, const grammar::Block& block, std::vector<IdUse>& out) {
    const auto& raw = deck.deck;
    std::string title;
    walk_dyna_block(raw, block, [&](const DynaCard& card) {
        for (const auto& v : card.values) {
            if (!v.spec) continue;
            if (auto t = field_title(v.spec->name, v.text); !t.empty()) title = t;
            auto role = dyna_id_role(card.match.schema->name, *v.spec);
            if (!role) continue;
            std::string id = id_text(v);
            if (id.empty()) continue;
            out.push_back({role->kind, std::move(id), v.span, role->defines, &block, role->defines ? title : ""});
        }
        return true;
    });
}

void collect_radioss(const CheckResult& deck, const grammar::Block& block, int version, std::vector<IdUse>& out) {
    const auto& raw = deck.deck;
    std::string title;
    if (auto header = header_id(block)) {
        if (header->role.defines && block.line_count > 0 && !rad::is_v4(version))
            title = std::string(grammar::trim_blanks(raw.text(*raw.begin_lines(block))));
        out.push_back({header->role.kind, header->id, header->span, header->role.defines, &block, title});
    }
    if (bulk_block(block)) return;
    walk_radioss_block(raw, block, version, [&](grammar::CardLinePtr, const RadiossCard& card) {
        for (const auto& v : card.values) {
            if (!v.spec) continue;
            auto role = radioss_id_role(*v.spec);
            if (!role) continue;
            std::string id = id_text(v);
            if (!id.empty()) out.push_back({role->kind, std::move(id), v.span, false, &block, ""});
        }
        return true;
    });
}

}  // namespace

std::optional<IdRole> dyna_id_role(std::string_view keyword, const keywords::FieldSpec& field) {
    const auto role = keywords::id_role(keyword, field);
    if (!role) return std::nullopt;
    return IdRole{std::string(role->kind), role->defines};
}

std::optional<IdRole> radioss_id_role(const rad::FieldSpec& field) {
    std::string kind = rad::kind_named_by(field);
    if (kind.empty()) return std::nullopt;
    return IdRole{std::move(kind), false};
}

bool ids_meet(std::string_view a, std::string_view b) { return rad::ids_meet(a, b); }

std::string id_text(const model::FieldValue& v) {
    if (!v.spec || !v.explicit_value) return {};
    if (v.spec->type == keywords::FieldType::Label &&
        grammar::classify_value(v.text).shape == grammar::ValueShape::Other)
        return model::normalise_id(v.text);
    if (!v.valid || v.number == 0.0 || v.number != std::trunc(v.number) || model::exceeds_integer_range(v.number))
        return {};
    return std::to_string(static_cast<long long>(v.number));
}

std::string id_text(const model::RadiossValue& v) {
    if (!v.spec || !v.explicit_value || !v.valid || v.number == 0.0 || v.number != std::trunc(v.number) ||
        model::exceeds_integer_range(v.number))
        return {};
    return std::to_string(static_cast<long long>(v.number));
}

std::vector<IdUse> collect_ids(const CheckResult& deck) {
    std::vector<IdUse> out;
    const auto& raw = deck.deck;
    const bool radioss = deck.model.radioss.has_value();
    const int version = radioss ? model::radioss_version(raw) : 0;
    for (const grammar::Block& block : raw.blocks) {
        if (radioss) {
            collect_radioss(deck, block, version, out);
        } else if (!bulk_block(block)) {
            collect_dyna(deck, block, out);
        }
    }
    return out;
}

std::optional<IdUse> id_at(const CheckResult& deck, grammar::FileId file, std::uint32_t line, std::uint32_t column) {
    const auto& raw = deck.deck;
    const grammar::Block* block = block_at(raw, file, line);
    if (!block) return std::nullopt;
    const bool radioss = deck.model.radioss.has_value();
    if (radioss && line == block->span.line) {
        auto header = header_id(*block);
        if (!header || column < header->span.column || column >= header->span.end_column) return std::nullopt;
        return IdUse{header->role.kind, header->id, header->span, header->role.defines, block, ""};
    }
    const std::optional<CardAt> at = card_at(raw, *block, line, radioss);
    if (!at) return std::nullopt;
    const std::optional<std::size_t> index = at->field_under(column);
    if (!index) return std::nullopt;
    if (radioss) {
        if (!at->radioss->card) return std::nullopt;
        const auto& v = at->radioss->values[*index];
        auto role = radioss_id_role(*v.spec);
        std::string id = id_text(v);
        if (!role || id.empty()) return std::nullopt;
        return IdUse{role->kind, id, v.span, false, block, ""};
    }
    const auto& v = at->dyna->values[*index];
    auto role = dyna_id_role(at->dyna->match.schema->name, *v.spec);
    std::string id = id_text(v);
    if (!role || id.empty()) return std::nullopt;
    return IdUse{role->kind, id, v.span, role->defines, block, ""};
}

namespace {
std::optional<long long> integer_id(const std::string& id) {
    const grammar::IntegerValue v = grammar::parse_integer(id);
    if (v.status != grammar::NumberStatus::Ok) return std::nullopt;
    return v.value;
}

// The block holding RawDeck line `index`: blocks own contiguous runs of lines.
const grammar::Block* block_of_line(const grammar::RawDeck& raw, std::uint32_t index) {
    auto block = std::upper_bound(raw.blocks.begin(), raw.blocks.end(), index,
                                  [](std::uint32_t n, const grammar::Block& b) { return n < b.first_line; });
    if (block == raw.blocks.begin()) return nullptr;
    --block;
    return index < block->first_line + block->line_count ? &*block : nullptr;
}

// The NID field of a *NODE line when it holds `id`.
std::optional<IdUse> node_on_line(const grammar::RawDeck& raw, std::uint32_t index, long long id) {
    const grammar::Block* block = block_of_line(raw, index);
    if (!block) return std::nullopt;
    auto card = dyna_card_at(raw, *block, raw.lines.at(index));
    if (!card || card->values.empty() || !card->values[0].valid || card->values[0].number != static_cast<double>(id))
        return std::nullopt;
    return IdUse{"NODE", std::to_string(id), card->values[0].span, true, block, ""};
}

// Where node `id` is defined. The model keeps no line per node (decks of 10^7 nodes), but nodes
// are stored in the order of the *NODE lines: the node's position there names its line unless an
// unreadable line was skipped before it; then the *NODE blocks are scanned.
std::vector<IdUse> node_definitions(const CheckResult& deck, long long id) {
    std::vector<IdUse> out;
    const auto& raw = deck.deck;
    if (deck.model.radioss) {
        const auto lines = model::radioss_node_lines(raw, {id});
        const auto found = lines.find(id);
        if (found == lines.end()) return out;
        for (const auto& span : found->second) {
            const grammar::Block* block = block_at(raw, span.file, span.line);
            out.push_back({"NODE", std::to_string(id), span, true, block, ""});
        }
        return out;
    }
    const auto& ids = deck.model.nodes.id;
    const auto at = std::find(ids.begin(), ids.end(), id);
    if (at == ids.end()) return out;
    std::size_t position = static_cast<std::size_t>(at - ids.begin());
    for (const grammar::Block& b : raw.blocks) {
        if (b.keyword != "*NODE") continue;
        if (position < b.line_count) {
            if (auto use = node_on_line(raw, b.first_line + static_cast<std::uint32_t>(position), id)) return {*use};
            break;
        }
        position -= b.line_count;
    }
    for (const grammar::Block& b : raw.blocks) {
        if (b.keyword != "*NODE") continue;
        for (std::uint32_t i = b.first_line; i < b.first_line + b.line_count; ++i) {
            // Cheap test first: the id's digits on the line at all.
            if (raw.text(raw.lines[i]).find(std::to_string(id)) == std::string_view::npos) continue;
            if (auto use = node_on_line(raw, i, id)) out.push_back(*use);
        }
    }
    return out;
}
}  // namespace

std::vector<IdUse> find_definitions(const CheckResult& deck, const std::string& kind, const std::string& id) {
    if (kind == "NODE") {
        auto node = integer_id(id);
        return node ? node_definitions(deck, *node) : std::vector<IdUse>{};
    }
    return definitions_of(deck, kind, &id);
}

std::vector<IdUse> definitions_of(const CheckResult& deck, const std::string& kind, const std::string* id) {
    std::vector<IdUse> out;
    if (kind == "NODE") return out;  // millions: never listed
    const auto& raw = deck.deck;
    const bool radioss = deck.model.radioss.has_value();
    const int version = radioss ? model::radioss_version(raw) : 0;
    for (const grammar::Block& block : raw.blocks) {
        std::vector<IdUse> found;
        if (radioss) {
            auto header = header_id(block);
            if (!header || !header->role.defines || !ids_meet(header->role.kind, kind) || (id && header->id != *id))
                continue;
            collect_radioss(deck, block, version, found);
        } else {
            if (!keywords::defines_kind(block.keyword, kind) || bulk_block(block)) continue;
            collect_dyna(deck, block, found);
        }
        for (auto& use : found)
            if (use.defines && ids_meet(use.kind, kind) && (!id || use.id == *id)) out.push_back(std::move(use));
    }
    return out;
}

std::vector<grammar::Span> particle_spans(const CheckResult& deck, const std::string& kind, const std::string& id,
                                          std::size_t limit) {
    std::vector<grammar::Span> out;
    const auto& raw = deck.deck;
    const auto& particles = deck.model.particles;
    if (deck.model.radioss || (kind != "PART" && kind != "NODE")) return out;  // /SPHCEL: part in the header
    const auto wanted = integer_id(id);
    if (!wanted) return out;
    const bool part = kind == "PART";
    const model::IdColumn& column = part ? particles.part : particles.node;
    std::uint32_t last_line = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < particles.size() && out.size() < limit; ++i) {
        if (column[i] != *wanted || particles.line[i] == last_line) continue;
        last_line = particles.line[i];
        const grammar::Block* block = block_of_line(raw, last_line);
        if (!block) continue;
        auto card = dyna_card_at(raw, *block, raw.lines.at(last_line));
        if (!card || card->values.size() < 2) continue;
        out.push_back(card->values[part ? 1 : 0].span);  // NID, PID, MASS, NEND
    }
    return out;
}

std::string describe(const CheckResult& deck, const IdUse& d) {
    const auto& sources = deck.deck.sources;
    if (d.kind == "NODE") {
        const auto& nodes = deck.model.nodes;
        std::string text = fmt::format("node {}", d.id);
        if (auto n = integer_id(d.id)) {
            const auto at = std::find(nodes.id.begin(), nodes.id.end(), *n);
            if (at != nodes.id.end()) {
                const auto i = static_cast<std::size_t>(at - nodes.id.begin());
                text += fmt::format(" at ({:g}, {:g}, {:g})", nodes.x[i], nodes.y[i], nodes.z[i]);
            }
        }
        return fmt::format("{}, line {}", text, d.span.line);
    }
    std::string keyword = d.block ? d.block->keyword : d.kind;
    if (d.block && !d.block->keyword.empty() && d.block->keyword[0] == '/') {
        // Radioss: the header without its id ("/PROP/SPH/7" -> "/PROP/SPH 7").
        keyword = d.block->keyword.substr(0, d.block->keyword.rfind('/' + d.id));
    }
    std::string text = fmt::format("{} {}", keyword, d.id);
    if (!d.title.empty()) text += fmt::format(" \"{}\"", d.title);
    text += fmt::format(", line {}", d.span.line);
    if (d.span.file != 0 && d.span.file < sources.size())
        text += fmt::format(" of {}", sources.file(d.span.file).display_name);
    return text;
}

}  // namespace sphdeck::engine
