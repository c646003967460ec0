#include "cli/parse_error_message.hpp"

#include <fmt/format.h>
#include <cctype>
#include <regex>

namespace sphdeck::cli {

namespace {

// The subcommand the command line names (its first word that is one), or "" for the program itself.
std::string command_of(const CLI::App& app, int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i)
        for (const CLI::App* sub : app.get_subcommands({}))
            if (sub->get_name() == argv[i]) return sub->get_name();
    return {};
}

// A missing positional as a person says it: "decks" -> "no deck given".
std::string missing_argument(const std::string& name) {
    if (name == "decks" || name == "deck" || name == "before") return "no deck given";
    if (name == "after") return "no second deck given (diff compares two decks: BEFORE AFTER)";
    return fmt::format("no {} given", name);
}

// CLI11's wording of one error, rewritten; unknown wordings pass through.
std::string reworded(const std::string& what) {
    std::smatch m;
    if (what == "A subcommand is required") return "no command given";
    if (std::regex_match(what, m, std::regex(R"((\S+) is required)"))) {
        const std::string name = m[1];
        if (name.starts_with("-")) return fmt::format("{} is required", name);
        return missing_argument(name);
    }
    // "--threads: Value abc not in range 0.000000 to 1797...": CLI::NonNegativeNumber and CLI::Range.
    if (std::regex_match(what, m, std::regex(R"((\S+): Value (.*) not in range (\S+) to (\S+))"))) {
        const double low = std::stod(m[3]);
        const double high = std::stod(m[4]);
        if (high > 1e300) return fmt::format("{}: '{}' is not a number of at least {:g}", m[1].str(), m[2].str(), low);
        return fmt::format("{}: '{}' is not a number from {:g} to {:g}", m[1].str(), m[2].str(), low, high);
    }
    // "--format: xyz not in {full,concise,json}": CLI::IsMember.
    if (std::regex_match(what, m, std::regex(R"((\S+): (.*) not in \{(.*)\})"))) {
        std::string choices = m[3];
        for (std::size_t at = choices.find(','); at != std::string::npos; at = choices.find(',', at + 2))
            choices.replace(at, 1, ", ");
        return fmt::format("{}: '{}' is not one of {}", m[1].str(), m[2].str(), choices);
    }
    // "--jobs: Failed parsing x as a unsigned int" and the like.
    if (std::regex_match(what, m, std::regex(R"((\S+): Failed parsing (.*) as an? (.*))")))
        return fmt::format("{}: '{}' is not {}", m[1].str(), m[2].str(),
                           m[3].str().find("int") != std::string::npos ? "a whole number" : "a number");
    if (std::regex_match(what, m, std::regex(R"((\S+) excludes (\S+))")))
        return fmt::format("{} and {} cannot be given together", m[1].str(), m[2].str());
    std::string text = what;
    if (!text.empty() && std::isupper(static_cast<unsigned char>(text[0])) &&
        !std::isupper(static_cast<unsigned char>(text[1])))
        text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error, int argc, const char* const* argv) {
    const std::string command = command_of(app, argc, argv);
    const std::string program = command.empty() ? "sphdeck" : "sphdeck " + command;
    return fmt::format("{}: {}; try '{} --help'", program, reworded(error.what()), program);
}

}  // namespace sphdeck::cli
