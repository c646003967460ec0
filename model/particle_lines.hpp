// Each particle's card line (an index into RawDeck::lines), kept as runs instead of 4 bytes a
// particle (issue 40 item 2): a block decoded one particle a line is one run (step 1), an NEND range
// one run of its line (step 0), a Radioss /SPH block one run of consecutive lines. Reads like a
// std::vector<std::uint32_t>; a read looks its run up (a binary search over a handful of runs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphdeck::model {

class ParticleLines {
public:
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    std::uint32_t operator[](std::size_t i) const;
    std::uint32_t at(std::size_t i) const;  // throws std::out_of_range past the end

    void push_back(std::uint32_t line);
    // `count` particles on lines first_line, first_line + step, ...
    void append_run(std::size_t count, std::uint32_t first_line, std::uint32_t step);
    void resize(std::size_t n);  // new particles on line 0
    void reserve(std::size_t) {}
    void assign(std::size_t n, std::uint32_t line) { clear(), append_run(n, line, 0); }
    void pop_back() { resize(size_ - 1); }
    void clear() { runs_.clear(), size_ = 0; }
    // Small models of tests: O(size) each.
    void insert(std::size_t at, std::uint32_t line);
    void erase(std::size_t at);

    std::size_t runs() const { return runs_.size(); }
    std::vector<std::uint32_t> all() const;  // one entry a particle (tests, small models)

    friend bool operator==(const ParticleLines& a, const ParticleLines& b) { return a.all() == b.all(); }

private:
    struct Run {
        std::size_t slot = 0;  // the run's first particle
        std::size_t count = 0;
        std::uint32_t line = 0;  // the first particle's line
        std::uint32_t step = 0;  // 0: every particle on that line; 1: one line each
    };
    std::vector<Run> runs_;
    std::size_t size_ = 0;
};

}  // namespace sphdeck::model
