// The Python module `sphdeck` (README, "From Python"): check, fix, format, keyword,
// smooth and rules over the same engine as the command line. Arguments are read here, the work is
// done by calls.cpp with the GIL released, and the JSON it answers becomes Python objects.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/calls.hpp"
#include "python/finding.hpp"
#include "python/json_to_python.hpp"

namespace py = pybind11;

namespace sphdeck::python {
namespace {

// Runs `work` without the GIL (other Python threads run meanwhile); what the engine throws becomes
// a Failure, raised as sphdeck.Error.
template <class Work>
auto without_gil(Work&& work) {
    py::gil_scoped_release release;
    try {
        return work();
    } catch (const Failure&) {
        throw;
    } catch (const std::exception& e) {
        throw Failure(e.what());
    }
}

bool is_path_like(const py::handle& value) { return py::hasattr(value, "__fspath__"); }

std::string fspath(const py::handle& value) {
    return py::module_::import("os").attr("fspath")(value).cast<std::string>();
}

// A deck named by a path (str or os.PathLike) or given as text (a str holding a line break).
DeckSource deck_source(const py::object& path_or_text, const std::string& name, const py::object& format) {
    DeckSource deck;
    if (!format.is_none()) deck.format = format.cast<std::string>();
    if (py::isinstance<py::str>(path_or_text)) {
        std::string s = path_or_text.cast<std::string>();
        if (s.find('\n') != std::string::npos) {
            deck.text = std::move(s);
            deck.path = name;
            return deck;
        }
        deck.path = std::move(s);
        return deck;
    }
    if (!is_path_like(path_or_text)) throw py::type_error("expected a path (str or os.PathLike) or a deck's text");
    deck.path = fspath(path_or_text);
    return deck;
}

// None, "SPH,DK001" or ["SPH", "DK001"]: rule selectors, as --select takes them.
std::optional<std::vector<std::string>> selectors(const py::object& value) {
    if (value.is_none()) return std::nullopt;
    std::vector<std::string> out;
    if (py::isinstance<py::str>(value)) {
        std::string all = value.cast<std::string>();
        for (std::size_t start = 0; start <= all.size();) {
            std::size_t comma = all.find(',', start);
            if (comma == std::string::npos) comma = all.size();
            if (comma > start) out.push_back(all.substr(start, comma - start));
            start = comma + 1;
        }
        return out;
    }
    for (const py::handle& item : value) out.push_back(py::str(item).cast<std::string>());
    return out;
}

ConfigChoice config_choice(const py::object& value) {
    ConfigChoice choice;
    if (value.is_none() || (py::isinstance<py::bool_>(value) && value.cast<bool>())) return choice;
    if (py::isinstance<py::bool_>(value)) {
        choice.kind = ConfigChoice::Kind::None;
        return choice;
    }
    choice.kind = ConfigChoice::Kind::File;
    choice.file = fspath(value);
    return choice;
}

py::list check_deck(const py::object& path_or_text, const py::object& format, const py::object& select,
                    const py::object& ignore, const py::object& config, const std::string& name) {
    CheckRequest request;
    request.deck = deck_source(path_or_text, name, format);
    request.select = selectors(select);
    request.ignore = selectors(ignore).value_or(std::vector<std::string>{});
    request.config = config_choice(config);
    const nlohmann::json diagnostics = without_gil([&] { return python::check(request); });
    py::list out;
    for (const nlohmann::json& d : diagnostics) out.append(py::cast(finding_from_json(d)));
    return out;
}

py::list smooth_deck(const py::object& path_or_text, std::optional<int> ini, const std::string& name) {
    const DeckSource deck = deck_source(path_or_text, name, py::none());
    const nlohmann::json parts = without_gil([&] { return python::smooth(deck, ini); });
    return to_python(parts);
}

}  // namespace
}  // namespace sphdeck::python

PYBIND11_MODULE(sphdeck, m) {
    using namespace sphdeck::python;
    using namespace pybind11::literals;
    m.doc() =
        "sphdeck: checks, fixes, formats and previews LS-DYNA and OpenRadioss SPH decks (the engine of the "
        "sphdeck command line).";
    m.attr("__version__") = SPHDECK_VERSION;
    py::register_exception<Failure>(m, "Error").attr("__doc__") =
        "What makes the sphdeck command exit 2: a deck that cannot be read, a bad sphdeck.toml, an unknown rule "
        "or keyword. The message is the command line's.";
    bind_finding(m);

    m.def("check", &check_deck, "path_or_text"_a, py::kw_only(), "format"_a = py::none(), "select"_a = py::none(),
          "ignore"_a = py::none(), "config"_a = py::none(), "name"_a = "deck.k",
          "Checks a deck and returns its findings (list of Finding), as `sphdeck check --format json` reports "
          "them.\n\n"
          "path_or_text: a path (str or os.PathLike), or the deck's text (a str with a line break); a path "
          "named as an include file is checked as part of the decks around it that include it.\n"
          "format: for text, 'lsdyna' or 'radioss' (default: detected from the text).\n"
          "select, ignore: rule codes, names or prefixes ('SPH' or ['SPH030', 'DK001']), as --select and "
          "--ignore.\n"
          "config: None finds sphdeck.toml as the command line does; a path reads that file; False reads none.\n"
          "name: for text, the file it stands for (includes are found from its folder).\n"
          "Raises sphdeck.Error where `sphdeck check` exits 2.");
    m.def(
        "fix",
        [](const std::string& text, bool unsafe, const std::string& name) {
            return without_gil([&] { return fix(text, name, unsafe); });
        },
        "text"_a, "unsafe"_a = false, py::kw_only(), "name"_a = "deck.k",
        "The deck's text with the safe fixes its findings carry applied (the unsafe ones too with unsafe=True), "
        "as `sphdeck check --fix` mends a file. name: the file the text stands for, in the working directory.");
    m.def(
        "format",
        [](const std::string& text, const std::string& name) {
            return without_gil([&] { return format(text, name); });
        },
        "text"_a, py::kw_only(), "name"_a = "deck.k",
        "The deck's text with its cards in the canonical column layout, as `sphdeck format` writes it.");
    m.def(
        "keyword",
        [](const std::string& name, const std::string& card_format) {
            return to_python(without_gil([&] { return keyword(name, card_format); }));
        },
        "name"_a, py::kw_only(), "card_format"_a = "standard",
        "An LS-DYNA keyword's layout as a dict: its cards, each with its fields' columns, types, defaults and "
        "meaning. card_format: 'standard', 'long' or 'i10'.");
    m.def("smooth", &smooth_deck, "path_or_text"_a, py::kw_only(), "ini"_a = py::none(), "name"_a = "deck.k",
          "The smoothing-length preview of the deck's SPH parts: one dict per part, as `sphdeck smooth --format "
          "json` gives them. ini: the initial smoothing length mode to use instead of the deck's.");
    m.def(
        "rules", [] { return to_python(rules()); },
        "Every rule as a dict: code, name, severity, since, source, summary, fixable, url.");
}
