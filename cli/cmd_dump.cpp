// sphdeck dump DECK --format json: the decoded model, for scripts and for checking the reader
// (LS-DYNA: model/model_json.hpp; OpenRadioss: model/radioss_json.hpp).
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/deck_input.hpp"
#include "cli/dump_cards.hpp"
#include "engine/check.hpp"
#include "model/model_json.hpp"
#include "model/radioss_json.hpp"

namespace sphdeck::cli {
namespace {

struct DumpArgs {
    std::string deck;
    std::string stdin_filename;
    std::string format = "json";
    bool particles = false;
    bool cards = false;
    std::vector<std::string> include_paths;
};

// The dump; with --cards on one line (compact), the card lines appended as "card_files" and "cards".
void print(nlohmann::ordered_json& out, const grammar::RawDeck& deck, bool cards) {
    // Decks carry Latin-1 comments and titles: bytes that are not UTF-8 become U+FFFD, as in check.
    const auto replace = nlohmann::ordered_json::error_handler_t::replace;
    if (!cards) {
        fmt::print("{}\n", out.dump(2, ' ', false, replace));
        return;
    }
    out["card_files"] = card_files_json(deck);
    std::string text = out.dump(-1, ' ', false, replace);
    text.pop_back();  // the closing '}'
    fmt::print("{},\"cards\":{}}}\n", text, cards_json(deck));
}

int run_dump(const DumpArgs& args) {
    engine::CheckOptions options;
    options.reader.include_paths = args.include_paths;
    engine::CheckResult r = check_deck_input(args.deck, args.stdin_filename, options);
    if (grammar::format_of(r.deck) == grammar::DeckFormat::Radioss) {
        nlohmann::ordered_json out =
            model::radioss_to_json(model::read_radioss_records(r.deck), r.model, r.deck, args.particles);
        print(out, r.deck, args.cards);
        return exit_clean;
    }
    nlohmann::ordered_json out = model::to_json(r.model, r.deck, {args.particles});
    print(out, r.deck, args.cards);
    return exit_clean;
}

}  // namespace

std::function<int()> setup_dump(CLI::App& app) {
    auto args = std::make_shared<DumpArgs>();
    app.add_option("deck", args->deck, "LS-DYNA keyword deck or OpenRadioss starter deck, or - for standard input")
        ->required();
    app.add_option("--stdin-filename", args->stdin_filename, stdin_help);
    app.add_option("--format", args->format, "output format")->check(CLI::IsMember({"json"}))->capture_default_str();
    app.add_flag("--particles", args->particles, "list every particle (id, part, mass), not only counts");
    app.add_flag("--cards", args->cards,
                 "also list every card line read, each field's text and number (every known keyword); compact JSON");
    app.add_option("-I,--include-path", args->include_paths, "extra folder searched for *INCLUDE files");
    return [args] { return run_dump(*args); };
}

}  // namespace sphdeck::cli
