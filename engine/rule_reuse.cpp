#include "engine/rule_reuse.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

#include "engine/check.hpp"
#include "grammar/keywords/schema.hpp"

namespace sphdeck::engine {
namespace {

// Where the lines of the old reading are in the new one: lines before the edit stay, lines past it
// moved with it; inside it only the card lines whose text it kept (a comment line added or removed
// beside them, which the splice takes in whole lines) are known, in their new places.
class LineMap {
public:
    LineMap(const grammar::RawDeck& before, const grammar::RawDeck& now, const grammar::SplicedLines& changed)
        : changed_(changed) {
        same_count_ = changed.old_card_end - changed.first_card == changed.new_card_end - changed.first_card;
        if (!same_count_) return;
        for (std::uint32_t k = changed.first_card; k < changed.old_card_end; ++k) {
            if (old_text(before.lines[k]) == now.text(now.lines[k]))
                kept_.emplace_back(before.lines[k].line, now.lines[k].line);
            else
                edited_.push_back(k);
        }
    }

    // Card lines in the same number, and those whose text changed (card indices, the same in both).
    bool same_card_count() const { return same_count_; }
    const std::vector<std::uint32_t>& edited_cards() const { return edited_; }

    std::optional<std::uint32_t> operator()(const text::Span& span) const {
        if (span.file != changed_.file || span.line < changed_.first_line) return span.line;
        if (span.line >= changed_.old_line_end)
            return static_cast<std::uint32_t>(static_cast<std::int64_t>(span.line) + changed_.new_line_end -
                                              changed_.old_line_end);
        // kept_ is in line order (cards are).
        const auto at =
            std::lower_bound(kept_.begin(), kept_.end(), std::pair<std::uint32_t, std::uint32_t>(span.line, 0));
        if (at != kept_.end() && at->first == span.line) return at->second;
        return std::nullopt;
    }

private:
    // An old card line the edit replaced, from the bytes the splice kept aside: the last reading's
    // buffer may have been patched in place since (grammar/earlier_text.hpp).
    std::string_view old_text(const grammar::CardLine& line) const {
        const std::string_view lines = changed_.replaced;
        std::string_view text = lines.substr(std::min<std::size_t>(line.offset - changed_.begin, lines.size()));
        text = text.substr(0, text.find('\n'));
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        return text;
    }

    const grammar::SplicedLines& changed_;
    bool same_count_ = false;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> kept_;
    std::vector<std::uint32_t> edited_;
};

bool same_place(const text::Span& before, const text::Span& now, const LineMap& map) {
    const auto line = map(before);
    return line && before.file == now.file && *line == now.line && before.column == now.column &&
           before.end_column == now.end_column;
}

bool same_field(const model::FieldRecord& a, const model::FieldRecord& b, const LineMap& map) {
    return a.name == b.name && a.type == b.type && std::memcmp(&a.number, &b.number, sizeof a.number) == 0 &&
           a.text == b.text && a.explicit_value == b.explicit_value && a.valid == b.valid &&
           same_place(a.span, b.span, map);
}

bool title_row(const std::vector<model::FieldRecord>& row) {
    if (row.empty()) return false;
    for (const model::FieldRecord& f : row)
        if (!keywords::is_title_field(f.name)) return false;
    return true;
}

// The record a block was decoded into (one per block, made at its keyword line).
const model::KeywordRecord* record_of(const model::Model& model, const grammar::Block& block) {
    for (const model::KeywordRecord& r : model.records)
        if (r.span.file == block.span.file && r.span.line == block.span.line && r.span.column == block.span.column)
            return &r;
    return nullptr;
}

// Whether `line` holds a title row of `record`.
bool on_title_row(const model::KeywordRecord& record, std::uint32_t line) {
    for (const auto& row : record.rows)
        if (title_row(row) && row.front().span.line == line) return true;
    return false;
}

// The edit left the values of its block alone but for titles: every card line whose text it changed
// is a title card, before and after, and every other card decodes to the same values in the same
// places. Only for a block read wholly into its record (known, no unknown option, not generated): what
// the model makes of it then comes from the record alone.
bool only_titles_changed(const CheckResult& previous, const grammar::RawDeck& deck, const model::Model& model,
                         const grammar::SplicedLines& changed, const LineMap& map) {
    if (!map.same_card_count()) return false;
    const grammar::Block& block = deck.blocks[changed.block];
    const auto known = keywords::find_keyword(block.keyword);
    if (!known || !known->unknown_options.empty() || known->schema->generated) return false;
    const model::KeywordRecord* before = record_of(previous.model, previous.deck.blocks[changed.block]);
    const model::KeywordRecord* now = record_of(model, block);
    if (!before || !now || before->schema != now->schema || before->keyword != now->keyword ||
        before->options != now->options || before->rows.size() != now->rows.size())
        return false;
    for (const std::uint32_t k : map.edited_cards())
        if (!on_title_row(*before, previous.deck.lines[k].line) || !on_title_row(*now, deck.lines[k].line))
            return false;
    for (std::size_t i = 0; i < now->rows.size(); ++i) {
        const auto &a = before->rows[i], &b = now->rows[i];
        if (title_row(a) && title_row(b)) continue;
        if (a.size() != b.size()) return false;
        for (std::size_t f = 0; f < a.size(); ++f)
            if (!same_field(a[f], b[f], map)) return false;
    }
    return true;
}

bool follow_span(text::Span& span, const LineMap& map) {
    if (!span.valid()) return true;
    const auto line = map(span);
    if (!line) return false;
    span.line = *line;
    return true;
}

// What changed of the inputs, and how lines moved.
lint::DeckInputs changed_inputs(const CheckResult& previous, const grammar::RawDeck& deck, const model::Model& model,
                                const grammar::SplicedLines& changed, const LineMap& map) {
    lint::DeckInputs out;
    const std::string& keyword = deck.blocks[changed.block].keyword;
    const bool nodes = keyword == "*NODE", particles = keyword.starts_with("*ELEMENT_SPH");
    // The cards as they were, comment lines added or removed beside them: the same values (a bulk
    // block's values come from its cards' text alone; a record is compared to be sure).
    const bool same_cards = map.same_card_count() && map.edited_cards().empty();
    if (nodes) {  // decoded into Model::nodes alone
        out.node_positions = !same_cards;
        out.node_ids = !same_cards && previous.model.nodes.id != model.nodes.id;
    } else if (particles) {
        out.particles = !same_cards;
        out.keywords = !same_cards && keyword != "*ELEMENT_SPH" && keyword != "*ELEMENT_SPH_VOLUME";
    } else if (only_titles_changed(previous, deck, model, changed, map)) {
        out.titles = !same_cards;
    } else {
        out.keywords = true;
    }
    return out;
}

bool follow_edit(std::vector<diag::Diagnostic>& findings, const LineMap& map) {
    for (diag::Diagnostic& d : findings) {
        if (!follow_span(d.span, map)) return false;
        for (diag::Note& note : d.notes)
            if (!follow_span(note.span, map)) return false;
        for (diag::Fix& fix : d.fixes)
            for (diag::TextEdit& edit : fix.edits)
                if (!follow_span(edit.span, map)) return false;
    }
    return true;
}

}  // namespace

lint::DeckInputs changed_inputs(const CheckResult& previous, const grammar::RawDeck& deck, const model::Model& model,
                                const grammar::SplicedLines& changed) {
    return changed_inputs(previous, deck, model, changed, LineMap(previous.deck, deck, changed));
}

bool follow_edit(std::vector<diag::Diagnostic>& findings, const grammar::RawDeck& before, const grammar::RawDeck& now,
                 const grammar::SplicedLines& changed) {
    return follow_edit(findings, LineMap(before, now, changed));
}

lint::RuleContext::Lookups lookups_after_edit(const CheckResult& previous, const lint::DeckInputs& changed) {
    lint::RuleContext::Lookups kept = previous.rule_lookups;
    if (changed.node_ids || changed.particles) kept.particle_nodes = nullptr;
    if (changed.node_ids) kept.node_index = nullptr;
    if (changed.particles) kept.particle_index = nullptr;
    return kept;
}

void run_rules_reusing(lint::RuleContext& context, const lint::PreviewSource& preview_source,
                       std::vector<diag::Diagnostic>& out, RuleFindings& keep, const CheckResult* previous,
                       const grammar::SplicedLines* changed) {
    const RuleFindings* last = previous ? &previous->rule_findings : nullptr;
    std::optional<lint::DeckInputs> edit;
    std::optional<LineMap> map;
    const lint::RuleOptions& options = context.options;
    if (last && changed && last->kept && last->options.solver == options.solver &&
        last->options.geometry == options.geometry && last->options.preview_arrays == options.preview_arrays &&
        last->options.keep_preview == options.keep_preview) {
        map.emplace(previous->deck, context.deck, *changed);
        edit = changed_inputs(*previous, context.deck, context.model, *changed, *map);
    }
    // Look-ups another deck of the run shared are kept (engine/shared_preview.hpp).
    if (const lint::RuleContext::Lookups now = context.lookups();
        edit && !now.node_index && !now.particle_index && !now.particle_nodes)
        context.use_lookups(lookups_after_edit(*previous, *edit));
    std::size_t start = out.size();
    bool preview_compared = false;
    lint::FamilySteps steps;
    steps.run = [&](lint::RuleFamily family) {
        const auto f = static_cast<std::size_t>(family);
        keep.reached[f] = true;
        start = out.size();
        if (!edit || !last->reached[f]) return true;
        if (!preview_compared) {  // a preview kept as it was is the same object
            edit->preview = context.preview != previous->preview;
            preview_compared = true;
        }
        if (lint::reads_any(family, *edit)) return true;
        std::vector<diag::Diagnostic> again = last->by_family[f];
        if (!follow_edit(again, *map)) return true;
        out.insert(out.end(), again.begin(), again.end());
        if (keep.kept) keep.by_family[f] = std::move(again);
        keep.reused[f] = true;
        return false;
    };
    steps.ran = [&](lint::RuleFamily family) {
        if (keep.kept)
            keep.by_family[static_cast<std::size_t>(family)].assign(out.begin() + static_cast<std::ptrdiff_t>(start),
                                                                    out.end());
    };
    // The preview is made of what its family reads: when none of that changed (a title, a comment
    // line), the last one is the one a full check computes, without comparing a million positions.
    const lint::PreviewSource kept_or_new = [&](const model::Model& model) {
        if (edit && previous->preview && !lint::reads_any(lint::RuleFamily::Preview, *edit)) return previous->preview;
        return preview_source(model);
    };
    lint::run_rules(context, kept_or_new, steps);
}

}  // namespace sphdeck::engine
