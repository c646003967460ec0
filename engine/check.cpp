#include "engine/check.hpp"

#include "grammar/read_deck.hpp"
#include "preproc/preview.hpp"
#include "lint/fold_causes.hpp"
#include "lint/fragment_ids.hpp"
#include "lint/suppressions.hpp"
#include "lint/typo_consequences.hpp"
#include "model/model_builder.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::engine {
namespace {
CheckResult finish(grammar::RawDeck deck, const CheckOptions& options) {
    CheckResult result;
    result.deck = std::move(deck);
    result.diagnostics = result.deck.diagnostics;
    result.model = grammar::format_of(result.deck) == grammar::DeckFormat::Radioss
                       ? model::build_radioss_model(result.deck, result.diagnostics, &result.summary)
                       : model::build_model(result.deck, result.diagnostics, &result.summary);
    lint::RuleContext context(result.model, result.deck, options.rules, result.diagnostics);
    lint::run_rules(context);
    lint::point_to_misspelt_keywords(result.diagnostics);
    result.preview = std::move(context.preview);
    lint::fold_into_causes(result.deck, result.diagnostics);
    diag::sort_by_location(result.diagnostics);
    // What the deck's own comments and the configuration say about the findings: every consumer
    // (the CLI, the deck tests, an editor) sees the same list.
    lint::apply_suppressions(result.deck.sources, result.diagnostics, grammar::format_of(result.deck));
    lint::apply_rule_settings(options.config, result.diagnostics);
    // After the settings: an ignored REF003 is not counted; the summary obeys them in its turn.
    if (lint::is_include_fragment(result.deck)) {
        lint::summarize_fragment_ids(result.deck, result.diagnostics);
        lint::apply_rule_settings(options.config, result.diagnostics);
    }
    result.includes = include_graph(result.deck.sources);
    return result;
}
}  // namespace

CheckResult check_deck(const std::string& path, const Documents& documents, const CheckOptions& options) {
    CheckOptions with_documents = options;
    if (!documents.empty()) with_documents.reader.overlay = &documents;
    return finish(grammar::read_deck(path, with_documents.reader), with_documents);
}

CheckResult check_file(const std::string& path, const CheckOptions& options) {
    return finish(grammar::read_deck(path, options.reader), options);
}

CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options,
                         std::optional<grammar::DeckFormat> format, const std::string& base_directory) {
    return finish(grammar::read_deck_buffer(std::move(text), name, base_directory, options.reader, format), options);
}

}  // namespace sphdeck::engine
