// PEGTL grammar of a Radioss Block format deck, line by line (radioss-format.md §2).
// It classifies each physical line; what a line means in its context (after /END, after
// #enddata, before any header) is decided by the reader's actions.
#pragma once

#include <tao/pegtl.hpp>

#include "grammar/dyna/line_grammar.hpp"  // rest_of_line (memchr), byte_order_mark

namespace sphdeck::grammar::radioss::rules {

namespace pegtl = tao::pegtl;
using dyna::rules::byte_order_mark;
using dyna::rules::rest_of_line;

struct inline_blank : pegtl::one<' ', '\t'> {};

// `#include <file>`: the name is the rest of the line (trimmed by the reader).
struct include_name : rest_of_line {};
struct include_line
    : pegtl::seq<pegtl::one<'#'>, TAO_PEGTL_ISTRING("include"), pegtl::plus<inline_blank>, include_name> {};
// `#enddata`: the end of an included file.
struct enddata_line : pegtl::seq<pegtl::one<'#'>, TAO_PEGTL_ISTRING("enddata"), rest_of_line> {};
// '#' or '$' in column 1 (an indented '#' is data). `#RADIOSS STARTER` is a comment too; the
// reader checks that it is the first line.
struct comment_line : pegtl::seq<pegtl::one<'#', '$'>, rest_of_line> {};

// A header: '/' in column 1, then the path /KEY1/KEY2/.../id up to the end of the line. Blanks
// before the '/' are tolerated and reported.
struct header_indent : pegtl::star<inline_blank> {};
struct header_path : pegtl::seq<pegtl::one<'/'>, rest_of_line> {};
struct header_line
    : pegtl::seq<header_indent, pegtl::at<pegtl::one<'/'>, pegtl::sor<pegtl::alpha, pegtl::one<'/'>>>, header_path> {};

struct data_line : pegtl::seq<pegtl::not_one<'\n'>, rest_of_line> {};
struct empty_line : pegtl::one<'\n'> {};

// Every alternative consumes at least one byte, so the file loop always advances.
struct line_body : pegtl::sor<include_line, enddata_line, comment_line, header_line, data_line> {};
struct line : pegtl::sor<empty_line, pegtl::seq<line_body, pegtl::opt<pegtl::one<'\n'>>>> {};
struct file : pegtl::seq<pegtl::opt<byte_order_mark>, pegtl::until<pegtl::eof, line>> {};

}  // namespace sphdeck::grammar::radioss::rules
