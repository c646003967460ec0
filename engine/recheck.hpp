// The editor's re-check of a deck it checked before (after an edit): the same findings as
// check_deck, computed keeping what the last check computed and the edit left alone: the reading
// (an edit inside one ordinary block re-reads only its lines, grammar/deck_splice.hpp), the decoded
// *NODE and *ELEMENT_SPH blocks (copied where unchanged, decoded only around the edit,
// model/bulk_reuse.hpp) and the geometry preview (neighbour grid, nearest neighbours, neighbour
// counts: the costliest rules of a big deck), kept or followed when the model's geometry inputs allow
// (engine/preview_reuse.hpp, engine/preview_after_edit.hpp). After a spliced edit only the rule
// families whose inputs it changed run again (engine/rule_reuse.hpp, lint/rule_inputs.hpp).
#pragma once

#include <string>

#include "engine/check.hpp"

namespace sphdeck::engine {

// check_deck(path, documents, options), reusing `previous` (the last check of the same deck, kept
// alive by the caller during the call). The result keeps its preview for the next re-check
// (options.rules.keep_preview is set).
CheckResult recheck_deck(const std::string& path, const Documents& documents, const CheckOptions& options,
                         const CheckResult& previous);

// The same for a caller that drops `previous` afterwards (the editor replaces it by the result): after
// an edit outside the bulk blocks their columns are moved out of `previous` into the result instead of
// copied (previous.taken says which; 45 MB neither copied nor held twice on a 1M-particle deck). (The
// card lines need no move: a bulk block's are runs, grammar/card_lines.hpp, copied in a few bytes.)
CheckResult recheck_deck_taking(const std::string& path, const Documents& documents, const CheckOptions& options,
                                CheckResult& previous);

}  // namespace sphdeck::engine
