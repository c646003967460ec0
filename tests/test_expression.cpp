// Tests of the *PARAMETER_EXPRESSION evaluator (grammar/dyna/expression.*).
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/dyna/expression.hpp"
#include "grammar/dyna/expression_grammar.hpp"

namespace test_expression_cpp {  // each test file's names stay its own in a unity batch

using sphdeck::grammar::evaluate_expression;
using sphdeck::grammar::ExpressionError;
using sphdeck::grammar::ExpressionResult;
using sphdeck::grammar::ParameterLookup;

namespace {

// Case-sensitive on purpose: the evaluator must pass names exactly as written.
const ParameterLookup deck_parameters = [](std::string_view name) -> std::optional<double> {
    static const std::map<std::string, double, std::less<>> values{{"tend", 0.5}, {"Rho", 1000.0}, {"n_2", 2.0}};
    if (auto it = values.find(name); it != values.end()) return it->second;
    return std::nullopt;
};

double value_of(std::string_view text) {
    const ExpressionResult r = evaluate_expression(text, deck_parameters);
    INFO("text: ", std::string(text), "  message: ", r.message);
    CHECK(r.ok());
    return r.value;
}

ExpressionResult error_of(std::string_view text) {
    const ExpressionResult r = evaluate_expression(text, deck_parameters);
    INFO("text: ", std::string(text));
    CHECK_FALSE(r.ok());
    CHECK(r.length >= 1);
    return r;
}

}  // namespace

TEST_CASE("expression: grammar has no analyze issues") {
    CHECK(tao::pegtl::analyze<sphdeck::grammar::expression_peg::grammar>() == 0);
}

TEST_CASE("expression: precedence") {
    CHECK(value_of("1+2*3") == 7);
    CHECK(value_of("(1+2)*3") == 9);
    CHECK(value_of("2*3**2") == 18);
    CHECK(value_of("-2**2") == -4);  // ** binds tighter than unary minus
    CHECK(value_of("2**-1") == 0.5);
    CHECK(value_of("2*-3") == -6);
    CHECK(value_of("1 - -2") == 3);
    CHECK(value_of("+3") == 3);
    CHECK(value_of("-(2+3)*2") == -10);
    CHECK(value_of("6/2*3") == 9);
}

TEST_CASE("expression: associativity") {
    CHECK(value_of("10-4-3") == 3);
    CHECK(value_of("64/4/2") == 8);
    CHECK(value_of("2**3**2") == 512);  // right associative
    CHECK(value_of("(2**3)**2") == 64);
}

TEST_CASE("expression: blanks between tokens") {
    CHECK(value_of(" 1 +\t2 * ( 3 ) ") == 7);
    CHECK(value_of("max ( 1 , 2 )") == 2);
    CHECK(value_of("2 ** 3") == 8);
    CHECK(value_of("- 4") == -4);
}

TEST_CASE("expression: fortran number forms") {
    CHECK(value_of("1") == 1);
    CHECK(value_of("1.") == 1);
    CHECK(value_of(".5") == 0.5);
    CHECK(value_of("1e3") == 1000);
    CHECK(value_of("1E+2") == 100);
    CHECK(value_of("1.0D3") == 1000);
    CHECK(value_of("2.5d-4") == doctest::Approx(2.5e-4));
    CHECK(value_of("2.e1") == 20);
    CHECK(value_of("1.0+3") == 4);   // '+' is an operator here, not an exponent
    CHECK(value_of("1e-400") == 0);  // underflow reads as zero
}

TEST_CASE("expression: each function") {
    using std::numbers::pi;
    CHECK(value_of("sin(0)") == 0);
    CHECK(value_of("sin(pi/2)") == doctest::Approx(1));
    CHECK(value_of("cos(0)") == 1);
    CHECK(value_of("tan(pi/4)") == doctest::Approx(1));
    CHECK(value_of("asin(1)") == doctest::Approx(pi / 2));
    CHECK(value_of("acos(1)") == 0);
    CHECK(value_of("atan(1)") == doctest::Approx(pi / 4));
    CHECK(value_of("atan2(1, -1)") == doctest::Approx(3 * pi / 4));
    CHECK(value_of("sqrt(16)") == 4);
    CHECK(value_of("abs(-3)") == 3);
    CHECK(value_of("exp(0)") == 1);
    CHECK(value_of("log(exp(2))") == doctest::Approx(2));
    CHECK(value_of("log10(1000)") == doctest::Approx(3));
    CHECK(value_of("min(3, 1, 2)") == 1);
    CHECK(value_of("max(1, 5, 2)") == 5);
    CHECK(value_of("min(4,3)") == 3);
    CHECK(value_of("int(2.7)") == 2);
    CHECK(value_of("int(-2.7)") == -2);  // toward zero
    CHECK(value_of("nint(2.5)") == 3);
    CHECK(value_of("nint(-2.5)") == -3);  // half away from zero
    CHECK(value_of("nint(2.4)") == 2);
    CHECK(value_of("SIN(0) + Cos(0) + MAX(1,2)") == 3);  // case-insensitive
    CHECK(value_of("max(min(1,2), sqrt(abs(-9)))") == 3);
}

TEST_CASE("expression: pi") {
    CHECK(value_of("pi") == std::numbers::pi);
    CHECK(value_of("PI") == std::numbers::pi);
    CHECK(value_of("2*Pi") == 2 * std::numbers::pi);
}

TEST_CASE("expression: parameter references") {
    CHECK(value_of("&tend") == 0.5);
    CHECK(value_of("tend") == 0.5);
    CHECK(value_of("-&tend") == -0.5);
    CHECK(value_of("&Rho * 2 + n_2") == 2002);
    CHECK(value_of("max(&tend, tend*3)") == 1.5);

    std::vector<std::string> asked;
    const ParameterLookup recording = [&](std::string_view name) -> std::optional<double> {
        asked.emplace_back(name);
        return 1.0;
    };
    CHECK(evaluate_expression("&TEnd + rho_1", recording).value == 2);
    CHECK(asked == std::vector<std::string>{"TEnd", "rho_1"});  // as written, without '&'
}

TEST_CASE("expression: undefined parameter") {
    ExpressionResult r = error_of("1 + &tend2");
    CHECK(r.error == ExpressionError::UndefinedParameter);
    CHECK(r.message == "undefined parameter 'tend2'");
    CHECK(r.offset == 4);
    CHECK(r.length == 6);

    r = error_of("2*RHO");  // the lookup is case-sensitive; the evaluator does not fold case
    CHECK(r.error == ExpressionError::UndefinedParameter);
    CHECK(r.offset == 2);
    CHECK(r.length == 3);

    r = evaluate_expression("&x", ParameterLookup{});  // no lookup at all
    CHECK(r.error == ExpressionError::UndefinedParameter);
}

TEST_CASE("expression: syntax errors with offsets") {
    ExpressionResult r = error_of("max(1,2");
    CHECK(r.error == ExpressionError::Syntax);
    CHECK(r.message == "expected ')' after 'max(1,2'");
    CHECK(r.offset == 7);
    CHECK(r.length == 1);

    r = error_of("");
    CHECK(r.message == "empty expression");
    CHECK(r.offset == 0);
    r = error_of("   ");
    CHECK(r.message == "empty expression");

    r = error_of("1 + ");
    CHECK(r.message == "expected expression after '1 +'");
    CHECK(r.offset == 4);

    r = error_of("1 2");
    CHECK(r.message == "unexpected '2' after '1'");
    CHECK(r.offset == 2);

    r = error_of("1 + 2 abc");  // trailing garbage
    CHECK(r.message == "unexpected 'abc' after '1 + 2'");
    CHECK(r.offset == 6);
    CHECK(r.length == 3);

    r = error_of("foo(1)");
    CHECK(r.error == ExpressionError::Syntax);
    CHECK(r.message == "unknown function 'foo'");
    CHECK(r.offset == 0);
    CHECK(r.length == 3);

    r = error_of("2 * (3 + 4");
    CHECK(r.message == "expected ')' after '2 * (3 + 4'");
    CHECK(r.offset == 10);

    r = error_of("1e+");
    CHECK(r.message == "expected exponent digits after '1e+'");
    CHECK(r.offset == 3);

    r = error_of("& tend");
    CHECK(r.message == "expected parameter name after '&'");
    CHECK(r.offset == 1);

    r = error_of("sin()");
    CHECK(r.message == "expected expression after 'sin('");
    CHECK(r.offset == 4);

    r = error_of("*3");
    CHECK(r.message == "expected expression");
    CHECK(r.offset == 0);

    r = error_of("2 *** 3");
    CHECK(r.offset == 4);

    r = error_of("atan2(1)");
    CHECK(r.message == "atan2 takes 2 arguments, got 1");
    CHECK(r.offset == 0);
    CHECK(r.length == 8);

    r = error_of("min(1)");
    CHECK(r.message == "min takes at least 2 arguments, got 1");

    r = error_of("sqrt(1, 2)");
    CHECK(r.message == "sqrt takes 1 argument, got 2");

    // A long prefix is shortened in the message.
    r = error_of("1 + 2 + 3 + 4 + 5 + 6 + 7 + 8 + 9 +");
    CHECK(r.message == "expected expression after '... 4 + 5 + 6 + 7 + 8 + 9 +'");
}

TEST_CASE("expression: domain errors with offsets") {
    ExpressionResult r = error_of("1/0");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(r.message == "division by zero");
    CHECK(r.offset == 2);
    CHECK(r.length == 1);

    r = error_of("1 / (2 - 2)");  // points at the whole divisor
    CHECK(r.message == "division by zero");
    CHECK(r.offset == 4);
    CHECK(r.length == 7);

    r = error_of("1 + sqrt(-1)");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(r.message == "sqrt of negative value -1");
    CHECK(r.offset == 4);
    CHECK(r.length == 8);

    r = error_of("log(0)");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(r.message == "log of zero");
    r = error_of("log10(-2)");
    CHECK(r.message == "log10 of negative value -2");
    r = error_of("asin(2)");
    CHECK(r.error == ExpressionError::Domain);

    r = error_of("2 * exp(1000)");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(r.message == "result of exp is not finite");
    CHECK(r.offset == 4);

    r = error_of("1e300 * 1e300");
    CHECK(r.message == "result of '*' is not finite");
    CHECK(r.offset == 0);
    CHECK(r.length == 13);

    r = error_of("1 + 1e400");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(r.message == "number '1e400' out of range");
    CHECK(r.offset == 4);
    CHECK(r.length == 5);

    r = error_of("(-8)**0.5");
    CHECK(r.error == ExpressionError::Domain);
    r = error_of("0**-1");
    CHECK(r.error == ExpressionError::Domain);
    CHECK(value_of("(-2)**3") == -8);  // integer powers of negative numbers are fine
}

TEST_CASE("expression: deep nesting") {
    CHECK(value_of(std::string(100, '(') + "1" + std::string(100, ')')) == 1);

    for (const std::string& text :
         {std::string(10000, '(') + "1" + std::string(10000, ')'), std::string(10000, '(') + "1",  // unbalanced too
          std::string(10000, '-') + "1",  // unary chains recurse as well
          [] {
              std::string s = "2";
              for (int i = 0; i < 10000; ++i) s += "**2";
              return s;
          }()}) {
        const ExpressionResult r = error_of(text);
        CHECK(r.error == ExpressionError::Syntax);
        CHECK(r.message == "expression nested too deeply");
    }
}

TEST_CASE("expression: garbage bytes including nul") {
    ExpressionResult r = error_of(std::string("1+\0", 3));
    CHECK(r.error == ExpressionError::Syntax);
    CHECK(r.message == "expected expression after '1+'");
    CHECK(r.offset == 2);
    CHECK(r.length == 1);

    r = error_of(std::string("1\0", 2));
    CHECK(r.message == "unexpected '\\x00' after '1'");
    CHECK(r.offset == 1);

    r = error_of("\xff\xfe");
    CHECK(r.error == ExpressionError::Syntax);
    CHECK(r.offset == 0);

    // Random bytes from the expression alphabet and beyond: never throws, every error has a span
    // inside (or just past) the text.
    const std::string alphabet = std::string("0123456789.+-*/()&, eEdDpisnqrtmaxlog_\t", 39) + '\0' + "\xff$";
    std::mt19937 random(12345);
    std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1), length(0, 24);
    for (int i = 0; i < 5000; ++i) {
        std::string text(length(random), ' ');
        for (char& c : text) c = alphabet[pick(random)];
        const ExpressionResult result = evaluate_expression(text, deck_parameters);
        if (!result.ok()) {
            INFO("text: ", text);
            CHECK(result.length >= 1);
            CHECK(result.offset <= text.size());
            CHECK(!result.message.empty());
        }
    }
}
}  // namespace test_expression_cpp
