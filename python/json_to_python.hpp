// nlohmann::json as Python objects: objects as dicts, arrays as lists, numbers as int or float,
// null as None. Needs the GIL.
#pragma once

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace sphdeck::python {

pybind11::object to_python(const nlohmann::json& value);

}  // namespace sphdeck::python
