// The smoothing-length preview as JSON (docs/json.md): what `sphdeck smooth --format json` prints per part
// and per Radioss deck, and what the MCP tool smoothing_preview returns.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "preproc/preview.hpp"

namespace sphdeck::preproc {

// "a; b" -> {"a", "b"}: a part's notes one by one.
std::vector<std::string> split_notes(const std::string& notes);

nlohmann::ordered_json part_preview_json(const PartPreview& part);
nlohmann::ordered_json radioss_preview_json(const RadiossPreview& radioss);

}  // namespace sphdeck::preproc
