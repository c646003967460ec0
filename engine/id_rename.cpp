#include "engine/id_rename.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <limits>
#include <tuple>

#include "engine/field_at_column.hpp"
#include "engine/id_lookup.hpp"
#include "engine/position_index.hpp"
#include "grammar/fields.hpp"
#include "grammar/value.hpp"
#include "model/model.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::engine {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

// A line's text without its '\r'.
std::string_view line_of(const grammar::SourceMap& sources, grammar::FileId file, std::uint32_t line) {
    std::string_view text = sources.line_text(file, line);
    while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
    return text;
}

// The field a value stands in: 0-based first column, width, and whether its line is in free format.
// `fixed` false: a Radioss header's id segment, which is no field and may grow.
struct Slot {
    std::size_t start = 0, width = 0;
    bool free_format = false;
    bool fixed = true;
    std::string name;  // the field's name, for a refusal
};

std::string where(const grammar::SourceMap& sources, const grammar::Span& span) {
    std::string text = fmt::format("line {}", span.line);
    if (span.file != 0 && span.file < sources.size()) text += " of " + sources.file(span.file).display_name;
    return text;
}

std::optional<std::size_t> slot_holding(const std::vector<grammar::FixedField>& positions, std::uint32_t column) {
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (column >= positions[i].start + 1 && column < positions[i].start + positions[i].width + 1) return i;
    return std::nullopt;
}

// *PARAMETER lines: name/value pairs of 10 (long: 20) columns; *PARAMETER_EXPRESSION: the name in
// columns 1-10 (1-20), read by the reader itself (grammar/dyna/parameter_cards.cpp).
std::optional<Slot> parameter_slot(const grammar::Block& block, std::string_view text, std::uint32_t column) {
    const bool free_format = grammar::is_free_format(text);
    if (block.keyword.find("EXPRESSION") != std::string::npos) {
        const std::size_t width = block.format == grammar::CardFormat::Long ? 20 : 10;
        if (column > width) return std::nullopt;
        return Slot{0, width, text.substr(0, std::min(width, text.size())).find(',') != std::string_view::npos, true,
                    "PRMR"};
    }
    static constexpr grammar::FixedField pairs[] = {{0, 10},  {10, 10}, {20, 10}, {30, 10},
                                                    {40, 10}, {50, 10}, {60, 10}, {70, 10}};
    std::vector<grammar::FixedField> positions;
    grammar::widen(pairs, block.format, positions);
    auto index = slot_holding(positions, column);
    if (!index) return std::nullopt;
    return Slot{positions[*index].start, positions[*index].width, free_format, true, *index % 2 ? "VAL" : "PRMR"};
}

std::optional<Slot> slot_of(const CheckResult& deck, const grammar::Span& span) {
    const auto& raw = deck.deck;
    const grammar::Block* block = block_at(raw, span.file, span.line);
    if (!block) return std::nullopt;
    const bool radioss = deck.model.radioss.has_value();
    if (radioss && span.line == block->span.line) return Slot{0, 0, false, false, "header"};
    grammar::CardLinePtr card_line = card_line_at(raw, *block, span.line);
    if (!card_line) return std::nullopt;
    const std::string_view text = raw.text(*card_line);
    if (!radioss && starts_with(block->keyword, "*PARAMETER")) return parameter_slot(*block, text, span.column);
    if (radioss) {
        const int version = model::radioss_version(raw);
        auto card = radioss_card_at(raw, *block, card_line, version);
        if (!card || !card->card) return std::nullopt;
        auto index = radioss_field_at_column(*card, text, span.column);
        if (!index) return std::nullopt;
        const auto positions = grammar::radioss::layout(*card->card, version);
        if (*index >= positions.size()) return std::nullopt;
        return Slot{positions[*index].start, positions[*index].width, grammar::is_free_format(text), true,
                    std::string(card->card->fields[*index].name)};
    }
    auto card = dyna_card_at(raw, *block, card_line);
    if (!card || !card->card) return std::nullopt;
    auto index = dyna_field_at_column(*card->card, block->format, card->values, text, span.column);
    if (!index) return std::nullopt;
    const auto positions = keywords::layout_to_write(card->match.schema->name, *card->card, block->format);
    if (*index >= positions.size()) return std::nullopt;
    return Slot{positions[*index].start, positions[*index].width, grammar::is_free_format(text), true,
                std::string(card->card->fields[*index].name)};
}

bool all_digits(std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

bool rename_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

// The new id as the fields will hold it ("007" -> "7"), or a refusal.
std::optional<std::string> new_id_text(const std::string& old_id, std::string_view wanted, std::string& refusal) {
    std::string_view id = grammar::trim_blanks(wanted);
    if (all_digits(id)) {
        while (id.size() > 1 && id.front() == '0') id.remove_prefix(1);
        if (id == "0") {
            refusal = "an id must not be 0: 0 means \"none\" (or the default) in an id field";
            return std::nullopt;
        }
        if (id.size() > 15) {
            refusal = fmt::format("id {} is too large for the model's integer ids", id);
            return std::nullopt;
        }
        return std::string(id);
    }
    // A label (LS-DYNA alphanumeric ids) only where the id already is one.
    if (!all_digits(old_id) && !id.empty() && std::all_of(id.begin(), id.end(), rename_name_char))
        return std::string(id);
    refusal = fmt::format("'{}' is not an id: ids are whole numbers above 0", wanted);
    return std::nullopt;
}

// The places `target` stands: its definitions and uses, as references lists them (lsp/feature_definition.cpp).
std::vector<grammar::Span> id_places(const CheckResult& deck, const RenameTarget& target) {
    std::vector<grammar::Span> out;
    for (const auto& u : collect_ids(deck))
        if (ids_meet(u.kind, target.kind) && u.id == target.name) out.push_back(u.span);
    if (target.kind == "NODE")
        for (const auto& d : find_definitions(deck, target.kind, target.name)) out.push_back(d.span);
    for (const auto& span : particle_spans(deck, target.kind, target.name, std::numeric_limits<std::size_t>::max()))
        out.push_back(span);
    return out;
}

// A parameter's places, the name alone: every `&name` outside comments and its definitions' name
// fields (where the type letter stands before it).
std::vector<grammar::Span> parameter_places(const CheckResult& deck, const std::string& name) {
    std::vector<grammar::Span> out;
    const auto& sources = deck.deck.sources;
    for (grammar::FileId f = 0; f < sources.size(); ++f) {
        const std::uint32_t lines = sources.line_count(f);
        for (std::uint32_t l = 1; l <= lines; ++l) {
            const std::string_view text = sources.line_text(f, l);
            if (text.find('&') == std::string_view::npos || text.front() == '$') continue;
            for (const auto& r : parameter_references(text, f, l))
                if (same_name(r.name, name)) out.push_back({f, l, r.span.column + 1, r.span.end_column});
        }
    }
    for (const auto& p : deck.deck.parameters.definitions()) {
        if (!same_name(p.name, name)) continue;
        const std::string_view text = line_of(sources, p.span.file, p.span.line);
        const std::size_t from = p.span.column - 1, to = std::min<std::size_t>(p.span.end_column - 1, text.size());
        if (from >= to) continue;
        // The name follows the type letter and any blanks in the name field.
        const std::string_view field = text.substr(from, to - from);
        std::size_t at = 0;
        for (; at + name.size() <= field.size(); ++at)
            if (same_name(field.substr(at, name.size()), name) && at > 0 &&
                (at + name.size() == field.size() || !rename_name_char(field[at + name.size()])))
                break;
        if (at + name.size() > field.size()) continue;
        out.push_back({p.span.file, p.span.line, static_cast<std::uint32_t>(from + at + 1),
                       static_cast<std::uint32_t>(from + at + name.size() + 1)});
    }
    return out;
}

// A *PARAMETER_EXPRESSION that names the parameter without '&' (expressions may): no field of the
// id walk, so a rename would miss it.
std::optional<grammar::Span> bare_use_in_expression(const CheckResult& deck, const std::string& name) {
    const auto& raw = deck.deck;
    for (const grammar::Block& block : raw.blocks) {
        if (!starts_with(block.keyword, "*PARAMETER") || block.keyword.find("EXPRESSION") == std::string::npos)
            continue;
        const std::size_t width = block.format == grammar::CardFormat::Long ? 20 : 10;
        for (grammar::CardLinePtr l = raw.begin_lines(block); l != raw.end_lines(block); ++l) {
            const std::string_view text = raw.text(*l);
            for (std::size_t at = width; at + name.size() <= text.size(); ++at) {
                if (!same_name(text.substr(at, name.size()), name)) continue;
                const bool before = at > 0 && (rename_name_char(text[at - 1]) || text[at - 1] == '&');
                const bool after = at + name.size() < text.size() && rename_name_char(text[at + name.size()]);
                if (!before && !after)
                    return grammar::Span{l->file, l->line, static_cast<std::uint32_t>(at + 1),
                                         static_cast<std::uint32_t>(at + name.size() + 1)};
            }
        }
    }
    return std::nullopt;
}

}  // namespace

FieldReplacement replace_in_field(std::string_view line, std::size_t field_start, std::size_t width,
                                  std::size_t value_start, std::size_t value_end, std::string_view value,
                                  bool free_format) {
    if (free_format || width == 0) return {value_start, value_end, std::string(value)};
    // The field as the line holds it (a short line ends inside it).
    const std::size_t field_end = field_start + width;
    const std::size_t region_end = std::max(value_end, std::min(field_end, line.size()));
    const std::string_view region = line.substr(field_start, region_end - field_start);
    const std::size_t old_length = region.size();
    std::string wanted;
    const bool left_aligned = value_start == field_start && value_end < field_end;
    if (left_aligned) {
        wanted = std::string(value);
        if (wanted.size() < old_length) wanted.append(old_length - wanted.size(), ' ');
    } else {
        // Right-aligned: the new value ends where the old one did, or further right when it needs the room.
        std::size_t end = value_end;
        if (value.size() > end - field_start) end = std::max(region_end, field_start + value.size());
        if (end - field_start > value.size()) wanted.append(end - field_start - value.size(), ' ');
        wanted += value;
        if (region_end > end) wanted.append(region_end - end, ' ');
    }
    // A field that ends the line ends with the blanks it had, no more.
    if (region_end >= line.size()) {
        const std::size_t last = region.find_last_not_of(' ');
        const std::size_t trailing = last == std::string_view::npos ? 0 : region.size() - last - 1;
        wanted.resize(wanted.find_last_not_of(' ') + 1);
        wanted.append(trailing, ' ');
    }
    // The smallest replacement: what differs between the old and the new field.
    std::size_t prefix = 0;
    while (prefix < region.size() && prefix < wanted.size() && region[prefix] == wanted[prefix]) ++prefix;
    std::size_t suffix = 0;
    while (suffix < region.size() - prefix && suffix < wanted.size() - prefix &&
           region[region.size() - 1 - suffix] == wanted[wanted.size() - 1 - suffix])
        ++suffix;
    return {field_start + prefix, region_end - suffix, wanted.substr(prefix, wanted.size() - prefix - suffix)};
}

std::optional<RenameTarget> rename_target_at(const CheckResult& deck, grammar::FileId file, std::uint32_t line,
                                             std::uint32_t column, std::string* refusal) {
    const auto& raw = deck.deck;
    const bool radioss = deck.model.radioss.has_value();
    auto reference = parameter_reference_at(raw.sources, file, line, column);
    if (!reference) reference = parameter_definition_at(raw, file, line, column);
    if (reference) {
        if (radioss) {
            if (refusal) *refusal = "renaming a Radioss /PARAMETER is not supported: rename it by hand";
            return std::nullopt;
        }
        // The name alone, within the reference or the definition's name field under the cursor.
        for (const auto& span : parameter_places(deck, reference->name))
            if (span.file == file && span.line == line && span.column >= reference->span.column &&
                span.end_column <= reference->span.end_column)
                return RenameTarget{"PARAMETER", reference->name, span};
        return std::nullopt;
    }
    auto use = id_at(deck, file, line, column);
    if (!use) return std::nullopt;
    if (radioss && use->kind == "NODE") {
        if (refusal)
            *refusal = "renaming a Radioss node is not supported: its /SPHCEL and element lines are not indexed";
        return std::nullopt;
    }
    return RenameTarget{use->kind, use->id, use->span};
}

RenamePlan plan_rename(const CheckResult& deck, const RenameTarget& target, std::string_view new_name) {
    RenamePlan plan;
    const auto& sources = deck.deck.sources;
    std::string value;
    std::vector<grammar::Span> places;
    if (target.kind == "PARAMETER") {
        value = std::string(grammar::trim_blanks(new_name));
        if (!value.empty() && value.front() == '&') value.erase(0, 1);
        if (value.empty() || !std::isalpha(static_cast<unsigned char>(value.front())) ||
            !std::all_of(value.begin(), value.end(), rename_name_char)) {
            plan.refusal = fmt::format("'{}' is no parameter name: a letter, then letters, digits or '_'", new_name);
            return plan;
        }
        if (same_name(value, target.name) && value == target.name) return plan;
        for (const auto& p : deck.deck.parameters.definitions())
            if (same_name(p.name, value) && !same_name(p.name, target.name)) {
                plan.refusal = fmt::format("parameter {} already exists ({})", p.name, where(sources, p.span));
                return plan;
            }
        if (auto bare = bare_use_in_expression(deck, target.name)) {
            plan.refusal = fmt::format("{} is named without '&' in an expression at {}: rename it by hand", target.name,
                                       where(sources, *bare));
            return plan;
        }
        places = parameter_places(deck, target.name);
    } else {
        auto id = new_id_text(target.name, new_name, plan.refusal);
        if (!id) return plan;
        value = *id;
        if (value == target.name) return plan;
        const auto existing = find_definitions(deck, target.kind, value);
        if (!existing.empty()) {
            plan.refusal =
                fmt::format("{} {} already exists: {}", target.kind, value, describe(deck, existing.front()));
            return plan;
        }
        places = id_places(deck, target);
    }
    std::sort(places.begin(), places.end(), [](const grammar::Span& a, const grammar::Span& b) {
        return std::tie(a.file, a.line, a.column) < std::tie(b.file, b.line, b.column);
    });
    places.erase(std::unique(places.begin(), places.end(),
                             [](const grammar::Span& a, const grammar::Span& b) {
                                 return a.file == b.file && a.line == b.line && a.column == b.column;
                             }),
                 places.end());
    const bool parameter = target.kind == "PARAMETER";
    for (const grammar::Span& span : places) {
        const std::string_view text = line_of(sources, span.file, span.line);
        if (span.column == 0 || span.end_column - 1 > text.size() || span.end_column <= span.column) continue;
        const std::size_t value_start = span.column - 1, value_end = span.end_column - 1;
        const std::string_view old_value = text.substr(value_start, value_end - value_start);
        if (!parameter) {
            // An id given through a parameter (&pid) or an expression is renamed at the parameter, not here.
            const auto shape = grammar::classify_value(old_value).shape;
            if (shape != grammar::ValueShape::Integer && shape != grammar::ValueShape::Real &&
                model::normalise_id(old_value) != target.name) {
                plan.refusal = fmt::format("{} {} is written as '{}' at {}: rename that by hand", target.kind,
                                           target.name, old_value, where(sources, span));
                plan.edits.clear();
                return plan;
            }
        }
        auto slot = slot_of(deck, span);
        // A reference on a line no layout reads (an unknown keyword): replaced in place when it does not grow.
        if (!slot && parameter && value.size() <= target.name.size()) slot = Slot{0, 0, true, false, ""};
        if (!slot) {
            plan.refusal =
                fmt::format("no field holds {} {} at {}: not renamed", target.kind, target.name, where(sources, span));
            plan.edits.clear();
            return plan;
        }
        std::size_t start = value_start, end = value_end;
        std::string new_value = value;
        if (parameter && slot->fixed && !slot->free_format) {
            // The whole value of the field changes: "&pid" is "-&pid" or "R pid" there.
            const std::size_t field_end = std::min(slot->start + slot->width, text.size());
            if (value_start < slot->start || value_end > field_end) {
                new_value = value;
            } else {
                const std::string_view field = text.substr(slot->start, field_end - slot->start);
                const std::size_t first = field.find_first_not_of(' ');
                const std::size_t last = field.find_last_not_of(' ');
                start = slot->start + first;
                end = slot->start + last + 1;
                new_value = std::string(text.substr(start, value_start - start)) + value +
                            std::string(text.substr(value_end, end - value_end));
            }
        }
        if (slot->fixed && !slot->free_format && slot->start < text.size() &&
            text.substr(slot->start, slot->width).find('\t') != std::string_view::npos) {
            plan.refusal = fmt::format("a tab at {} makes its columns ambiguous: not renamed", where(sources, span));
            plan.edits.clear();
            return plan;
        }
        if (slot->fixed && new_value.size() > slot->width) {
            plan.refusal = fmt::format("{} does not fit the {}-column field {} at {}", new_value, slot->width,
                                       slot->name, where(sources, span));
            plan.edits.clear();
            return plan;
        }
        const FieldReplacement r = replace_in_field(text, slot->start, slot->fixed ? slot->width : 0, start, end,
                                                    new_value, slot->free_format);
        if (r.start == r.end && r.text.empty()) continue;
        plan.edits.push_back({grammar::Span{span.file, span.line, static_cast<std::uint32_t>(r.start + 1),
                                            static_cast<std::uint32_t>(r.end + 1)},
                              r.text});
    }
    return plan;
}

}  // namespace sphdeck::engine
