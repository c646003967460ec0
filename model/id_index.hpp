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

    // Position of `id` in the indexed array (the first one when duplicated). Inline: the rules ask it once
    // a particle (a call each showed in profiles).
    [[gnu::always_inline]] std::optional<std::size_t> find(long long id) const {
        if (arithmetic_) return find_in_sequence(id);
        if (!dense_.empty()) {
            if (id < min_) return std::nullopt;
            const unsigned long long at = static_cast<unsigned long long>(id) - static_cast<unsigned long long>(min_);
            if (at >= dense_.size() || dense_[at] == absent) return std::nullopt;
            return dense_[at];
        }
        return find_sorted(id);
    }

    // (first position, repeated position) of every duplicated id, in array order.
    const std::vector<std::pair<std::size_t, std::size_t>>& duplicates() const { return duplicates_; }

private:
    template <typename Ids>
    void build(const Ids& ids);
    [[gnu::always_inline]] std::optional<std::size_t> find_in_sequence(long long id) const {
        // In unsigned magnitudes: offset and step have the same sign for an id of the column.
        long long offset = 0;
        if (__builtin_sub_overflow(id, min_, &offset) || (offset != 0 && (offset < 0) != (step_ < 0)))
            return std::nullopt;
        const auto magnitude = [](long long v) {
            return v < 0 ? 0ull - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
        };
        const unsigned long long distance = magnitude(offset), stride = magnitude(step_);
        if (stride != 1 && distance % stride != 0) return std::nullopt;
        const unsigned long long position = stride == 1 ? distance : distance / stride;  // no division for 1..n
        if (position >= count_) return std::nullopt;
        return static_cast<std::size_t>(position);
    }
    std::optional<std::size_t> find_sorted(long long id) const;

    // A column kept as first + step * i with step != 0 (IdColumn::compact: node ids 1..n): its ids are
    // distinct and a position is found by arithmetic, without a table of 4 bytes an id.
    bool arithmetic_ = false;
    long long step_ = 0;
    std::size_t count_ = 0;

    long long min_ = 0;  // the least id (a table's base); an arithmetic index's entry 0
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
