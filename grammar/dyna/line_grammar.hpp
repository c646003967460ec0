// PEGTL grammar of an LS-DYNA keyword file, line by line (lsdyna-format.md §2, §15).
// It classifies each physical line; what a line means in its context (inside *COMMENT, after
// *END, inside an encrypted block) is decided by the reader's actions.
#pragma once

#include <tao/pegtl.hpp>

namespace sphdeck::grammar::dyna::rules {

namespace pegtl = tao::pegtl;

struct byte_order_mark : pegtl::string<'\xEF', '\xBB', '\xBF'> {};
struct rest_of_line : pegtl::star<pegtl::not_one<'\n'>> {};  // '\r' is stripped by the actions
struct inline_blank : pegtl::one<' ', '\t'> {};

// '$' in column 1.
struct comment_line : pegtl::seq<pegtl::one<'$'>, rest_of_line> {};

// '*' (blanks before it tolerated and reported), the name up to the first blank, an optional
// format suffix (+ long, - standard, % I10) glued or after blanks, then free arguments.
struct keyword_indent : pegtl::star<inline_blank> {};
struct keyword_name : pegtl::star<pegtl::sor<pegtl::alnum, pegtl::one<'_'>>> {};
struct suffix_char : pegtl::one<'+', '-', '%'> {};
struct suffix_end : pegtl::at<pegtl::sor<inline_blank, pegtl::one<'\r', '\n'>, pegtl::eof>> {};
struct keyword_suffix : pegtl::seq<pegtl::star<pegtl::one<' '>>, suffix_char, suffix_end> {};
struct keyword_arguments : rest_of_line {};
struct keyword_line
    : pegtl::seq<keyword_indent, pegtl::one<'*'>, keyword_name, pegtl::opt<keyword_suffix>, keyword_arguments> {};

// PGP-encrypted sections are kept opaque (lsdyna-format.md §15).
struct pgp_begin_line : pegtl::seq<TAO_PEGTL_STRING("-----BEGIN PGP"), rest_of_line> {};
struct pgp_end_line : pegtl::seq<TAO_PEGTL_STRING("-----END PGP"), rest_of_line> {};

struct data_line : pegtl::plus<pegtl::not_one<'\n'>> {};
struct empty_line : pegtl::one<'\n'> {};  // a blank data line: inside a keyword it is a card

// Every alternative consumes at least one byte, so the file loop always advances.
struct line_body : pegtl::sor<comment_line, keyword_line, pgp_begin_line, pgp_end_line, data_line> {};
struct line : pegtl::sor<empty_line, pegtl::seq<line_body, pegtl::opt<pegtl::one<'\n'>>>> {};
struct file : pegtl::seq<pegtl::opt<byte_order_mark>, pegtl::until<pegtl::eof, line>> {};

}  // namespace sphdeck::grammar::dyna::rules
