// A thread's ids of one column while they run first + step * k over consecutive lines of a bulk block (the
// parallel decoding, model/model_builder.cpp). A preprocessor's deck numbers its nodes 1..n and gives its
// particles the nodes 1..n and one part: three such runs, which the decoding keeps as two numbers each and
// never writes out an entry at a time (12 MB of a 1M-particle deck's memory not touched, issue 40; on the
// benchmarks' VM a MiB touched costs 1.3-2.7 ms). The first id that does not continue the run ends it.
#pragma once

#include <cstddef>

#include "model/id_column.hpp"

namespace sphdeck::model {

struct IdRun {
    std::size_t start = 0;  // the block line of its first id
    std::size_t count = 0;
    long long first = 0, step = 0;

    // Takes `id` of line `index` into the run when it continues it (true); false: it does not, and the run
    // is as it was. Only ids kept in 4 bytes: a run becomes a sequence column (IdColumn::assign_sequence).
    bool extend(std::size_t index, long long id) {
        if (!IdColumn::fits(id)) return false;
        if (count == 0) {
            start = index, first = id, count = 1;
            return true;
        }
        if (index != start + count) return false;  // a line between them gave no id
        if (count == 1)
            step = id - first;
        else if (id != at(count))
            return false;
        ++count;
        return true;
    }
    // Its k-th id (k <= count: the one after its last, to compare).
    long long at(std::size_t k) const { return first + step * static_cast<long long>(k); }
    std::size_t end() const { return start + count; }
};

}  // namespace sphdeck::model
