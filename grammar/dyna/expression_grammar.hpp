// PEGTL grammar of *PARAMETER_EXPRESSION text and its error messages.
// Internal: included by expression.cpp and by the test that runs analyze<grammar>().
// Precedence, loosest first: + -, * /, unary + -, ** (right associative), primary.
// So -2**2 is -(2**2) and 2**-1 is 2**(-1), as in Fortran and pydyna.
#pragma once
#include <tao/pegtl.hpp>

namespace sphdeck::grammar::expression_peg {

using namespace tao::pegtl;

// Blanks between tokens; newlines too, in case a caller joins continuation lines with them.
struct ws : star<space> {};

// Identifier: a letter, then letters, digits or underscores.
struct name : seq<alpha, star<identifier_other>> {};

// Fortran numbers: 1  1.  .5  1e3  1.0D3  2.5d-4. No sign (unary minus is an operator) and no
// letter-less exponent (1.0+3 is an addition here).
struct digits : plus<digit> {};
struct mantissa : sor<seq<digits, opt<one<'.'>, star<digit>>>, seq<one<'.'>, digits>> {};
struct exponent_digits : digits {};
struct exponent : if_must<one<'e', 'E', 'd', 'D'>, opt<one<'+', '-'>>, exponent_digits> {};
struct number : seq<mantissa, opt<exponent>> {};

struct expression;
struct factor;

struct closing_paren : one<')'> {};
struct group : if_must<one<'('>, ws, expression, ws, closing_paren> {};

// A name followed by '(' is a call; the look-ahead keeps the function-name action from firing
// for a bare parameter name.
struct function_name : name {};
struct arguments : seq<expression, star<ws, one<','>, ws, must<expression>>> {};
struct call : if_must<at<name, ws, one<'('>>, function_name, ws, one<'('>, ws, arguments, ws, closing_paren> {};

struct parameter_name : name {};
struct reference : if_must<one<'&'>, parameter_name> {};  // &name
struct bare_name : name {};                               // pi or a parameter
struct primary : sor<group, call, number, reference, bare_name> {};

struct power_tail : if_must<two<'*'>, ws, factor> {};  // factor, not primary: right associative
struct power : seq<primary, opt<ws, power_tail>> {};
struct negate : if_must<one<'-'>, ws, factor> {};
struct unary_plus : if_must<one<'+'>, ws, factor> {};
struct factor : sor<negate, unary_plus, power> {};  // every recursion passes here: depth is counted here

struct multiply : if_must<one<'*'>, ws, factor> {};
struct divide : if_must<one<'/'>, ws, factor> {};
struct term : seq<factor, star<ws, sor<multiply, divide>>> {};

struct add : if_must<one<'+'>, ws, term> {};
struct subtract : if_must<one<'-'>, ws, term> {};
struct expression : seq<term, star<ws, sor<add, subtract>>> {};

struct not_empty : not_at<eof> {};
struct end_of_input : eof {};
struct grammar : seq<ws, must<not_empty, expression>, ws, must<end_of_input>> {};

// What was expected when a must<> fails; the control appends "after '<text before>'".
template <typename Rule>
inline constexpr const char* error_message = "syntax error";
template <>
inline constexpr const char* error_message<not_empty> = "empty expression";
template <>
inline constexpr const char* error_message<expression> = "expected expression";
template <>
inline constexpr const char* error_message<arguments> = "expected expression";
template <>
inline constexpr const char* error_message<term> = "expected expression";
template <>
inline constexpr const char* error_message<factor> = "expected expression";
template <>
inline constexpr const char* error_message<closing_paren> = "expected ')'";
template <>
inline constexpr const char* error_message<exponent_digits> = "expected exponent digits";
template <>
inline constexpr const char* error_message<parameter_name> = "expected parameter name";
template <>
inline constexpr const char* error_message<end_of_input> = "unexpected";  // + the token

// One token for error spans: a word or number (possibly after '&'), else a single byte.
struct token : sor<seq<opt<one<'&'>>, plus<sor<identifier_other, one<'.'>>>>, any> {};

}  // namespace sphdeck::grammar::expression_peg
