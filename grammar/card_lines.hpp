// The card lines of a deck (issue 40 item 2): where each data line starts, kept without an object a line
// where the lines are regular. A bulk block written by a preprocessor (*NODE, *ELEMENT_SPH, /NODE, /SPH)
// has lines of one width one after the other: line k of such a run is at offset + k * stride on line
// number + k, so the run keeps its first line and its stride (28 bytes for any number of lines) where a
// CardLine a line kept 12 bytes a line (24 MB a million particles). Other lines are kept as they are.
// Readers see the same lines either way: by index (`lines[i]`, a CardLine by value) or through a
// CardLinePtr, which walks them like a `const CardLine*`.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <vector>

#include "text/source_map.hpp"

namespace sphdeck::grammar {

// One data line of a block: where it starts in its file's text. The length is not stored: the line ends
// at the next '\n' (the readers split lines there), found again with memchr when the text is asked for.
struct CardLine {
    FileId file = 0;
    std::uint32_t line = 0;    // 1-based line number
    std::uint32_t offset = 0;  // byte offset of the line in the file text
};

class CardLines;
struct CardLinesBody;

// A position in a CardLines, used as a `const CardLine*` was: ++, +n, -, comparisons, *p and p->line (a
// CardLine made on the spot: never take its address), p[n]; null by default. It keeps the stretch its
// line lies in (stored lines or a run), so that walking a block costs no look-up a line.
class CardLinePtr {
public:
    using iterator_category = std::random_access_iterator_tag;
    using iterator_concept = std::random_access_iterator_tag;
    using value_type = CardLine;
    using difference_type = std::ptrdiff_t;
    using reference = CardLine;
    struct Arrow {
        CardLine line;
        const CardLine* operator->() const { return &line; }
    };
    using pointer = Arrow;

    CardLinePtr() = default;
    CardLinePtr(std::nullptr_t) {}
    // Settled: its stretch found now (else at the first step or on each *p: an end is compared, not read).
    CardLinePtr(const CardLines& lines, std::uint32_t index, bool settled = true);

    // Inline always: the bulk walks take it once a line (a call a line showed in profiles).
    [[gnu::always_inline]] CardLine operator*() const {
        const std::uint32_t k = index_ - lo_;
        if (k >= hi_ - lo_) return slow();
        if (stored_) return stored_[k];
        return CardLine{origin_.file, origin_.line + k, origin_.offset + k * stride_};
    }
    Arrow operator->() const { return Arrow{**this}; }
    CardLine operator[](difference_type n) const { return *(*this + n); }

    CardLinePtr& operator+=(difference_type n) {
        index_ = static_cast<std::uint32_t>(static_cast<difference_type>(index_) + n);
        if (index_ - lo_ >= hi_ - lo_) settle();
        return *this;
    }
    CardLinePtr& operator-=(difference_type n) { return *this += -n; }
    [[gnu::always_inline]] CardLinePtr& operator++() {
        if (++index_ - lo_ >= hi_ - lo_) settle();
        return *this;
    }
    CardLinePtr& operator--() { return *this += -1; }
    CardLinePtr operator++(int) {
        CardLinePtr was = *this;
        ++*this;
        return was;
    }
    CardLinePtr operator--(int) {
        CardLinePtr was = *this;
        --*this;
        return was;
    }
    friend CardLinePtr operator+(CardLinePtr p, difference_type n) { return p += n; }
    friend CardLinePtr operator+(difference_type n, CardLinePtr p) { return p += n; }
    friend CardLinePtr operator-(CardLinePtr p, difference_type n) { return p -= n; }
    friend difference_type operator-(const CardLinePtr& a, const CardLinePtr& b) {
        return static_cast<difference_type>(a.index_) - static_cast<difference_type>(b.index_);
    }
    friend bool operator==(const CardLinePtr& a, const CardLinePtr& b) {
        return a.lines_ == b.lines_ && a.index_ == b.index_;
    }
    friend std::strong_ordering operator<=>(const CardLinePtr& a, const CardLinePtr& b) {
        return a.index_ <=> b.index_;
    }
    explicit operator bool() const { return lines_ != nullptr; }

    // The line's index in its CardLines (what `p - deck.lines.data()` was).
    std::uint32_t index() const { return index_; }

    // Where the line lies when it is in a run (lines of one stride on consecutive line numbers of one file):
    // that stride and how many lines of the run follow it. Stride 0 for a stored line (or none).
    struct RunPlace {
        std::uint32_t stride = 0, after = 0;
    };
    RunPlace run_place() const {
        if (stored_ || index_ - lo_ >= hi_ - lo_) return {};
        return {stride_, hi_ - 1 - index_};
    }

private:
    friend class CardLines;
    friend struct CardLinesBody;
    CardLine slow() const;
    void settle();  // finds the stretch of index_ (none past the end)

    const CardLinesBody* lines_ = nullptr;  // on the heap: stays where it is when its CardLines moves
    std::uint32_t index_ = 0;
    std::uint32_t lo_ = 0, hi_ = 0;     // the stretch [lo_, hi_) the fields below describe
    const CardLine* stored_ = nullptr;  // the stored line at lo_, or null in a run
    CardLine origin_;                   // a run's line at lo_
    std::uint32_t stride_ = 0;          // a run's bytes a line
};

// What a CardLines holds. Its lines are stored ones and runs; a run's lines are not stored.
struct CardLinesBody {
    struct Run {
        std::uint32_t first = 0;  // index of its first line
        std::uint32_t count = 0;
        std::uint32_t stored_before = 0;  // stored lines before `first`
        CardLine origin;
        std::uint32_t stride = 0;
    };
    std::vector<CardLine> stored;
    std::vector<Run> runs;
    std::size_t size = 0;
    std::uint32_t tail = 0;  // stored lines at the end, after the last run, that are regular so far

    void describe(CardLinePtr& p) const;  // fills p's stretch for its index
};

// The lines, as a vector of them was used (moved, copied, appended to). A CardLinePtr into it stays
// valid when it moves, as a pointer into a vector did.
class CardLines {
public:
    // Lines of one stride on consecutive line numbers of one file become a run from this many on.
    static constexpr std::uint32_t min_run = 32;

    CardLines() : body_(std::make_unique<CardLinesBody>()) {}
    CardLines(const CardLines& other) : body_(std::make_unique<CardLinesBody>(other.body())) {}
    CardLines(CardLines&& other) noexcept = default;
    CardLines& operator=(const CardLines& other) {
        if (this != &other) body_ = std::make_unique<CardLinesBody>(other.body());
        return *this;
    }
    CardLines& operator=(CardLines&& other) noexcept = default;

    std::size_t size() const { return body_ ? body_->size : 0; }
    bool empty() const { return size() == 0; }
    CardLine operator[](std::size_t i) const { return *CardLinePtr(*this, static_cast<std::uint32_t>(i), false); }
    CardLine back() const { return (*this)[size() - 1]; }
    CardLinePtr begin() const { return CardLinePtr(*this, 0); }
    CardLinePtr end() const { return CardLinePtr(*this, static_cast<std::uint32_t>(size()), false); }
    CardLinePtr at(std::size_t i) const { return CardLinePtr(*this, static_cast<std::uint32_t>(i)); }

    void push_back(const CardLine& line);
    // `count` lines of `file` on consecutive line numbers from `first_line`, starting at `starts`: the lines
    // push_back would keep, a run extended in one step (a reader's run of data lines, a bulk block's).
    void push_back_lines(FileId file, std::uint32_t first_line, const std::uint32_t* starts, std::size_t count);
    void pop_back();
    // Room for `n` lines in all (stored ones: a run needs none).
    void reserve(std::size_t n);
    std::size_t capacity() const { return body_ ? body_->stored.capacity() + runs_lines() : 0; }
    void clear() { body_ = std::make_unique<CardLinesBody>(); }

    // Appends lines [begin, end) of `from` moved by `line_shift` lines and `byte_shift` bytes (modulo 2^32:
    // a negative shift wraps back), into file `file` where `set_file`: runs stay runs.
    struct Move {
        std::uint32_t line_shift = 0, byte_shift = 0;
        bool set_file = false;
        FileId file = 0;
    };
    void append(const CardLines& from, std::size_t begin, std::size_t end, const Move& move);
    void append(const CardLines& from, std::size_t begin, std::size_t end) { append(from, begin, end, Move{}); }

    // What it holds (for profiles and tests): bytes, stored lines, runs.
    std::size_t bytes() const {
        return body_ ? body_->stored.capacity() * sizeof(CardLine) + body_->runs.capacity() * sizeof(CardLinesBody::Run)
                     : 0;
    }
    std::size_t stored_lines() const { return body_ ? body_->stored.size() : 0; }
    std::size_t runs() const { return body_ ? body_->runs.size() : 0; }

private:
    friend class CardLinePtr;
    static const CardLinesBody& empty_body();
    const CardLinesBody& body() const { return body_ ? *body_ : empty_body(); }
    CardLinesBody& own();  // the body, made again after a move
    std::size_t runs_lines() const { return size() - stored_lines(); }
    void add_run(const CardLine& origin, std::uint32_t stride, std::uint32_t count);

    std::unique_ptr<CardLinesBody> body_;
};

}  // namespace sphdeck::grammar
