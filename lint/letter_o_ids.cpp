#include "lint/letter_o_ids.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace sphdeck::lint {

std::optional<std::string> letter_o_digits(const std::string& value) {
    std::string digits = value;
    bool letter_o = false;
    for (char& ch : digits)
        if (ch == 'O' || ch == 'o') ch = '0', letter_o = true;
    if (!letter_o || !std::all_of(digits.begin(), digits.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
        return std::nullopt;
    return digits;
}

std::optional<diag::Fix> letter_o_fix(const std::optional<std::string>& digits, grammar::Span place) {
    if (!digits) return std::nullopt;
    return diag::Fix{fmt::format("write the digits {} (the letter O read as a label)", *digits),
                     false,
                     {{place, *digits}}};
}

std::string letter_o_words(const std::optional<std::string>& digits) {
    return digits ? fmt::format(" (the letter O for the digit 0: {} meant?)", *digits) : "";
}

}  // namespace sphdeck::lint
