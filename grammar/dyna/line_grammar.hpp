// PEGTL grammar of an LS-DYNA keyword file, line by line (lsdyna-format.md §2, §15).
// It classifies each physical line; what a line means in its context (inside *COMMENT, after
// *END, inside an encrypted block) is decided by the reader's actions.
#pragma once

#include <cstring>
#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

namespace sphdeck::grammar::dyna::rules {

namespace pegtl = tao::pegtl;

struct byte_order_mark : pegtl::string<'\xEF', '\xBB', '\xBF'> {};

// Everything up to (not including) the next '\n', found with memchr: the reader's hot loop
// runs once per line of decks with millions of lines. Equivalent to star<not_one<'\n'>>.
struct rest_of_line {
    using rule_t = rest_of_line;
    using subs_t = pegtl::type_list<>;
    template <pegtl::apply_mode, pegtl::rewind_mode, template <typename...> class, template <typename...> class,
              typename Input, typename... States>
    static bool match(Input& in, States&&...) {
        const char* begin = in.current();
        const char* end = in.end();
        const void* newline = std::memchr(begin, '\n', static_cast<std::size_t>(end - begin));
        in.bump_in_this_line(static_cast<std::size_t>((newline ? static_cast<const char*>(newline) : end) - begin));
        return true;
    }
};
struct inline_blank : pegtl::one<' ', '\t'> {};

// '$' in column 1.
struct comment_line : pegtl::seq<pegtl::one<'$'>, rest_of_line> {};

// '*' (blanks before it tolerated and reported), the name up to the first blank, an optional
// format suffix (+ long, - standard, % I10) glued or after blanks, then free arguments.
// LS-DYNA names hold '-' and '/' between letters or digits (*CONSTRAINED_TIE-BREAK, *MAT_SAMP-1,
// *MAT_SIMPLIFIED_RUBBER/FOAM): there they join, while a '-' ending the name (`*NODE-`, `*NODE -`)
// stays the standard-format suffix.
struct keyword_indent : pegtl::star<inline_blank> {};
struct name_char : pegtl::sor<pegtl::alnum, pegtl::one<'_'>> {};
struct name_joiner : pegtl::seq<pegtl::one<'-', '/'>, pegtl::at<name_char>> {};
// May be empty (a bare '*'): the reader finds the '*' from where the name starts.
struct keyword_name : pegtl::opt<name_char, pegtl::star<pegtl::sor<name_char, name_joiner>>> {};
struct suffix_char : pegtl::one<'+', '-', '%'> {};
struct suffix_end : pegtl::at<pegtl::sor<inline_blank, pegtl::one<'\r', '\n'>, pegtl::eof>> {};
struct keyword_suffix : pegtl::seq<pegtl::star<pegtl::one<' '>>, suffix_char, suffix_end> {};
struct keyword_arguments : rest_of_line {};
struct keyword_line
    : pegtl::seq<keyword_indent, pegtl::one<'*'>, keyword_name, pegtl::opt<keyword_suffix>, keyword_arguments> {};

// PGP-encrypted sections are kept opaque (lsdyna-format.md §15).
struct pgp_begin_line : pegtl::seq<TAO_PEGTL_STRING("-----BEGIN PGP"), rest_of_line> {};
struct pgp_end_line : pegtl::seq<TAO_PEGTL_STRING("-----END PGP"), rest_of_line> {};

struct data_line : pegtl::seq<pegtl::not_one<'\n'>, rest_of_line> {};
struct empty_line : pegtl::one<'\n'> {};  // a blank data line: inside a keyword it is a card

// Every alternative consumes at least one byte, so the file loop always advances.
struct line_body : pegtl::sor<comment_line, keyword_line, pgp_begin_line, pgp_end_line, data_line> {};
struct line : pegtl::sor<empty_line, pegtl::seq<line_body, pegtl::opt<pegtl::one<'\n'>>>> {};
struct file : pegtl::seq<pegtl::opt<byte_order_mark>, pegtl::until<pegtl::eof, line>> {};

}  // namespace sphdeck::grammar::dyna::rules

// For pegtl::analyze: rest_of_line may succeed without consuming input, like an opt<>.
template <typename Name>
struct tao::pegtl::analyze_traits<Name, sphdeck::grammar::dyna::rules::rest_of_line>
    : tao::pegtl::analyze_opt_traits<> {};
