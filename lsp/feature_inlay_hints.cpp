// textDocument/inlayHint: beside each value of the requested lines, the name of its field; on a
// blank field inside the line, the default the solver takes; after a `&name` reference, the
// parameter's value. Off in bulk blocks (nodes, particles, elements) unless the client's settings
// ask for them (README "Editor settings": initializationOptions or workspace/didChangeConfiguration).
#include <cmath>
#include <fmt/format.h>
#include <string>

#include "engine/position_index.hpp"
#include "lsp/display_text.hpp"
#include "lsp/features.hpp"

namespace sphdeck::lsp {
using namespace engine;  // the position index: engine/position_index.hpp, engine/id_lookup.hpp
namespace {

constexpr int kHintType = 1;       // InlayHintKind.Type: a value
constexpr int kHintParameter = 2;  // InlayHintKind.Parameter: a field name
constexpr std::size_t kMaxHints = 5000;

struct HintSettings {
    bool enable = true;
    bool bulk_blocks = false;  // *NODE, *ELEMENT_SPH, /NODE, /SPHCEL...
    bool defaults = true;      // the default of a blank field
    bool parameter_values = true;
};

bool flag(const nlohmann::json& object, const char* name, bool fallback) {
    if (!object.is_object()) return fallback;
    const auto found = object.find(name);
    return found != object.end() && found->is_boolean() ? found->get<bool>() : fallback;
}

// The server passes the client's "inlayHints" settings as params["settings"].
HintSettings settings_of(const nlohmann::json& params) {
    HintSettings s;
    const nlohmann::json settings = params.is_object() ? params.value("settings", nlohmann::json()) : nlohmann::json();
    s.enable = flag(settings, "enable", s.enable);
    s.bulk_blocks = flag(settings, "bulkBlocks", s.bulk_blocks);
    s.defaults = flag(settings, "defaults", s.defaults);
    s.parameter_values = flag(settings, "parameterValues", s.parameter_values);
    return s;
}

std::string inlay_number(double v) { return fmt::format("{:g}", v); }

class Hints {
public:
    Hints(const CheckedDeck& deck, grammar::FileId file, const HintSettings& settings)
        : raw_(deck.result.deck), file_(file), settings_(settings) {}

    void add(std::uint32_t line, std::uint32_t column, std::string label, int kind, bool pad_left, bool pad_right,
             std::string_view tooltip = {}) {
        if (out_.size() >= kMaxHints) return;
        nlohmann::json hint = {{"position", position_json(raw_.sources, file_, line, column)},
                               {"label", display_text(label)},
                               {"kind", kind},
                               {"paddingLeft", pad_left},
                               {"paddingRight", pad_right}};
        if (!tooltip.empty()) hint["tooltip"] = display_text(tooltip);
        out_.push_back(std::move(hint));
    }

    void dyna_line(const grammar::Block& block, const grammar::CardLine& line, const DynaCard& card) {
        const std::string_view text = raw_.text(line);
        for (std::size_t i = 0; i < card.values.size(); ++i) {
            const model::FieldValue& v = card.values[i];
            if (!v.spec || v.spec->type == keywords::FieldType::Unused) continue;
            if (v.explicit_value) {
                add(line.line, v.span.column, fmt::format("{}:", v.spec->name), kHintParameter, false, false,
                    v.spec->doc);
                if (settings_.parameter_values && !v.text.empty() && v.text[0] == '&')
                    parameter_value(block, line.line, v);
                continue;
            }
            // A blank inside the line: where the default would be read.
            const std::optional<std::uint32_t> start =
                settings_.defaults ? blank_field_start(card, block.format, text, i) : std::nullopt;
            if (!start) continue;
            std::string value;
            if (v.spec->type == keywords::FieldType::Text)
                value = std::string(v.spec->default_text);
            else if (v.valid)
                value = inlay_number(v.number);
            if (value.empty()) continue;
            add(line.line, *start, fmt::format("{}={}", v.spec->name, value), kHintParameter, false, false,
                "blank: the default applies");
        }
    }

    void radioss_line(const grammar::CardLine& line, const RadiossCard& card) {
        if (card.title) return;
        for (const model::RadiossValue& v : card.values) {
            if (!v.spec || !v.explicit_value || v.spec->cell == grammar::radioss::Cell::Skip ||
                v.spec->cell == grammar::radioss::Cell::Skip20)
                continue;
            add(line.line, v.span.column, fmt::format("{}:", v.spec->name), kHintParameter, false, false, v.spec->note);
        }
    }

    nlohmann::json take() { return std::move(out_); }

private:
    void parameter_value(const grammar::Block& block, std::uint32_t line, const model::FieldValue& v) {
        std::string_view name = v.text.substr(1);
        const auto found = raw_.parameters.find(name, file_, block.parameter_epoch);
        if (!found.parameter) return;
        const grammar::Parameter& p = *found.parameter;
        std::string value =
            p.type == grammar::ParameterType::Character ? fmt::format("\"{}\"", p.text) : inlay_number(p.number);
        add(line, v.span.end_column, "= " + value, kHintType, true, false,
            fmt::format("*PARAMETER line {}", p.span.line));
    }

    const grammar::RawDeck& raw_;
    grammar::FileId file_;
    HintSettings settings_;
    nlohmann::json out_ = nlohmann::json::array();
};

}  // namespace

nlohmann::json inlay_hints(const CheckedDeck& deck, grammar::FileId file, const nlohmann::json& params) {
    const auto& sources = deck.result.deck.sources;
    TextPosition start, end;
    if (!params.is_object() || !params.contains("range") || !params["range"].is_object() ||
        !parse_position(params["range"].value("start", nlohmann::json()), start) ||
        !parse_position(params["range"].value("end", nlohmann::json()), end) || file >= sources.size())
        return nlohmann::json::array();
    const HintSettings settings = settings_of(params);
    if (!settings.enable) return nlohmann::json::array();
    Hints hints(deck, file, settings);
    RangeWalkOptions options;
    options.skip_bulk = !settings.bulk_blocks;
    visit_card_lines(deck.result.deck, deck.result.model.radioss.has_value(), file, {start.line + 1, end.line + 1},
                     options, [&](const DecodedLine& decoded) {
                         if (decoded.dyna) hints.dyna_line(*decoded.block, *decoded.line, *decoded.dyna);
                         if (decoded.radioss) hints.radioss_line(*decoded.line, *decoded.radioss);
                     });
    return hints.take();
}

}  // namespace sphdeck::lsp
