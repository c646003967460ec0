#include "grammar/dyna/keyword_arguments.hpp"

#include <charconv>
#include <tao/pegtl.hpp>

#include "grammar/parameters.hpp"

namespace sphdeck::grammar::dyna {
namespace {

namespace pegtl = tao::pegtl;

struct blank : pegtl::one<' ', '\t', ',', '\r'> {};
struct argument_name : pegtl::plus<pegtl::sor<pegtl::alnum, pegtl::one<'_'>>> {};
struct value : pegtl::plus<pegtl::not_one<' ', '\t', ',', '\r', '='>> {};
struct named : pegtl::seq<argument_name, pegtl::star<pegtl::one<' '>>, pegtl::one<'='>, pegtl::star<pegtl::one<' '>>,
                          pegtl::opt<value>> {};
struct bare : value {};
struct argument : pegtl::sor<named, bare> {};
struct argument_list : pegtl::seq<pegtl::star<blank>, pegtl::star<argument, pegtl::star<blank>>> {};

struct Collector {
    KeywordArguments& out;
    std::string_view pending_name;
    std::string_view pending_value;
    bool first = true;
};

template <typename Rule>
struct argument_action : pegtl::nothing<Rule> {};

template <>
struct argument_action<argument_name> {
    template <typename Input>
    static void apply(const Input& in, Collector& c) {
        c.pending_name = in.string_view();
        c.pending_value = {};
    }
};
template <>
struct argument_action<value> {
    template <typename Input>
    static void apply(const Input& in, Collector& c) {
        c.pending_value = in.string_view();
    }
};

bool is_yes(std::string_view v) { return !v.empty() && (v[0] == 'y' || v[0] == 'Y'); }

template <>
struct argument_action<named> {
    template <typename Input>
    static void apply(const Input&, Collector& c) {
        std::string key = to_upper(c.pending_name);
        std::string_view v = c.pending_value;
        if (key == "MEMORY")
            c.out.memory = std::string(v);
        else if (key == "MEMORY2")
            c.out.memory2 = std::string(v);
        else if (key == "LONG")
            c.out.long_format = is_yes(v);  // LONG=S and LONG=K read standard input
        else if (key == "I10")
            c.out.i10_format = is_yes(v);
        else if (key == "NCPU")
            std::from_chars(v.data(), v.data() + v.size(), c.out.ncpu);
        c.first = false;
    }
};
template <>
struct argument_action<bare> {
    template <typename Input>
    static void apply(const Input& in, Collector& c) {
        if (c.first) c.out.memory = in.string();
        c.first = false;
    }
};

}  // namespace

KeywordArguments parse_keyword_arguments(std::string_view text) {
    KeywordArguments out;
    out.present = true;
    Collector collector{out, {}, {}, true};
    pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(text.data(),
                                                                                         text.data() + text.size(),
                                                                                         "*KEYWORD");
    pegtl::parse<argument_list, argument_action>(in, collector);
    return out;
}

}  // namespace sphdeck::grammar::dyna
