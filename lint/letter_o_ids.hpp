// The letter O typed for the digit 0 in an id ("1O" for 10): LS-DYNA reads a label then, so the id names
// nothing or defines what nothing names. The digits it was meant to be, the words that say so and the
// unsafe fix that writes them, for the reference rules (REF003-REF005 at a definition, REF004 TMID, REF009).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "model/model.hpp"

namespace sphdeck::lint {

// The digits `value` was meant to be ("O" -> "0", "1O" -> "10"); nullopt when it has no O or other letters too.
std::optional<std::string> letter_o_digits(const std::string& value);

// The unsafe fix writing `digits` at `place`; nullopt without digits.
std::optional<diag::Fix> letter_o_fix(const std::optional<std::string>& digits, grammar::Span place);

// " (the letter O for the digit 0: 10 meant?)", or nothing without digits.
std::string letter_o_words(const std::optional<std::string>& digits);

// The definition among `definitions` (sections, materials, EOS) whose id is `named` with the letter O typed for
// a 0: the one a part naming `named` was written for.
template <typename Definition>
const Definition* letter_o_definition(const std::vector<Definition>& definitions, const model::Id& named) {
    for (const Definition& d : definitions)
        if (const std::optional<std::string> digits = letter_o_digits(d.id); digits && *digits == named) return &d;
    return nullptr;
}

}  // namespace sphdeck::lint
