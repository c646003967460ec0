// What the Python module asks of the engine, free of Python: each call takes plain values, runs the
// same engine functions as the command line and the MCP server, and answers in the JSON those write
// (docs/json.md), which module.cpp turns into Python objects. Safe to run without the GIL held.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphdeck::python {

// What makes `sphdeck` exit 2 (a deck that cannot be read, a bad sphdeck.toml, an unknown rule or
// keyword): raised in Python as sphdeck.Error with the message the command line prints.
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A deck named by a path, or given as text under a name (includes are found from the name's folder).
struct DeckSource {
    std::string path;                 // the file, or the name the text stands under
    std::optional<std::string> text;  // the deck's text, when not read from `path`
    std::string format;               // text only: "lsdyna" or "radioss"; empty: detected from the text
};

// Which sphdeck.toml applies: the nearest one (as `sphdeck check` finds it), a named file, or none.
struct ConfigChoice {
    enum class Kind { Search, File, None } kind = Kind::Search;
    std::string file;
};

struct CheckRequest {
    DeckSource deck;
    std::optional<std::vector<std::string>> select;  // replaces the config's list
    std::vector<std::string> ignore;                 // added to the config's list
    ConfigChoice config;
};

// The "diagnostics" array of `sphdeck check --format json` for the deck (a path named as an include
// file is checked as part of the decks around it that include it, as `sphdeck check` does).
nlohmann::json check(const CheckRequest& request);

// The deck's text with the safe fixes (and the unsafe ones too when `unsafe`) applied, as `sphdeck
// check --fix` writes it; `name` is the file the text stands for, in the working directory.
std::string fix(const std::string& text, const std::string& name, bool unsafe);

// The deck's text in the canonical column layout, as `sphdeck format` writes it.
std::string format(const std::string& text, const std::string& name);

// An LS-DYNA keyword's cards and fields, as the MCP tool keyword_layout gives them; `card_format`:
// "standard", "long" or "i10".
nlohmann::json keyword(const std::string& name, const std::string& card_format);

// The smoothing-length preview of the deck's SPH parts, one object per part (`sphdeck smooth --format json`).
nlohmann::json smooth(const DeckSource& deck, std::optional<int> ini);

// Every rule: code, name, severity, since, source, summary, fixable, url.
nlohmann::json rules();

}  // namespace sphdeck::python
