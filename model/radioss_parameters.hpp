// Radioss /PARAMETER (radioss-format.md §2: "values from /PARAMETER"). Global INTEGER and REAL
// parameters are read and substituted into the numeric cells of later blocks; other kinds
// (LOCAL scope, REAL_EXPR, INT_EXPR, TEXT) are recognised, reported once as not evaluated
// (DK001, info), and cells that use them stay unknown without a finding.
//
// Layout (OpenRadioss CFG radioss2017/PARAMETER/parameter_int.cfg, parameter_float.cfg):
//   /PARAMETER/GLOBAL/INTEGER/id     /PARAMETER/GLOBAL/REAL/id
//   title                            title
//   name (%-10s) value (%10d)        name (%-10s) value (%20lg)
//
// A cell refers to a parameter as `&name` or `-&name`, the symbol the OpenRadioss reader sets for
// Radioss decks (reader/source/cfgio/MODEL_IO/meci_syntax_infos.cpp, myparameterSymbol), or as
// `[name]` / `-[name]`: the reader's cell test (meci_data_reader.cpp, isParameterCell) also takes
// a two-character symbol with a closing character, and Altair's Radioss guides write `[name]`.
//
// Diagnostics: an undefined name, or one defined only by a later block (reader message 100106,
// "has to be defined before it is used"), DK012; a REAL parameter in an integer cell DK013; a
// second definition of a name DK014 (the starter's choice between them is not documented:
// sphdeck keeps the first, as LS-DYNA does by default).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::model {

// A reference written in a cell.
struct RadiossParameterReference {
    std::string_view name;
    bool negated = false;
    bool closed = true;  // false: `[name` without its ']' (cut by the cell width, reader message 100105)
};

// `&name`, `-&name`, `[name]` or `-[name]` (the token already trimmed); nullopt for anything else.
std::optional<RadiossParameterReference> radioss_parameter_reference(std::string_view token);

struct RadiossParameter {
    enum class Kind { Integer, Real, NotEvaluated };
    std::string name;
    Kind kind = Kind::NotEvaluated;
    double value = 0.0;
    std::size_t block = 0;  // index of the defining block in RawDeck::blocks
    grammar::Span span;     // the name (the header when the card is missing)
};

class RadiossParameters {
public:
    // Reads the starter deck's /PARAMETER blocks in order (values may use earlier parameters).
    // Reports DK001 (not evaluated), DK008 (no name), DK009 (extra lines), DK014 (redefinition)
    // and what the decoder finds in the value cells.
    void collect(const grammar::RawDeck& deck, int version, RadiossCardDecoder& decoder,
                 std::vector<diag::Diagnostic>& out);

    // The value of `ref` for a cell of block `block`, or nullopt when it has none. Reports
    // DK012 / DK013 at `span`; `field` names the cell in messages.
    std::optional<double> value_of(const RadiossParameterReference& ref, std::size_t block, bool integer_cell,
                                   std::string_view field, grammar::Span span,
                                   std::vector<diag::Diagnostic>& out) const;

    const std::vector<RadiossParameter>& definitions() const { return definitions_; }

private:
    const RadiossParameter* find(std::string_view name) const;
    void define(RadiossParameter p, std::vector<diag::Diagnostic>& out);

    std::vector<RadiossParameter> definitions_;             // first definition of each name, in reading order
    std::unordered_map<std::string, std::size_t> by_name_;  // into definitions_: cells look names up often
};

}  // namespace sphdeck::model
