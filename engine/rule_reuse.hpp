// The editor's re-check (issue 45 item 2): after an edit the re-check spliced into the last reading,
// only the rule families whose inputs the edit changed run again (lint/rule_inputs.hpp says what each
// reads); the others' findings are the last check's, moved with their lines. The same findings as a
// full check, in the same order: a family's findings depend on nothing but what it reads.
#pragma once

#include <array>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/deck_splice.hpp"
#include "grammar/raw_deck.hpp"
#include "lint/rule_context.hpp"
#include "lint/rule_inputs.hpp"
#include "lint/rules.hpp"
#include "model/model.hpp"

namespace sphdeck::engine {

struct CheckResult;

// Each family's findings of an editor's check as the family reported them (before they were folded
// into their causes and suppressed), for the next re-check to reuse.
struct RuleFindings {
    bool kept = false;  // the check kept them (RuleOptions::keep_preview, the editor's checks)
    lint::RuleOptions options;
    std::array<std::vector<diag::Diagnostic>, lint::rule_family_count> by_family;
    std::array<bool, lint::rule_family_count> reached{};  // run or reused (not left out by the options)
    std::array<bool, lint::rule_family_count> reused{};   // taken from the check before (tests, bench)
};

// What a spliced edit changed of the families' inputs: `previous` read, `deck` and `model` now.
// `preview` is left false (the preview is known only when computed).
lint::DeckInputs changed_inputs(const CheckResult& previous, const grammar::RawDeck& deck, const model::Model& model,
                                const grammar::SplicedLines& changed);

// `findings` of the reading `before`, moved to the lines of `now` (spliced from it); false when one of
// their places (span, notes, fix edits) lies on a line the edit replaced: a comment line, a card line
// whose text it changed.
bool follow_edit(std::vector<diag::Diagnostic>& findings, const grammar::RawDeck& before, const grammar::RawDeck& now,
                 const grammar::SplicedLines& changed);

// lint::run_rules on `context` (whose findings go to `out`), keeping each family's findings in
// `keep` when `keep.kept`; with `previous` and `changed` (a spliced re-check), the families whose
// inputs the edit left alone are not run: their findings in `previous` are put in their place, and
// `previous`'s preview is kept without asking `preview_source` when its inputs are unchanged.
void run_rules_reusing(lint::RuleContext& context, const lint::PreviewSource& preview_source,
                       std::vector<diag::Diagnostic>& out, RuleFindings& keep, const CheckResult* previous,
                       const grammar::SplicedLines* changed);

// The id look-ups of `previous`'s rules that still hold after the edit (RuleContext::use_lookups):
// those over node ids and particle nodes the edit left alone.
lint::RuleContext::Lookups lookups_after_edit(const CheckResult& previous, const lint::DeckInputs& changed);

}  // namespace sphdeck::engine
