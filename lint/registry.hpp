// The rule registry: every lint rule as data, with the documentation `sphdeck rule CODE` prints.
// One flat table sorted by code (ruff's codes.rs is the model); codes are never reused. The rows are
// in lint/registry_rows.cpp; each rule's documentation is docs/rules/CODE.md, embedded at build time.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"  // sphdeck::diag::Severity { Info, Warning, Error }

namespace sphdeck::lint {

// A rule's documentation in ruff's sections, as plain text (Markdown escapes removed): the sections of
// docs/rules/CODE.md (lint/rule_docs.hpp reads them).
struct RuleDoc {
    std::string_view what;    // what the rule checks, one paragraph
    std::string_view why;     // why it matters: the manual remark it comes from, in our own words,
                              // citing the source, e.g. "(*CONTROL_SPH, Remark 2e)"
    std::string_view fix;     // how to fix it
    std::string_view before;  // a small deck fragment that triggers the rule (keyword line, $# ruler, card)
    std::string_view after;   // the same fragment fixed
};

// Whether a rule's findings carry a fix (diag::Fix) that `check --fix` and the editor apply. A fix is
// offered only where the rule's page says exactly what it does, so a rule that can fix still leaves a
// finding without one when the mend is not certain (its page says when).
enum class Fixable {
    None,    // findings never carry a fix
    Safe,    // the fixes are safe: the solver then reads the values the author evidently meant
    Unsafe,  // the fixes are a judgement (a did-you-mean name): applied with --unsafe-fixes only
    Mixed,   // some findings carry a safe fix, others an unsafe one
};
std::string_view to_string(Fixable f);  // "none", "safe", "unsafe", "safe or unsafe"

// Where a rule lives besides its row: the source files whose code reports it and the folders of its
// decks. Its page is docs/rules/CODE.md (rule_page_path); its decks are the files CODE_* in those folders
// of decks/tests/, those named *fires* fire it and those named *silent* must not. A deck that cannot be
// written (a model too big for the repository) is replaced by a reason here and a unit test. A test
// (tests/test_rule_rows.cpp) holds every row to this: each named file reports the code, each rule has
// its page, a firing and a silent deck or the reason why not; ctest runs each rule's decks as rule-CODE.
struct RuleHome {
    std::string_view check;                // "lint/rules_control_sph_form.cpp"; several separated by blanks, main first
    std::string_view decks;                // "sph": folders under decks/tests/, several separated by blanks ("dk rad")
    std::string_view no_firing_deck = {};  // why no deck fires it, and which unit test does instead
    std::string_view no_silent_deck = {};  // why no deck must stay silent, and which unit test shows it
};

// What a rule's finding says of its line's layout, for `sphdeck format` (edit/format_deck.cpp): a line
// whose layout is in doubt is left as written, so formatting never moves a value its author misplaced.
enum class Layout {
    Trusted,   // the finding is about a value, not its place (a blank required field, a value out of range)
    Doubtful,  // values may not read as laid out: cut, glued or shifted values, text past the last column,
               // tabs, parameter names a field may have cut, decimal commas
};

struct RuleInfo {
    std::string_view code;            // "SPH030"
    std::string_view name;            // "iavis-solid-in-2d" (kebab-case, as in the catalogue)
    diag::Severity severity;          // default severity; for "error/warning" rules the stronger one, and
                                      // `what` says when a finding is reported lower
    std::string_view since;           // "0.1.0"
    std::string_view source;          // "CONTROL_SPH R2e", "reader", "SPHBCS", ... as in the catalogue
    RuleHome home;                    // its check and its decks
    std::string_view summary;         // one line: the catalogue's condition in plain words
    Fixable fix = Fixable::None;      // whether its findings carry fixes (a test compares with the deck tests)
    Layout layout = Layout::Trusted;  // Doubtful: the formatter leaves a line with its finding as written
    RuleDoc doc{};                    // empty in the rows; the registry fills it from docs/rules/CODE.md
};

// "docs/rules/SPH030.md": the page a rule's documentation is read from.
std::string rule_page_path(const RuleInfo& rule);

// Every rule, sorted by code.
std::span<const RuleInfo> all_rules();

// The rule with this code (case-insensitive: "sph030") or exactly this name; nullptr if none.
const RuleInfo* find_rule(std::string_view code_or_name);

// "Did you mean": up to `max` codes or names close to `query`. Rules whose code or name starts with
// the query come first (in code order), then those containing it, then those within a small edit
// distance. Each rule appears once, as its code or its name, whichever matched better.
std::vector<std::string_view> similar_rules(std::string_view query, std::size_t max = 3);

namespace detail {
// The rows without their documentation, defined in lint/registry_rows.cpp; use all_rules() instead.
std::span<const RuleInfo> rule_rows();
}  // namespace detail

}  // namespace sphdeck::lint
