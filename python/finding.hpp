// sphdeck.Finding: one finding of check(), with an attribute for every field of a diagnostic of
// `sphdeck check --format json` (docs/json.md), under the same names and with the same values.
#pragma once

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace sphdeck::python {

struct Finding {
    pybind11::dict fields;  // the diagnostic's JSON object as a dict
};

Finding finding_from_json(const nlohmann::json& diagnostic);

// Adds the class Finding to the module.
void bind_finding(pybind11::module_& module);

}  // namespace sphdeck::python
