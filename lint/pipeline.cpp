#include "lint/pipeline.hpp"

#include "model/model_builder.hpp"

namespace sphdeck::lint {
namespace {
CheckResult finish(grammar::RawDeck deck, const CheckOptions& options) {
    CheckResult result;
    result.deck = std::move(deck);
    result.diagnostics = result.deck.diagnostics;
    result.model = model::build_model(result.deck, result.diagnostics, &result.summary);
    RuleContext context(result.model, result.deck, options.rules, result.diagnostics);
    run_rules(context);
    diag::sort_by_location(result.diagnostics);
    return result;
}
}  // namespace

CheckResult check_file(const std::string& path, const CheckOptions& options) {
    return finish(grammar::dyna::read_file(path, options.reader), options);
}

CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options) {
    return finish(grammar::dyna::read_buffer(std::move(text), name, ".", options.reader), options);
}

}  // namespace sphdeck::lint
