// A safety bound, not a presentation: every finding reaches every output format (the text formats
// fold long runs themselves, cli/text_folding.cpp), but a pathological block of 10^7 broken lines
// must not hold 10^7 findings in memory. Past `kept` findings of one code on the lines of one block,
// the rest are dropped while the block is walked, and the last one kept says how many were dropped
// (issue 13 class 7, issue 25 item 5).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace sphdeck::model {

inline constexpr std::size_t kKeptPerCodePerBlock = 100000;

// The bound of one block (or of one thread's range of it). Findings are appended to one vector from
// `from` on; trim() may run as often as wanted while they come (each finding is looked at once),
// annotate() once at the end.
class FloodBound {
public:
    explicit FloodBound(std::size_t from, std::size_t kept = kKeptPerCodePerBlock) : checked_(from), kept_(kept) {}

    // Drops the findings appended since the last call that are past `kept` of their code. Cheap
    // when nothing was appended; call it every few thousand lines.
    void trim(std::vector<diag::Diagnostic>& out);
    // Findings dropped elsewhere (another thread's range of the same block) count here too.
    void merge(const FloodBound& other);
    // Trims, then adds "(and N more ... dropped ...)" to the last finding kept of each code that lost
    // some, in out[from, end).
    void annotate(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword);

    std::size_t dropped() const;

private:
    struct Dropped {
        std::size_t count = 0;
        std::vector<std::uint32_t> lines;  // the first few dropped lines, ascending
    };
    std::size_t checked_;
    std::size_t kept_;
    std::map<std::string, std::size_t, std::less<>> seen_;
    std::map<std::string, Dropped, std::less<>> dropped_;
};

// The whole bound at once on out[from, end): what check_deck did per block before the walk trimmed.
void collapse_block_floods(std::vector<diag::Diagnostic>& out, std::size_t from, std::string_view keyword,
                           std::size_t kept = kKeptPerCodePerBlock);

}  // namespace sphdeck::model
