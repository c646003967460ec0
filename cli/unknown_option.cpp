#include "cli/unknown_option.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

#include "grammar/similar_names.hpp"

namespace sphdeck::cli {

namespace {

// Whether `token` ("--name", "--name=value", "-x", "-xVALUE") names an option of `app`.
bool known_option(const CLI::App& app, std::string_view token, std::vector<std::string>& spellings) {
    bool known = false;
    const bool long_form = token.starts_with("--");
    const std::string_view long_name = long_form ? token.substr(2, token.find('=') - 2) : std::string_view{};
    for (const CLI::Option* o : app.get_options()) {
        for (const std::string& l : o->get_lnames()) {
            spellings.push_back("--" + l);
            if (long_form && long_name == l) known = true;
        }
        for (const std::string& s : o->get_snames()) {
            spellings.push_back("-" + s);
            if (!long_form && token.substr(1, s.size()) == s) known = true;  // "-I", "-Idir"
        }
    }
    return known;
}

bool looks_like_option(std::string_view token) {
    if (token.size() < 2 || token[0] != '-' || token == "--") return false;
    // "-1.5" is a value, not an option.
    return !(std::isdigit(static_cast<unsigned char>(token[1])) || token[1] == '.');
}

}  // namespace

std::optional<std::string> unknown_option_message(const CLI::App& app, int argc, const char* const* argv) {
    // The subcommand: the first word of the command line that names one (CLI11 forgets what it
    // parsed when it throws).
    const CLI::App* parsed = &app;
    std::string command = "sphdeck";
    int first = 1;
    for (int i = 1; i < argc && parsed == &app; ++i)
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
            if (argv[i] == sub->get_name()) {
                parsed = sub;
                command += " " + sub->get_name();
                first = i + 1;
                break;
            }
    for (int i = first; i < argc; ++i) {
        const std::string_view token = argv[i];
        if (token == "--") break;  // everything after it is positional
        if (!looks_like_option(token)) continue;
        std::vector<std::string> spellings;
        if (known_option(*parsed, token, spellings)) continue;
        const std::string_view typed = token.substr(0, token.find('='));
        const auto close = grammar::closest_names(typed, spellings);
        std::string message = fmt::format("{}: unknown option {}", command, typed);
        if (!close.empty()) message += fmt::format("; did you mean {}?", close.front());
        message += fmt::format("\nrun '{} --help' for the options", command);
        return message;
    }
    return std::nullopt;
}

}  // namespace sphdeck::cli
