#include "model/id_column.hpp"

#include <cstring>
#include <stdexcept>

namespace sphdeck::model {

namespace {
// Ids kept aside cost 16 bytes each; past one in 16 entries the column holds all in 8 bytes.
constexpr std::size_t aside_allowance(std::size_t size) { return size / 16 + 64; }
}  // namespace

long long IdColumn::aside(std::size_t i) const {
    const auto it =
        std::lower_bound(aside_.begin(), aside_.end(), i, [](const Aside& a, std::size_t at) { return a.first < at; });
    return it->second;
}

long long IdColumn::at(std::size_t i) const {
    if (i >= size()) throw std::out_of_range("IdColumn::at");
    return (*this)[i];
}

void IdColumn::push_back(long long id) {
    write_out();
    if (full_) return wide_ids_.push_back(id);
    if (fits(id)) return narrow_.push_back(static_cast<std::int32_t>(id));
    aside_.emplace_back(narrow_.size(), id);
    narrow_.push_back(aside_mark);
    widen_if_many();
}

void IdColumn::set(std::size_t i, long long id) {
    write_out();
    if (full_) return void(wide_ids_[i] = id);
    auto it =
        std::lower_bound(aside_.begin(), aside_.end(), i, [](const Aside& a, std::size_t at) { return a.first < at; });
    const bool was_aside = narrow_[i] == aside_mark && it != aside_.end() && it->first == i;
    if (fits(id)) {
        if (was_aside) aside_.erase(it);
        narrow_[i] = static_cast<std::int32_t>(id);
        return;
    }
    narrow_[i] = aside_mark;
    if (was_aside)
        it->second = id;
    else
        aside_.insert(it, {i, id});
    widen_if_many();
}

void IdColumn::resize(std::size_t n) {
    write_out();
    if (full_) return wide_ids_.resize(n);
    if (n < narrow_.size()) {
        auto it = std::lower_bound(aside_.begin(), aside_.end(), n,
                                   [](const Aside& a, std::size_t at) { return a.first < at; });
        aside_.erase(it, aside_.end());
    }
    narrow_.resize(n, 0);
}

void IdColumn::append(const IdColumn& from, std::size_t first, std::size_t count) {
    if (size() == 0 && from.sequence_ && count >= compact_min_entries) {  // a long piece of a sequence: one too
        assign_sequence(from[first], from.step_, count);
        return;
    }
    write_out();
    if (!full_ && from.plain_narrow()) {
        const auto begin = from.narrow_.begin() + static_cast<std::ptrdiff_t>(first);
        narrow_.insert(narrow_.end(), begin, begin + static_cast<std::ptrdiff_t>(count));
        return;
    }
    if (!full_ && from.sequence_) {  // a sequence's entries all fit in 4 bytes
        narrow_.reserve(narrow_.size() + count);
        for (std::size_t i = first; i < first + count; ++i) narrow_.push_back(static_cast<std::int32_t>(from[i]));
        return;
    }
    reserve(size() + count);
    for (std::size_t i = first; i < first + count; ++i) push_back(from[i]);
}

void IdColumn::copy_from(const IdColumn& from, std::size_t first, std::size_t count, std::size_t to) {
    write_out();
    if (plain_narrow() && from.plain_narrow()) {
        const auto begin = from.narrow_.begin() + static_cast<std::ptrdiff_t>(first);
        std::copy(begin, begin + static_cast<std::ptrdiff_t>(count), narrow_.begin() + static_cast<std::ptrdiff_t>(to));
        return;
    }
    if (plain_narrow() && from.sequence_) {
        for (std::size_t i = 0; i < count; ++i) narrow_[to + i] = static_cast<std::int32_t>(from[first + i]);
        return;
    }
    for (std::size_t i = 0; i < count; ++i) set(to + i, from[first + i]);
}

IdColumn::const_iterator IdColumn::insert(const_iterator at, long long id) {
    std::vector<long long> all(begin(), end());
    const std::size_t i = at.index();
    all.insert(all.begin() + static_cast<std::ptrdiff_t>(i), id);
    clear();
    for (long long v : all) push_back(v);
    return {this, i};
}

IdColumn::const_iterator IdColumn::erase(const_iterator at) {
    std::vector<long long> all(begin(), end());
    const std::size_t i = at.index();
    all.erase(all.begin() + static_cast<std::ptrdiff_t>(i));
    clear();
    for (long long v : all) push_back(v);
    return {this, i};
}

bool IdColumn::compact() {
    if (sequence_) return true;
    if (!plain_narrow() || narrow_.size() < compact_min_entries) return false;
    const long long first = narrow_[0], step = static_cast<long long>(narrow_[1]) - first;
    for (std::size_t i = 2; i < narrow_.size(); ++i)
        if (narrow_[i] != first + step * static_cast<long long>(i)) return false;
    sequence_size_ = narrow_.size(), first_ = first, step_ = step, sequence_ = true;
    std::vector<std::int32_t>().swap(narrow_);  // given back (`narrow_ = {}` would keep its capacity)
    return true;
}

void IdColumn::assign_sequence(long long first, long long step, std::size_t n) {
    clear();
    std::vector<std::int32_t>().swap(narrow_);
    sequence_size_ = n, first_ = first, step_ = step, sequence_ = true;
}

void IdColumn::write_out_sequence() {
    // Every entry fits in 4 bytes: the sequence was made from narrow entries (and a prefix of it stays one).
    std::vector<std::int32_t> entries(sequence_size_);
    for (std::size_t i = 0; i < sequence_size_; ++i)
        entries[i] = static_cast<std::int32_t>(first_ + step_ * static_cast<long long>(i));
    sequence_ = false;
    narrow_ = std::move(entries);
}

void IdColumn::widen_if_many() {
    if (aside_.size() <= aside_allowance(narrow_.size())) return;
    std::vector<long long> all(begin(), end());
    wide_ids_ = std::move(all);
    full_ = true;
    std::vector<std::int32_t>().swap(narrow_), std::vector<Aside>().swap(aside_);
}

bool operator==(const IdColumn& a, const IdColumn& b) {
    if (a.size() != b.size()) return false;
    if (a.sequence_ && b.sequence_) return a.first_ == b.first_ && (a.step_ == b.step_ || a.size() == 1);
    if (!a.sequence_ && !b.sequence_ && !a.full_ && !b.full_ && a.aside_ == b.aside_) return a.narrow_ == b.narrow_;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) return false;
    return true;
}

std::size_t first_difference(const IdColumn& a, const IdColumn& b, std::size_t n) {
    std::size_t i = 0;
    if (a.plain_narrow() && b.plain_narrow()) {
        constexpr std::size_t block = 1024;
        const std::int32_t *x = a.narrow_.data(), *y = b.narrow_.data();
        while (i + block <= n && std::memcmp(x + i, y + i, block * sizeof(std::int32_t)) == 0) i += block;
    }
    while (i < n && a[i] == b[i]) ++i;
    return i;
}

std::size_t common_tail(const IdColumn& a, std::size_t a_end, const IdColumn& b, std::size_t b_end, std::size_t n) {
    std::size_t k = 0;
    if (a.plain_narrow() && b.plain_narrow()) {
        constexpr std::size_t block = 1024;
        const std::int32_t *x = a.narrow_.data(), *y = b.narrow_.data();
        while (k + block <= n &&
               std::memcmp(x + a_end - k - block, y + b_end - k - block, block * sizeof(std::int32_t)) == 0)
            k += block;
    }
    while (k < n && a[a_end - k - 1] == b[b_end - k - 1]) ++k;
    return k;
}

}  // namespace sphdeck::model
