#include "model/particle_lines.hpp"

#include <algorithm>
#include <stdexcept>

namespace sphdeck::model {

std::uint32_t ParticleLines::operator[](std::size_t i) const {
    // The last run whose first particle is at or before i.
    auto it = std::upper_bound(runs_.begin(), runs_.end(), i, [](std::size_t at, const Run& r) { return at < r.slot; });
    const Run& run = *(it - 1);
    return run.line + run.step * static_cast<std::uint32_t>(i - run.slot);
}

std::uint32_t ParticleLines::at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("ParticleLines::at");
    return (*this)[i];
}

void ParticleLines::push_back(std::uint32_t line) {
    if (!runs_.empty()) {
        Run& last = runs_.back();
        // A run of one particle takes its step from the second: the same line (an NEND range) or the next.
        if (last.count == 1 && (line == last.line || line == last.line + 1)) {
            last.step = line - last.line, ++last.count, ++size_;
            return;
        }
        if (last.count > 1 && line == last.line + last.step * static_cast<std::uint32_t>(last.count)) {
            ++last.count, ++size_;
            return;
        }
    }
    runs_.push_back({size_, 1, line, 1});
    ++size_;
}

void ParticleLines::append_run(std::size_t count, std::uint32_t first_line, std::uint32_t step) {
    if (count == 0) return;
    if (!runs_.empty()) {  // continues the last run: one run stays one run
        Run& last = runs_.back();
        if (last.step == step && last.line + step * static_cast<std::uint32_t>(last.count) == first_line) {
            last.count += count, size_ += count;
            return;
        }
    }
    runs_.push_back({size_, count, first_line, step});
    size_ += count;
}

void ParticleLines::resize(std::size_t n) {
    if (n >= size_) return append_run(n - size_, 0, 0);
    while (!runs_.empty() && runs_.back().slot >= n) runs_.pop_back();
    if (!runs_.empty()) runs_.back().count = n - runs_.back().slot;
    size_ = n;
}

std::vector<std::uint32_t> ParticleLines::all() const {
    std::vector<std::uint32_t> out;
    out.reserve(size_);
    for (const Run& r : runs_)
        for (std::size_t k = 0; k < r.count; ++k) out.push_back(r.line + r.step * static_cast<std::uint32_t>(k));
    return out;
}

void ParticleLines::insert(std::size_t at, std::uint32_t line) {
    std::vector<std::uint32_t> lines = all();
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), line);
    clear();
    for (std::uint32_t l : lines) push_back(l);
}

void ParticleLines::erase(std::size_t at) {
    std::vector<std::uint32_t> lines = all();
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at));
    clear();
    for (std::uint32_t l : lines) push_back(l);
}

}  // namespace sphdeck::model
