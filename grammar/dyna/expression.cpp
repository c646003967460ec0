// Actions and driver for the *PARAMETER_EXPRESSION grammar (expression_grammar.hpp).
// Actions evaluate on the fly with a value stack: every operand keeps its byte span so that a
// domain error can point at the divisor or call that caused it.
#include "grammar/dyna/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "grammar/dyna/expression_grammar.hpp"

namespace sphdeck::grammar {
namespace {

namespace pegtl = tao::pegtl;
namespace peg = expression_peg;

// Real decks nest a handful of levels; the limit keeps hostile input from exhausting the stack.
constexpr std::size_t max_depth = 200;

// An evaluation problem found by an action; parse errors come as pegtl::parse_error instead.
struct Failure {
    ExpressionError error;
    std::string message;
    std::size_t offset;
    std::size_t length;
};

struct Operand {
    double value;
    std::size_t begin, end;  // byte span in the text
};

struct Function;

struct Call {
    const Function* function;
    std::size_t first_argument;  // index into the value stack
};

struct State {
    const char* text;  // start of the input, for spans
    const ParameterLookup& lookup;
    std::vector<Operand> values;
    std::vector<Call> calls;
    std::size_t depth = 0;

    template <typename ActionInput>
    std::size_t offset(const ActionInput& in) const {
        return std::size_t(in.begin() - text);
    }
    template <typename ActionInput>
    void push(double value, const ActionInput& in) {
        values.push_back({value, offset(in), std::size_t(in.end() - text)});
    }
    Operand pop() {
        Operand top = values.back();
        values.pop_back();
        return top;
    }
};

[[noreturn]] void fail(ExpressionError error, std::string message, std::size_t begin, std::size_t end) {
    throw Failure{error, std::move(message), begin, std::max<std::size_t>(end - begin, 1)};
}

bool iequals(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    });
}

// Bytes as they can be shown inside quotes: control and non-ASCII bytes as \xNN.
std::string printable(std::string_view text) {
    std::string out;
    for (const unsigned char c : text) {
        if (c >= 0x20 && c < 0x7f)
            out += char(c);
        else
            out += fmt::format("\\x{:02x}", c);
    }
    return out;
}

std::size_t token_length(std::string_view rest) {
    if (rest.empty()) return 1;  // at the end: point just past the text
    pegtl::memory_input in(rest.data(), rest.size(), "");
    (void)pegtl::parse<peg::token>(in);  // always matches: the last alternative is any byte
    return in.byte();
}

// --- functions -------------------------------------------------------------------------------

using Arguments = std::span<const double>;

struct Function {
    std::string_view name;
    std::size_t min_arguments, max_arguments;
    double (*apply)(Arguments);
};

constexpr std::size_t any_count = std::numeric_limits<std::size_t>::max();

const Function functions[] = {
    {"sin", 1, 1, [](Arguments a) { return std::sin(a[0]); }},
    {"cos", 1, 1, [](Arguments a) { return std::cos(a[0]); }},
    {"tan", 1, 1, [](Arguments a) { return std::tan(a[0]); }},
    {"asin", 1, 1, [](Arguments a) { return std::asin(a[0]); }},
    {"acos", 1, 1, [](Arguments a) { return std::acos(a[0]); }},
    {"atan", 1, 1, [](Arguments a) { return std::atan(a[0]); }},
    {"atan2", 2, 2, [](Arguments a) { return std::atan2(a[0], a[1]); }},
    {"sqrt", 1, 1, [](Arguments a) { return std::sqrt(a[0]); }},
    {"abs", 1, 1, [](Arguments a) { return std::abs(a[0]); }},
    {"exp", 1, 1, [](Arguments a) { return std::exp(a[0]); }},
    {"log", 1, 1, [](Arguments a) { return std::log(a[0]); }},
    {"log10", 1, 1, [](Arguments a) { return std::log10(a[0]); }},
    {"min", 2, any_count, [](Arguments a) { return *std::ranges::min_element(a); }},
    {"max", 2, any_count, [](Arguments a) { return *std::ranges::max_element(a); }},
    {"int", 1, 1, [](Arguments a) { return std::trunc(a[0]); }},   // Fortran INT: toward zero
    {"nint", 1, 1, [](Arguments a) { return std::round(a[0]); }},  // Fortran NINT: half away from zero
};

const Function* find_function(std::string_view name) {
    for (const Function& f : functions)
        if (iequals(f.name, name)) return &f;
    return nullptr;
}

// Why the arguments are outside the function's domain; empty when they are not.
std::string domain_problem(std::string_view function, Arguments a) {
    const double x = a[0];
    const bool is_log = function == "log" || function == "log10";
    if (function == "sqrt" && x < 0) return fmt::format("sqrt of negative value {}", x);
    if (is_log && x == 0) return fmt::format("{} of zero", function);
    if (is_log && x < 0) return fmt::format("{} of negative value {}", function, x);
    if ((function == "asin" || function == "acos") && std::abs(x) > 1)
        return fmt::format("{} of {} outside [-1, 1]", function, x);
    return {};
}

// --- actions ---------------------------------------------------------------------------------

template <typename Rule>
struct expression_action : pegtl::nothing<Rule> {};

template <>
struct expression_action<peg::factor> : pegtl::maybe_nothing {
    // Counts nesting around the whole factor match (like pegtl's limit_depth, with our message).
    template <typename Rule, pegtl::apply_mode A, pegtl::rewind_mode M, template <typename...> class Action,
              template <typename...> class Control, typename ParseInput>
    static bool match(ParseInput& in, State& st) {
        if (st.depth >= max_depth) {
            const std::size_t at = in.byte();
            fail(ExpressionError::Syntax, "expression nested too deeply", at, at + 1);
        }
        ++st.depth;
        const bool matched = pegtl::match<Rule, A, M, Action, Control>(in, st);
        --st.depth;
        return matched;
    }
};

template <>
struct expression_action<peg::number> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        std::string text = in.string();
        std::ranges::replace_if(
            text, [](char c) { return c == 'd' || c == 'D'; }, 'e');  // 1.0D3
        double value = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc::result_out_of_range) {
            // Numbers carry no sign, so a '-' is the exponent's: underflow reads as zero.
            if (text.find('-') == std::string::npos)
                fail(ExpressionError::Domain, fmt::format("number '{}' out of range", in.string()), st.offset(in),
                     st.offset(in) + in.size());
            value = 0.0;
        }
        st.push(value, in);
    }
};

template <typename ActionInput>
void push_parameter(const ActionInput& in, State& st, std::string_view name) {
    const std::optional<double> value = st.lookup ? st.lookup(name) : std::nullopt;
    if (!value)
        fail(ExpressionError::UndefinedParameter, fmt::format("undefined parameter '{}'", printable(name)),
             st.offset(in), st.offset(in) + in.size());
    st.push(*value, in);
}

template <>
struct expression_action<peg::reference> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        push_parameter(in, st, in.string_view().substr(1));  // without '&'
    }
};

template <>
struct expression_action<peg::bare_name> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        if (iequals(in.string_view(), "pi"))
            st.push(std::numbers::pi, in);
        else
            push_parameter(in, st, in.string_view());
    }
};

template <>
struct expression_action<peg::group> {
    // The value of "(...)" spans the parentheses, so errors about it underline all of it.
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        st.values.back().begin = st.offset(in);
        st.values.back().end = st.offset(in) + in.size();
    }
};

template <>
struct expression_action<peg::function_name> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        const Function* function = find_function(in.string_view());
        if (!function)
            fail(ExpressionError::Syntax, fmt::format("unknown function '{}'", printable(in.string_view())),
                 st.offset(in), st.offset(in) + in.size());
        st.calls.push_back({function, st.values.size()});
    }
};

template <>
struct expression_action<peg::call> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        const Call call = st.calls.back();
        st.calls.pop_back();
        const Function& f = *call.function;
        const std::size_t begin = st.offset(in), end = begin + in.size();
        const std::size_t count = st.values.size() - call.first_argument;
        if (count < f.min_arguments || count > f.max_arguments) {
            const std::string expected =
                f.max_arguments == any_count
                    ? fmt::format("at least {} arguments", f.min_arguments)
                    : fmt::format("{} argument{}", f.min_arguments, f.min_arguments == 1 ? "" : "s");
            fail(ExpressionError::Syntax, fmt::format("{} takes {}, got {}", f.name, expected, count), begin, end);
        }
        std::vector<double> arguments;
        for (std::size_t i = call.first_argument; i < st.values.size(); ++i) arguments.push_back(st.values[i].value);
        st.values.resize(call.first_argument);

        if (std::string problem = domain_problem(f.name, arguments); !problem.empty())
            fail(ExpressionError::Domain, std::move(problem), begin, end);
        const double value = f.apply(arguments);
        if (!std::isfinite(value))
            fail(ExpressionError::Domain, fmt::format("result of {} is not finite", f.name), begin, end);
        st.values.push_back({value, begin, end});
    }
};

template <>
struct expression_action<peg::negate> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        st.values.back().value = -st.values.back().value;
        st.values.back().begin = st.offset(in);
    }
};

template <>
struct expression_action<peg::unary_plus> {
    template <typename ActionInput>
    static void apply(const ActionInput& in, State& st) {
        st.values.back().begin = st.offset(in);
    }
};

// Pops two operands, applies `op`, pushes the result spanning both.
template <typename Op>
void binary(State& st, std::string_view symbol, Op op) {
    const Operand rhs = st.pop();
    const Operand lhs = st.pop();
    if (symbol == "/" && rhs.value == 0.0) fail(ExpressionError::Domain, "division by zero", rhs.begin, rhs.end);
    if (symbol == "**" && lhs.value < 0 && std::trunc(rhs.value) != rhs.value)
        fail(ExpressionError::Domain, fmt::format("negative base {} to non-integer power {}", lhs.value, rhs.value),
             lhs.begin, rhs.end);
    if (symbol == "**" && lhs.value == 0 && rhs.value < 0)
        fail(ExpressionError::Domain, "zero to a negative power", lhs.begin, rhs.end);
    const double value = op(lhs.value, rhs.value);
    if (!std::isfinite(value))
        fail(ExpressionError::Domain, fmt::format("result of '{}' is not finite", symbol), lhs.begin, rhs.end);
    st.values.push_back({value, lhs.begin, rhs.end});
}

template <>
struct expression_action<peg::power_tail> {
    static void apply0(State& st) {
        binary(st, "**", [](double a, double b) { return std::pow(a, b); });
    }
};
template <>
struct expression_action<peg::multiply> {
    static void apply0(State& st) { binary(st, "*", std::multiplies<>()); }
};
template <>
struct expression_action<peg::divide> {
    static void apply0(State& st) { binary(st, "/", std::divides<>()); }
};
template <>
struct expression_action<peg::add> {
    static void apply0(State& st) { binary(st, "+", std::plus<>()); }
};
template <>
struct expression_action<peg::subtract> {
    static void apply0(State& st) { binary(st, "-", std::minus<>()); }
};

// --- errors ----------------------------------------------------------------------------------

// Raises a must<> failure as "<what was expected> after '<text before the error>'".
template <typename Rule>
struct control : pegtl::normal<Rule> {
    template <typename ParseInput, typename... States>
    [[noreturn]] static void raise(const ParseInput& in, States&&... /*unused*/) {
        const std::string_view rest(in.current(), in.size());
        std::string message = peg::error_message<Rule>;
        if constexpr (std::is_same_v<Rule, peg::end_of_input>)
            message += fmt::format(" '{}'", printable(rest.substr(0, token_length(rest))));

        std::string_view before(in.begin(), std::size_t(in.current() - in.begin()));
        while (!before.empty() && std::isspace(static_cast<unsigned char>(before.back()))) before.remove_suffix(1);
        constexpr std::size_t shown = 24;  // enough to recognise the place, short enough for one line
        if (before.size() > shown)
            message += fmt::format(" after '...{}'", printable(before.substr(before.size() - shown)));
        else if (!before.empty())
            message += fmt::format(" after '{}'", printable(before));
        throw pegtl::parse_error(message, in);
    }
};

ExpressionResult failure(ExpressionError error, std::string message, std::size_t offset, std::size_t length) {
    ExpressionResult result;
    result.error = error;
    result.message = std::move(message);
    result.offset = offset;
    result.length = std::max<std::size_t>(length, 1);
    return result;
}

}  // namespace

ExpressionResult evaluate_expression(std::string_view text, const ParameterLookup& lookup) {
    State st{text.data(), lookup, {}, {}};
    pegtl::memory_input in(text.data(), text.size(), "expression");
    try {
        // The grammar either matches or raises; the check only guards against a grammar bug.
        if (!pegtl::parse<peg::grammar, expression_action, control>(in, st) || st.values.size() != 1)
            return failure(ExpressionError::Syntax, "syntax error", 0, text.size());
    } catch (const pegtl::parse_error& e) {
        const std::size_t offset = e.positions().empty() ? 0 : e.positions().front().byte;
        return failure(ExpressionError::Syntax, std::string(e.message()), offset, token_length(text.substr(offset)));
    } catch (const Failure& f) {
        return failure(f.error, f.message, f.offset, f.length);
    } catch (const std::exception& e) {  // from the caller's lookup, or out of memory
        return failure(ExpressionError::Syntax, fmt::format("evaluation failed: {}", e.what()), 0, text.size());
    }
    ExpressionResult result;
    result.value = st.values.back().value;
    if (!std::isfinite(result.value))  // a parameter that was not finite itself
        return failure(ExpressionError::Domain, "result is not finite", 0, text.size());
    return result;
}

}  // namespace sphdeck::grammar
