// `sphdeck diff A B` (issue 33 item 4): what the solver reads differently in two decks. Keywords are
// matched by kind and id (the first id field of their first card: PID, SECID, MID, LCID...) or, where
// they have none, by their order among keywords of the same kind; each field is compared by its
// effective value (after includes, parameters and defaults: the values `sphdeck dump` prints), numbers
// with a relative tolerance. Formatting, comments and order do not count. Nodes and particles are
// summarised: counts, added and removed ids, moved nodes and the largest displacement.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/check.hpp"

namespace sphdeck::engine {

struct DiffLocation {
    std::string file;
    std::uint32_t line = 0, column = 0;  // 0: not in the deck (a default)
};

struct FieldChange {
    std::string field;                     // "FORM", or "card 3 A1" for a repeated card
    nlohmann::ordered_json before, after;  // null where the side has no such field
    DiffLocation before_at, after_at;
};

struct KeywordChange {
    enum class Kind { Added, Removed, Changed };
    Kind kind = Kind::Changed;
    std::string name;  // "*SECTION_SPH"
    std::string id;    // "SECID 1", or "" when matched by order
    DiffLocation before_at, after_at;
    std::vector<FieldChange> fields;  // Changed only
};

// Nodes (by id, coordinates) or particles (by node id, part and mass).
struct BulkChange {
    std::size_t before_count = 0, after_count = 0, added = 0, removed = 0, changed = 0;
    std::vector<long long> added_ids, removed_ids, changed_ids;  // the first kMostIdsListed of each, ascending
    double largest_displacement = 0.0;                           // nodes only
    long long largest_displacement_id = 0;
    bool equal() const { return added == 0 && removed == 0 && changed == 0; }
};
inline constexpr std::size_t kMostIdsListed = 10;

struct DeckDiff {
    std::vector<KeywordChange> keywords;  // in the order of the second deck, removed ones where they were
    BulkChange nodes, particles;
    bool equal() const { return keywords.empty() && nodes.equal() && particles.equal(); }
};

// `rtol`: numbers a and b are equal when |a - b| <= rtol * max(|a|, |b|); node coordinates the same,
// against the larger extent of the two meshes for coordinates near 0.
DeckDiff diff_decks(const CheckResult& before, const CheckResult& after, double rtol);

nlohmann::ordered_json to_json(const DeckDiff& diff);

}  // namespace sphdeck::engine
