#include "grammar/card_lines.hpp"

#include <algorithm>

namespace sphdeck::grammar {

CardLinePtr::CardLinePtr(const CardLines& lines, std::uint32_t index, bool settled)
    : lines_(&lines.body()), index_(index) {
    if (settled) settle();
}

void CardLinePtr::settle() {
    lo_ = hi_ = index_;
    stored_ = nullptr;
    if (lines_ && index_ < lines_->size) lines_->describe(*this);
}

CardLine CardLinePtr::slow() const {
    CardLinePtr p = *this;
    p.settle();
    if (p.hi_ == p.lo_) return CardLine{};  // past the end or null: nothing to read (as a past-the-end pointer)
    return *p;
}

void CardLinesBody::describe(CardLinePtr& p) const {
    const std::uint32_t i = p.index_;
    if (runs.empty()) {
        p.lo_ = 0, p.hi_ = static_cast<std::uint32_t>(size), p.stored_ = stored.data();
        return;
    }
    // The first run past i, and the one before it.
    const auto next =
        std::upper_bound(runs.begin(), runs.end(), i, [](std::uint32_t at, const Run& r) { return at < r.first; });
    if (next != runs.begin()) {
        const Run& r = *(next - 1);
        if (i - r.first < r.count) {
            p.lo_ = r.first, p.hi_ = r.first + r.count, p.stored_ = nullptr;
            p.origin_ = r.origin, p.stride_ = r.stride;
            return;
        }
        p.lo_ = r.first + r.count;
        p.stored_ = stored.data() + r.stored_before;
    } else {
        p.lo_ = 0;
        p.stored_ = stored.data();
    }
    p.hi_ = next != runs.end() ? next->first : static_cast<std::uint32_t>(size);
}

const CardLinesBody& CardLines::empty_body() {
    static const CardLinesBody none;
    return none;
}

CardLinesBody& CardLines::own() {
    if (!body_) body_ = std::make_unique<CardLinesBody>();
    return *body_;
}

void CardLines::reserve(std::size_t n) {
    const std::size_t in_runs = runs_lines();
    own().stored.reserve(n > in_runs ? n - in_runs : 0);
}

void CardLines::add_run(const CardLine& origin, std::uint32_t stride, std::uint32_t count) {
    CardLinesBody& b = own();
    CardLinesBody::Run r;
    r.first = static_cast<std::uint32_t>(b.size);
    r.count = count;
    r.stored_before = static_cast<std::uint32_t>(b.stored.size());
    r.origin = origin;
    r.stride = stride;
    b.runs.push_back(r);
    b.size += count;
    b.tail = 0;
}

void CardLines::push_back(const CardLine& line) {
    CardLinesBody& b = own();
    if (!b.runs.empty() && b.runs.back().first + b.runs.back().count == b.size) {  // the last line is a run's
        CardLinesBody::Run& r = b.runs.back();
        if (line.file == r.origin.file && line.line == r.origin.line + r.count &&
            line.offset == r.origin.offset + r.count * r.stride) {
            ++r.count;
            ++b.size;
            return;
        }
        b.stored.push_back(line);
        ++b.size;
        b.tail = 1;
        return;
    }
    if (b.tail > 0) {
        const CardLine& last = b.stored.back();
        bool regular = line.file == last.file && line.line == last.line + 1 && line.offset > last.offset;
        if (regular && b.tail > 1)
            regular = line.offset - last.offset == last.offset - b.stored[b.stored.size() - 2].offset;
        b.tail = regular ? b.tail + 1 : 1;
    } else {
        b.tail = 1;
    }
    b.stored.push_back(line);
    ++b.size;
    if (b.tail == min_run) {  // the last min_run stored lines become a run
        const std::size_t from = b.stored.size() - min_run;
        const CardLine origin = b.stored[from];
        const std::uint32_t stride = b.stored[from + 1].offset - origin.offset;
        b.stored.resize(from);
        b.size -= min_run;
        add_run(origin, stride, min_run);
    }
}

void CardLines::push_back_lines(FileId file, std::uint32_t first_line, const std::uint32_t* starts, std::size_t count) {
    std::size_t i = 0;
    while (i < count) {
        CardLinesBody& b = own();
        if (!b.runs.empty() && b.runs.back().first + b.runs.back().count == b.size) {  // the last line is a run's
            CardLinesBody::Run& r = b.runs.back();
            // The line numbers run on by construction: the offsets decide how far the run goes on.
            if (file == r.origin.file && first_line + i == r.origin.line + r.count) {
                std::uint32_t next = r.origin.offset + r.count * r.stride;
                std::size_t k = i;
                for (; k < count && starts[k] == next; ++k) next += r.stride;
                r.count += static_cast<std::uint32_t>(k - i);
                b.size += k - i;
                i = k;
                if (i == count) return;
            }
        }
        push_back(CardLine{file, first_line + static_cast<std::uint32_t>(i), starts[i]});
        ++i;
    }
}

void CardLines::pop_back() {
    CardLinesBody& b = own();
    if (!b.runs.empty() && b.runs.back().first + b.runs.back().count == b.size) {
        if (--b.runs.back().count == 0) b.runs.pop_back();
    } else {
        b.stored.pop_back();
    }
    --b.size;
    b.tail = 0;  // regular lines before it may still become a run; none is merely slower
}

void CardLines::append(const CardLines& from, std::size_t begin, std::size_t end, const Move& move) {
    const auto moved = [&](CardLine l) {
        l.line += move.line_shift;
        l.offset += move.byte_shift;
        if (move.set_file) l.file = move.file;
        return l;
    };
    CardLinePtr p(from, static_cast<std::uint32_t>(begin));
    while (p.index_ < end) {
        const std::uint32_t stop = std::min(p.hi_, static_cast<std::uint32_t>(end));
        const std::uint32_t count = stop - p.index_;
        if (p.stored_ || count < min_run) {
            for (; p.index_ < stop; ++p.index_) push_back(moved(*p));
        } else {
            const std::uint32_t k = p.index_ - p.lo_;
            const CardLine origin =
                moved(CardLine{p.origin_.file, p.origin_.line + k, p.origin_.offset + k * p.stride_});
            CardLinesBody& b = own();
            CardLinesBody::Run* last = b.runs.empty() ? nullptr : &b.runs.back();
            if (last && last->first + last->count == b.size && last->stride == p.stride_ &&
                origin.file == last->origin.file && origin.line == last->origin.line + last->count &&
                origin.offset == last->origin.offset + last->count * last->stride) {
                last->count += count;
                b.size += count;
            } else {
                add_run(origin, p.stride_, count);
            }
            p.index_ = stop;
        }
        p.settle();
    }
}

}  // namespace sphdeck::grammar
