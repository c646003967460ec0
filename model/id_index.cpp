#include "model/id_index.hpp"

#include <algorithm>

namespace sphdeck::model {

IdIndex::IdIndex(const std::vector<long long>& ids) { build(ids); }
IdIndex::IdIndex(const IdColumn& ids) {
    if (ids.sequence() && ids.sequence_step() != 0) {
        arithmetic_ = true, min_ = ids.sequence_first(), step_ = ids.sequence_step(), count_ = ids.size();
        return;
    }
    build(ids);
}

template <typename Ids>
void IdIndex::build(const Ids& ids) {
    if (ids.empty()) return;
    auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
    min_ = *lo;
    const unsigned long long span = static_cast<unsigned long long>(*hi) - static_cast<unsigned long long>(*lo);
    if (span < 4ull * ids.size() + 1024 && ids.size() < absent) {
        dense_.assign(span + 1, absent);
        for (std::size_t i = 0; i < ids.size(); ++i) {
            std::uint32_t& slot = dense_[static_cast<std::size_t>(ids[i] - min_)];
            if (slot != absent)
                duplicates_.emplace_back(slot, i);
            else
                slot = static_cast<std::uint32_t>(i);
        }
        return;
    }
    sorted_.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) sorted_.emplace_back(ids[i], i);
    std::sort(sorted_.begin(), sorted_.end());
    for (std::size_t i = 1; i < sorted_.size(); ++i) {
        if (sorted_[i].first != sorted_[i - 1].first) continue;
        std::size_t first = i - 1;
        while (first > 0 && sorted_[first - 1].first == sorted_[i].first) --first;
        duplicates_.emplace_back(sorted_[first].second, sorted_[i].second);
    }
    std::sort(duplicates_.begin(), duplicates_.end(), [](auto& a, auto& b) { return a.second < b.second; });
}

std::optional<std::size_t> IdIndex::find_sorted(long long id) const {
    auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(id, std::size_t{0}));
    if (it == sorted_.end() || it->first != id) return std::nullopt;
    return it->second;
}

namespace {
template <typename Ids>
std::vector<std::pair<std::size_t, std::size_t>> duplicate_ids_of(const Ids& ids) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    if (ids.empty()) return out;
    auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
    const unsigned long long span = static_cast<unsigned long long>(*hi) - static_cast<unsigned long long>(*lo);
    if (span >= 64ull * ids.size() + 4096) return IdIndex(ids).duplicates();
    std::vector<bool> seen(span + 1, false);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        auto slot = static_cast<std::size_t>(ids[i] - *lo);
        if (!seen[slot]) {
            seen[slot] = true;
            continue;
        }
        std::size_t first = static_cast<std::size_t>(std::find(ids.begin(), ids.end(), ids[i]) - ids.begin());
        out.emplace_back(first, i);
        if (out.size() > 1000) break;  // enough to report; the scan for `first` is linear
    }
    return out;
}
}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> find_duplicate_ids(const std::vector<long long>& ids) {
    return duplicate_ids_of(ids);
}
std::vector<std::pair<std::size_t, std::size_t>> find_duplicate_ids(const IdColumn& ids) {
    if (ids.sequence() && ids.sequence_step() != 0) return {};  // first + step * i: every id distinct
    return duplicate_ids_of(ids);
}

}  // namespace sphdeck::model
