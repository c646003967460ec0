// Lookup of integer ids (nodes, particles) in arrays of millions: a dense table when the ids
// are compact (the usual case), a sorted copy otherwise. Duplicates are found on the way.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "model/id_column.hpp"

namespace sphdeck::model {

class IdIndex {
public:
    explicit IdIndex(const std::vector<long long>& ids);
    explicit IdIndex(const IdColumn& ids);

    // Position of `id` in the indexed array (the first one when duplicated).
    std::optional<std::size_t> find(long long id) const;

    // (first position, repeated position) of every duplicated id, in array order.
    const std::vector<std::pair<std::size_t, std::size_t>>& duplicates() const { return duplicates_; }

private:
    template <typename Ids>
    void build(const Ids& ids);

    long long min_ = 0;
    static constexpr std::uint32_t absent = 0xFFFFFFFFu;
    std::vector<std::uint32_t> dense_;  // id - min_ → position, `absent` when none (4 bytes: decks of 1e7)
    std::vector<std::pair<long long, std::size_t>> sorted_;  // (id, position) when ids are sparse
    std::vector<std::pair<std::size_t, std::size_t>> duplicates_;
};

// (first position, repeated position) of duplicated ids without building an index: one bit per
// id for compact ranges, a sorted copy otherwise. For particle ids, checked only for duplicates.
std::vector<std::pair<std::size_t, std::size_t>> find_duplicate_ids(const std::vector<long long>& ids);
std::vector<std::pair<std::size_t, std::size_t>> find_duplicate_ids(const IdColumn& ids);

}  // namespace sphdeck::model
