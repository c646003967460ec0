#include "python/finding.hpp"

#include <string>

#include "python/json_to_python.hpp"

namespace sphdeck::python {
namespace py = pybind11;

namespace {
// The attributes, each a field of docs/json.md's diagnostic.
struct Attribute {
    const char* name;
    const char* doc;
};
constexpr Attribute kAttributes[] = {
    {"code", "rule code, e.g. 'SPH030' (sphdeck.rules() lists them)"},
    {"name", "the rule's name, e.g. 'iavis-solid-in-2d'; None for a code the registry does not know"},
    {"severity", "'error', 'warning' or 'info', after sphdeck.toml's [severity] overrides"},
    {"message", "what is wrong, naming the value found and what was expected"},
    {"file", "the file as the command line names it; None for a finding about the deck as a whole"},
    {"line", "1-based line; 0 when file is None"},
    {"column", "1-based column (bytes) where the finding's span starts; 0 when file is None"},
    {"end_column", "the column after the span's last character (exclusive); 0 when file is None"},
    {"notes", "secondary remarks: dicts of message, file, line, column, end_column"},
    {"fixes",
     "mends the finding offers: dicts of description, safe and edits (file, line, column, "
     "end_column, replacement)"},
    {"include_chain", "the files that include file, main deck first: dicts of file and line"},
    {"url", "the rule's section of docs/rules.md"},
};

std::string text_of(const py::handle& value) { return py::str(value).cast<std::string>(); }

// "deck.k:20:70: error: IAVIS 1 ... [SPH030]", as `sphdeck check --format concise` writes the finding.
std::string concise(const Finding& f) {
    const py::object file = f.fields["file"];
    const std::string where = file.is_none()
                                  ? "sphdeck"
                                  : text_of(file) + ":" + text_of(f.fields["line"]) + ":" + text_of(f.fields["column"]);
    return where + ": " + text_of(f.fields["severity"]) + ": " + text_of(f.fields["message"]) + " [" +
           text_of(f.fields["code"]) + "]";
}
}  // namespace

Finding finding_from_json(const nlohmann::json& diagnostic) {
    return Finding{py::reinterpret_steal<py::dict>(to_python(diagnostic).release())};
}

void bind_finding(py::module_& module) {
    py::class_<Finding> finding(module, "Finding",
                                "One finding of sphdeck.check(): the fields of a diagnostic of `sphdeck check "
                                "--format json`, as attributes.");
    for (const Attribute& a : kAttributes) {
        const std::string name = a.name;
        finding.def_property_readonly(
            a.name, [name](const Finding& f) { return py::object(f.fields[py::str(name)]); }, a.doc);
    }
    finding.def(
        "to_dict", [](const Finding& f) { return py::dict(f.fields.attr("copy")()); },
        "The finding as the dict of its JSON object (a copy).");
    finding.def("__str__", &concise);
    finding.def("__repr__", [](const Finding& f) { return "<Finding " + concise(f) + ">"; });
    finding.def("__eq__", [](const Finding& f, const py::object& other) {
        return py::isinstance<Finding>(other) && f.fields.equal(other.cast<const Finding&>().fields);
    });
    finding.attr("__hash__") = py::none();  // equal by value, mutable fields: not hashable, as a dict
}

}  // namespace sphdeck::python
