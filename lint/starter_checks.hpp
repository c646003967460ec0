// The OpenRadioss starter's own value checks as data (RAD040): per material law, EOS and property, the field, the
// condition under which the starter's reader stops with an error, the default it puts in place of a
// blank or 0 before testing, and the starter message id and text. Collected by hand from the
// readers' conditions (starter/source/materials/mat/*/hm_read_mat*.F, .F90, materials/eos/hm_read_eos_*.F,
// properties/*/hm_read_prop*.F) and the message texts
// (starter/source/output/message/starter_message_description.txt) of OpenRadioss, AGPL-3.0, at
// commit bd4557ba7503a277d3be5b50e1c64e8a12e0c53f: facts about the readers, not their code.
// The table in docs/radioss.md ("Starter value checks") lists the same rows; a test compares them.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "grammar/radioss/cards.hpp"

namespace sphdeck::lint::radioss {

// What the starter accepts. Each names the values that make it stop.
enum class Allowed : unsigned char {
    Positive,       // fires on v <= 0
    AboveMinusOne,  // fires on v <= -1
    NotZero,        // fires on v == 0
    ZeroToOne,      // fires on v < 0 or v > 1
    AtMostOne,      // fires on v > 1
    ZeroToHalf,     // fires on v < 0 or v >= 0.5
    AtMostHundred,  // fires on v > 100
    AboveOne,       // fires on v <= 1
    NotNegative,    // fires on v < 0
};

bool allowed(Allowed a, double value);
// "> 0", "> -1", "not 0", "between 0 and 1"...: what the message says is expected.
std::string_view expected(Allowed a);

struct StarterCheck {
    std::string_view field;  // the CFG field name in the layout ("MAT_SIGY")
    std::string_view label;  // as the deck's comment line names it ("a")
    Allowed allowed;
    // The value the reader puts in place of 0 (or a blank) before it tests; 0: none.
    double zero_means = 0.0;
    // The check runs only when this holds on the block's other fields ("MAT_SRC!0": c written
    // not 0), in the syntax of the generated layouts' conditions; empty: always.
    std::string_view when = {};
    int message = 0;          // the starter message id
    std::string_view text;    // its text (starter_message_description.txt)
    std::string_view source;  // reader file:line of the test, under reader_folder()
    // Another rule that already reports it ("SPH119" for the density): RAD040 leaves it to that one.
    std::string_view reported_by = {};
};

// One row of the table: the keywords (header prefixes, "/MAT/PLAS_JOHNS", "/EOS/MURNAGHAN", "/PROP/TYPE6")
// that one reader reads, and its checks. `layout` is the cards by format when sphdeck writes them here
// (LAW2: the generated layout cannot follow its CARD_PREREAD and Iflag branches; LAW51 and the EOS:
// their cards are in sub-object or shared CFG files the generator does not follow); empty: the
// generated layout of the first name is used.
struct StarterLaw {
    std::vector<std::string_view> names;
    std::string_view reader;  // "hm_read_mat02_jc.F90"
    std::vector<StarterCheck> checks;
    std::vector<grammar::radioss::FormatSpec> layout = {};
};

// The folder of OpenRadioss's starter/source/ that a row's sources are under, by its family:
// "materials/mat", "materials/eos", "properties".
std::string_view reader_folder(const StarterLaw& law);

// Every row (built once).
std::span<const StarterLaw> starter_laws();
// The row reading a header's law ("/MAT/LAW2/7" → LAW2's row), or nullptr.
const StarterLaw* starter_law_of(std::string_view header);

}  // namespace sphdeck::lint::radioss
