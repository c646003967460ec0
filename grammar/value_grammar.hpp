// PEGTL rules for one field's value. Shared by the LS-DYNA and Radioss readers.
#pragma once

#include <tao/pegtl.hpp>

namespace sphdeck::grammar::value_rules {

namespace pegtl = tao::pegtl;

struct blanks : pegtl::star<pegtl::one<' ', '\t'>> {};
struct sign : pegtl::one<'+', '-'> {};
struct digits : pegtl::plus<pegtl::digit> {};

struct integer : pegtl::seq<pegtl::opt<sign>, digits> {};

// Mantissa: 1.0  1.  .5  5
struct mantissa : pegtl::sor<pegtl::seq<digits, pegtl::opt<pegtl::one<'.'>, pegtl::star<pegtl::digit>>>,
                             pegtl::seq<pegtl::one<'.'>, digits>> {};
// Exponent with a letter (e, E, d, D) and optional sign, or a bare signed exponent (1.0+3).
struct lettered_exponent : pegtl::seq<pegtl::one<'e', 'E', 'd', 'D'>, pegtl::opt<sign>, digits> {};
struct bare_exponent : pegtl::seq<sign, digits> {};
struct exponent : pegtl::sor<lettered_exponent, bare_exponent> {};
struct real : pegtl::seq<pegtl::opt<sign>, mantissa, pegtl::opt<exponent>> {};

struct parameter_name : pegtl::plus<pegtl::sor<pegtl::alnum, pegtl::one<'_'>>> {};
struct negation : pegtl::one<'-'> {};
struct parameter_ref : pegtl::seq<pegtl::opt<negation>, pegtl::one<'&'>, parameter_name> {};

// The whole field: optional blanks, one value, optional blanks, end.
struct integer_field : pegtl::seq<blanks, integer, blanks, pegtl::eof> {};
struct real_field : pegtl::seq<blanks, real, blanks, pegtl::eof> {};
struct parameter_field : pegtl::seq<blanks, parameter_ref, blanks, pegtl::eof> {};

}  // namespace sphdeck::grammar::value_rules
