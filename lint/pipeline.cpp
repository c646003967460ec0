#include "lint/pipeline.hpp"

namespace sphdeck::lint {
namespace {
CheckResult finish(grammar::RawDeck deck) {
    CheckResult result;
    result.deck = std::move(deck);
    result.diagnostics = result.deck.diagnostics;
    result.summary = model::check_deck(result.deck, result.diagnostics);
    diag::sort_by_location(result.diagnostics);
    return result;
}
}  // namespace

CheckResult check_file(const std::string& path, const CheckOptions& options) {
    return finish(grammar::dyna::read_file(path, options.reader));
}

CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options) {
    return finish(grammar::dyna::read_buffer(std::move(text), name, ".", options.reader));
}

}  // namespace sphdeck::lint
