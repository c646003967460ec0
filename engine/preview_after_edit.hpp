// The geometry preview of the editor's re-check (engine/recheck.hpp): the last check's preview when
// the data it reads did not change (engine/preview_reuse.hpp), that preview followed locally when only
// particles moved, came or went (preproc/preview_follow.hpp: an edit inside *NODE or *ELEMENT_SPH),
// else a new one.
#pragma once

#include <memory>

#include "engine/check.hpp"
#include "model/model.hpp"
#include "preproc/preview.hpp"

namespace sphdeck::engine {

// The preview for `now`, re-checked after `previous` (whose kept preview it reads); `particle_arrays`
// as lint::compute_rules_preview. A new or followed preview keeps its neighbour counts, so that the
// next edit can be followed in its turn. `taken`: the columns `now` took from `previous`
// (engine/recheck.hpp); a preview is not followed from a model whose columns went.
std::shared_ptr<const preproc::Preview> preview_after_edit(const CheckResult& previous, const model::Model& now,
                                                           bool particle_arrays, const model::BulkTaken& taken = {});

}  // namespace sphdeck::engine
