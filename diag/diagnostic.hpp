// A finding about a deck: what is wrong, where, and which rule says so.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "text/source_map.hpp"
#include "text/text_edit.hpp"

namespace sphdeck::diag {

enum class Severity { Info, Warning, Error };

std::string_view to_string(Severity s);
// "info", "warning", "error" (also "note" for info); false when the word is none of these.
bool parse_severity(std::string_view word, Severity& out);

// A secondary location or remark attached to a diagnostic ("the section is defined here").
struct Note {
    text::Span span;  // may be invalid: a note without a location
    std::string message;
};

// A fix's edits and the fix itself are text-level (text/text_edit.hpp): diag::Fix names the same type.
using text::Fix;
using text::TextEdit;

struct Diagnostic {
    std::string code;  // rule code, e.g. "DK010"
    Severity severity = Severity::Error;
    std::string message;  // short lower-case fragment naming the value found and what was expected
    text::Span span;      // primary location; invalid for deck-wide findings
    std::vector<Note> notes;
    std::vector<Fix> fixes = {};  // mends the finding offers, most likely first; empty when none is mechanical
};

struct Counts {
    std::size_t errors = 0, warnings = 0, infos = 0;
};
Counts count(const std::vector<Diagnostic>& diagnostics);

// Sorts by file, line, column, then code: the order every renderer prints in.
void sort_by_location(std::vector<Diagnostic>& diagnostics);

}  // namespace sphdeck::diag
