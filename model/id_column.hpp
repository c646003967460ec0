// A column of integer ids (node ids, the particles' nodes and parts) held in 4 bytes an entry while
// the ids fit, as nearly every deck's do: a deck of 1e7 particles keeps 3e7 of them (issue 40 item 2).
// An id that does not fit (10-digit I10 ids, labels read as numbers) is kept aside, sorted by
// position; a column with many such ids holds all of them in 8 bytes instead, so no deck pays more
// than a std::vector<long long> would. A column that is first + step * i (node ids 1..n, the particles'
// nodes 1..n, one part for every particle: what preprocessors write) can be kept as those two numbers
// (compact(): no bytes an entry, issue 40), and is written out again by the first change. Read like a
// std::vector<long long> (index, iterate, compare); written through push_back, set and resize.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace sphdeck::model {

class IdColumn {
public:
    using value_type = long long;

    class const_iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = long long;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = long long;

        const_iterator() = default;
        const_iterator(const IdColumn* column, std::size_t at) : column_(column), at_(at) {}
        long long operator*() const { return (*column_)[at_]; }
        long long operator[](difference_type n) const { return (*column_)[at_ + static_cast<std::size_t>(n)]; }
        const_iterator& operator++() { return ++at_, *this; }
        const_iterator operator++(int) { return {column_, at_++}; }
        const_iterator& operator--() { return --at_, *this; }
        const_iterator operator--(int) { return {column_, at_--}; }
        const_iterator& operator+=(difference_type n) { return at_ += static_cast<std::size_t>(n), *this; }
        const_iterator& operator-=(difference_type n) { return at_ -= static_cast<std::size_t>(n), *this; }
        friend const_iterator operator+(const_iterator i, difference_type n) { return i += n; }
        friend const_iterator operator+(difference_type n, const_iterator i) { return i += n; }
        friend const_iterator operator-(const_iterator i, difference_type n) { return i -= n; }
        friend difference_type operator-(const const_iterator& a, const const_iterator& b) {
            return static_cast<difference_type>(a.at_) - static_cast<difference_type>(b.at_);
        }
        friend bool operator==(const const_iterator& a, const const_iterator& b) { return a.at_ == b.at_; }
        friend auto operator<=>(const const_iterator& a, const const_iterator& b) { return a.at_ <=> b.at_; }
        std::size_t index() const { return at_; }

    private:
        const IdColumn* column_ = nullptr;
        std::size_t at_ = 0;
    };
    using iterator = const_iterator;  // read-only: write through set()

    IdColumn() = default;
    IdColumn(std::initializer_list<long long> ids) {
        for (long long id : ids) push_back(id);
    }
    template <typename It>
    IdColumn(It first, It last) {
        for (; first != last; ++first) push_back(*first);
    }

    std::size_t size() const { return sequence_ ? sequence_size_ : full_ ? wide_ids_.size() : narrow_.size(); }
    bool empty() const { return size() == 0; }
    long long operator[](std::size_t i) const {
        if (sequence_) return first_ + step_ * static_cast<long long>(i);
        if (full_) return wide_ids_[i];
        const std::int32_t v = narrow_[i];
        return v != aside_mark ? v : aside(i);
    }
    long long at(std::size_t i) const;  // throws std::out_of_range past the end, as std::vector::at
    long long front() const { return (*this)[0]; }
    long long back() const { return (*this)[size() - 1]; }
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

    void push_back(long long id);
    void pop_back() { resize(size() - 1); }
    // Entry `i` (< size()) becomes `id`. One thread at a time; see set_narrow for the parallel path.
    void set(std::size_t i, long long id);
    // The parallel decoding's write: `id` stored at `i` when it fits in 4 bytes (true), else false and
    // the caller hands it to set() afterwards, on one thread. Distinct `i` on several threads at once.
    bool set_narrow(std::size_t i, long long id) {
        if (sequence_) return false;  // written out by set(), on one thread
        if (full_) return wide_ids_[i] = id, true;
        if (!fits(id) || narrow_[i] == aside_mark) return false;
        narrow_[i] = static_cast<std::int32_t>(id);
        return true;
    }
    void resize(std::size_t n);  // new entries are 0
    void reserve(std::size_t n) {
        write_out();
        full_ ? wide_ids_.reserve(n) : narrow_.reserve(n);
    }
    std::size_t capacity() const {
        return sequence_ ? sequence_size_ : full_ ? wide_ids_.capacity() : narrow_.capacity();
    }
    void clear() { narrow_.clear(), aside_.clear(), wide_ids_.clear(), full_ = false, sequence_ = false; }
    void assign(std::size_t n, long long id) {
        clear();
        for (std::size_t i = 0; i < n; ++i) push_back(id);
    }
    // Entries [first, first + count) of `from` appended.
    void append(const IdColumn& from, std::size_t first, std::size_t count);
    // Entries [first, first + count) of `from` copied to [to, to + count) of this column (within size()).
    void copy_from(const IdColumn& from, std::size_t first, std::size_t count, std::size_t to);
    // Small columns of tests and generated particles: O(size) each.
    const_iterator insert(const_iterator at, long long id);
    const_iterator erase(const_iterator at);

    // Keeps the column as first + step * i when it is one and long enough for that to free whole pages
    // (true then): its entries are given back. Any later change writes them out again.
    bool compact();
    // 64 KiB of entries at least: below that the pages freed are few, and small decks (an editor's) are
    // left as they were.
    static constexpr std::size_t compact_min_entries = 16384;
    // An empty column made the sequence first + step * i of `n` entries, each of which fits() (as compact()
    // would leave the column written out; the parallel decoding's runs, model/id_run.hpp).
    void assign_sequence(long long first, long long step, std::size_t n);
    bool sequence() const { return sequence_; }
    // Whether `id` is kept in 4 bytes (else aside, or the column widens).
    static bool fits(long long id) { return id > aside_mark && id <= std::numeric_limits<std::int32_t>::max(); }
    // A sequence's entry 0 and step (entry i is first + step * i); meaningful only while sequence().
    long long sequence_first() const { return first_; }
    long long sequence_step() const { return step_; }

    // Bytes held (capacity aside): 4 an entry while narrow, none as a sequence.
    std::size_t bytes() const {
        return narrow_.size() * sizeof(std::int32_t) + aside_.size() * sizeof(Aside) +
               wide_ids_.size() * sizeof(long long);
    }
    // Heap bytes held, capacities included: what compact() gives back.
    std::size_t heap_bytes() const {
        return narrow_.capacity() * sizeof(std::int32_t) + aside_.capacity() * sizeof(Aside) +
               wide_ids_.capacity() * sizeof(long long);
    }
    bool narrow() const { return !full_; }  // 4 bytes an entry at most (a sequence is narrow)

    friend bool operator==(const IdColumn& a, const IdColumn& b);
    friend bool operator==(const IdColumn& a, const std::vector<long long>& b) {
        return a.size() == b.size() && std::equal(b.begin(), b.end(), a.begin());
    }
    // The first i < n where a[i] != b[i] (n when none); the count k <= n of equal entries at the ends of
    // a[0, a_end) and b[0, b_end). Whole blocks compared at once while both columns are narrow.
    friend std::size_t first_difference(const IdColumn& a, const IdColumn& b, std::size_t n);
    friend std::size_t common_tail(const IdColumn& a, std::size_t a_end, const IdColumn& b, std::size_t b_end,
                                   std::size_t n);

private:
    static constexpr std::int32_t aside_mark = std::numeric_limits<std::int32_t>::min();
    using Aside = std::pair<std::size_t, long long>;                    // (position, id), sorted by position
    [[gnu::cold, gnu::noinline]] long long aside(std::size_t i) const;  // out of line: operator[] stays small
    void widen_if_many();
    // A sequence's entries written out as narrow ones, before any change.
    void write_out() {
        if (sequence_) write_out_sequence();
    }
    [[gnu::cold, gnu::noinline]] void write_out_sequence();
    // Whether the entries may be compared as narrow_ arrays (no sequence, no aside, not full).
    bool plain_narrow() const { return !sequence_ && !full_ && aside_.empty(); }

    std::vector<std::int32_t> narrow_;  // the ids, or aside_mark where the id is in aside_
    std::vector<Aside> aside_;
    std::vector<long long> wide_ids_;  // every id, once the column is full_
    bool full_ = false;
    // A sequence: entry i is first_ + step_ * i, and narrow_, aside_ and wide_ids_ are empty.
    bool sequence_ = false;
    long long first_ = 0, step_ = 0;
    std::size_t sequence_size_ = 0;
};

}  // namespace sphdeck::model
