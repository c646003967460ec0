// Keyword blocks written after the end of a file: LS-DYNA stops reading a file at `*END`, the OpenRadioss
// starter its deck at `/END` ("all lines or blocks located after /END are ignored"), so a stray end line
// pasted before `*PART` (a leftover of merging an include) silently drops the parts, nodes and particles
// after it. The readers note each keyword line they skip there; a file whose end dropped blocks that define
// or load something gets one warning at its end line (DK017) naming how many and which kinds. What is not
// such a block stays information (the first skipped line, as before): text, comments, `*COMMENT`, an
// `*INCLUDE` after `*END` (Oasys PRIMER reads such "post END" includes on purpose, for pre-processing only),
// and the metadata HyperMesh writes after `/END` (`/DUMMY_START`, `/ASSEMBLY`, `/POSITION`), which the
// starter never reads.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::grammar {

class DroppedAfterEnd {
public:
    // The end line of the file (`*END`, `/END`); keyword lines after it are noted from then on.
    void set_end(Span end_line) { end_ = end_line; }
    bool ended() const { return end_.valid(); }
    // A keyword (LS-DYNA `*NAME` upper case) or header (OpenRadioss `/PART/1`, upper case, and whether the
    // starter knows it) skipped after the end.
    void note_dyna(std::string_view keyword);
    void note_radioss(std::string_view header, bool known);

    // The warning, when blocks that define or load something were dropped; `include`: the file is an
    // included one (LS-DYNA goes on with the file that included it).
    std::optional<diag::Diagnostic> finding(std::string_view end_word, bool include) const;

    // Adds the warning to `out`, where it stands for the information on the first line after the end in
    // the same file (the DK017 info at index `from` or later); nothing when no block was dropped.
    void report(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view end_word, bool include) const;

private:
    static constexpr std::size_t max_kinds = 4;  // kinds named in the message
    Span end_;
    std::size_t count_ = 0;
    std::vector<std::string> kinds_;  // first few distinct kinds, in deck order
    void add(std::string kind);
};

}  // namespace sphdeck::grammar
