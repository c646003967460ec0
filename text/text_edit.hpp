// Edits of a deck's text: the replacements a fix, the formatter or the editor makes. Text-level data
// that diag/ (a finding's fixes), grammar/ and model/ (the fixes they attach) and edit/ share.
#pragma once

#include <string>
#include <vector>

#include "text/source_map.hpp"

namespace sphdeck::text {

// One text replacement: the columns of `span` (one line, end_column exclusive as in every Span) become
// `replacement`. An empty span (column == end_column) inserts.
struct TextEdit {
    Span span;
    std::string replacement;
};

// A mechanical mend carried by a finding. Safe: the solver then reads the values the author evidently
// meant, with no judgement (a value moved back into its field). Unsafe: a judgement (a did-you-mean name).
struct Fix {
    std::string description;  // "realign the line to the fields of *CONTROL_SPH"
    bool safe = false;
    std::vector<TextEdit> edits;
};

}  // namespace sphdeck::text
