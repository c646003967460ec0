// Evaluator for the EXPRESSION field of *PARAMETER_EXPRESSION (format reference §14.3).
// The grammar itself lives in expression_grammar.hpp so that PEGTL stays out of this header.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace sphdeck::grammar {

enum class ExpressionError { None, Syntax, UndefinedParameter, Domain };

struct ExpressionResult {
    ExpressionError error = ExpressionError::None;
    double value = 0.0;
    std::string message;     // short lower-case fragment, e.g. "expected ')' after 'max(1,2'" or "undefined parameter
                             // 'tend'" or "division by zero"
    std::size_t offset = 0;  // byte offset in the input text where the problem is
    std::size_t length = 0;  // length of the offending token (>=1 when error)
    bool ok() const { return error == ExpressionError::None; }
};

// Looks a parameter up by name as written (without '&'); nullopt when undefined.
using ParameterLookup = std::function<std::optional<double>(std::string_view name)>;

// Evaluates `text` (numbers in Fortran forms, + - * / **, unary signs, parentheses, sin cos tan
// asin acos atan atan2 sqrt abs exp log log10 min max int nint, pi, &name and bare name).
// Never throws: every problem comes back as an ExpressionResult with its offset in `text`.
ExpressionResult evaluate_expression(std::string_view text, const ParameterLookup& lookup);

}  // namespace sphdeck::grammar
