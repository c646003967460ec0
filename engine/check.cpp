#include "engine/check.hpp"

#include <functional>
#include <optional>

#include <omp.h>

#include "engine/mended_consequences.hpp"
#include "engine/preview_after_edit.hpp"
#include "engine/recheck.hpp"
#include "engine/shared_preview.hpp"
#include "grammar/deck_splice.hpp"
#include "grammar/read_deck.hpp"
#include "preproc/preview.hpp"
#include "lint/fold_causes.hpp"
#include "lint/fragment_ids.hpp"
#include "lint/rules.hpp"
#include "lint/suppressions.hpp"
#include "lint/typo_consequences.hpp"
#include "model/model_builder.hpp"
#include "model/radioss_decoder.hpp"
#include "text/big_file_heap.hpp"

namespace sphdeck::engine {
namespace {
// The LS-DYNA model of `result.deck`; a re-check copies the bulk blocks the edit left alone, and every
// check notes those the next may copy.
// `share`: the run's shared bulk blocks (null: none); `provenance` receives those the model was made of.
// `take_from`: `previous` itself when its owner drops it after this check (its whole columns are then
// moved, `taken` says which).
// `documents`: the texts held in memory that the check reads (null: none).
model::Model build_dyna_model(CheckResult& result, const CheckResult* previous, const grammar::SplicedLines* changed,
                              RunShare* share, model::BulkProvenance& provenance, CheckResult* take_from,
                              model::BulkTaken& taken, const grammar::FileOverlay* documents) {
    std::optional<model::BulkReuse> reuse;
    if (previous)
        reuse.emplace(model::BulkReuse{previous->deck, previous->model, previous->bulk_blocks, changed,
                                       take_from ? &take_from->model : nullptr, take_from ? &taken : nullptr,
                                       documents});
    return model::build_model(result.deck, result.diagnostics, &result.summary, reuse ? &*reuse : nullptr,
                              result.bulk_blocks, share ? &share->bulk : nullptr, &provenance);
}

// read → model → rules, the findings of each line's cause folded into it.
// `previous`: the last check of the same deck (a re-check), or null; `changed`: where the deck was
// spliced into the last one's reading (grammar/deck_splice.hpp), or null.
// `take_from`: as build_dyna_model's. `documents`: the editor's texts `previous` was read from, when
// not options.reader.overlay (a re-check of mended files lays them over those).
CheckResult analyse(grammar::RawDeck deck, const CheckOptions& options, const CheckResult* previous,
                    const grammar::SplicedLines* changed = nullptr, CheckResult* take_from = nullptr,
                    const grammar::FileOverlay* documents = nullptr) {
    if (!documents) documents = options.reader.overlay;
    CheckResult result;
    result.deck = std::move(deck);
    result.diagnostics = result.deck.diagnostics;
    model::BulkProvenance provenance;
    model::BulkTaken taken;
    result.model =
        grammar::format_of(result.deck) == grammar::DeckFormat::Radioss
            ? model::build_radioss_model(result.deck, result.diagnostics, &result.summary)
            : build_dyna_model(result, previous, changed, options.share, provenance, take_from, taken, documents);
    if (take_from && taken.any()) take_from->taken = taken;
    text::give_back_free_heap();  // the reading's freed scratch, before the rules' searches (big decks only)
    lint::RuleContext context(result.model, result.deck, options.rules, result.diagnostics);
    if (options.share) context.use_bulk_facts(options.share->lookups.facts(result.model, provenance));
    if (options.share) context.use_lookups(options.share->lookups.find(result.model, provenance));
    result.rule_findings.kept = options.rules.keep_preview;
    result.rule_findings.options = options.rules;
    // A spliced re-check runs only the rule families whose inputs the edit changed.
    const CheckResult* reusable = changed ? previous : nullptr;
    if (previous && previous->preview) {
        const bool arrays = options.rules.preview_arrays;
        run_rules_reusing(
            context,
            [previous, arrays, &taken](const model::Model& model) {
                return preview_after_edit(*previous, model, arrays, taken);  // kept, followed or new
            },
            result.diagnostics, result.rule_findings, reusable, changed);
    } else if (options.share) {
        // The preview another deck of the run computed from the same inputs (engine/shared_preview.hpp).
        const bool arrays = options.rules.preview_arrays, counts = options.rules.keep_preview;
        lint::run_rules(context, [&](const model::Model& model) {
            return options.share->previews.preview(model, provenance, arrays, counts, [&](const model::Model& m) {
                return lint::compute_rules_preview(m, arrays, counts);
            });
        });
    } else {
        const bool arrays = options.rules.preview_arrays, counts = options.rules.keep_preview;
        run_rules_reusing(
            context,
            [arrays, counts](const model::Model& model) { return lint::compute_rules_preview(model, arrays, counts); },
            result.diagnostics, result.rule_findings, reusable, changed);
    }
    if (options.rules.keep_preview) result.rule_lookups = context.lookups();
    if (options.share) options.share->lookups.keep(result.model, provenance, context.lookups());
    lint::point_to_misspelt_keywords(result.diagnostics);
    result.preview = std::move(context.preview);
    lint::fold_into_causes(result.deck, result.diagnostics);
    return result;
}

bool is_bulk_keyword(const std::string& keyword) {
    return keyword.rfind("*NODE", 0) == 0 || keyword.rfind("*ELEMENT_SPH", 0) == 0;
}

// A spliced re-check on the calling thread alone: it decodes only the lines around an edit, and
// between its short parallel regions OpenMP's idle workers spin (libgomp's default wait policy), which
// on a busy 2-core machine cost more than the threads gained: a *NODE edit of a 1M-particle deck
// took 178 ms CPU on two threads and 110 on one, less wall time too (bench/bench_incremental.cpp).
class OneThreadForSplicedRecheck {
public:
    OneThreadForSplicedRecheck() : saved_(omp_get_max_threads()) { omp_set_num_threads(1); }
    ~OneThreadForSplicedRecheck() { omp_set_num_threads(saved_); }
    OneThreadForSplicedRecheck(const OneThreadForSplicedRecheck&) = delete;
    OneThreadForSplicedRecheck& operator=(const OneThreadForSplicedRecheck&) = delete;

private:
    int saved_;
};

// `reread` reads the deck again with mended files laid over it (engine/mended_consequences.hpp).
// `original`: the deck as first read (a buffer's text is its first file).
using Reread = std::function<grammar::RawDeck(const grammar::dyna::ReaderOptions&, const grammar::RawDeck& original)>;

CheckResult finish(grammar::RawDeck deck, const CheckOptions& options, const Reread& reread,
                   const CheckResult* previous = nullptr, const grammar::SplicedLines* changed = nullptr,
                   CheckResult* take_from = nullptr) {
    CheckResult result = analyse(std::move(deck), options, previous, changed, take_from);
    fold_mended_consequences(result.deck, result.diagnostics, options.reader.overlay,
                             [&](const grammar::FileOverlay& mended) {
                                 CheckOptions again = options;
                                 again.reader.overlay = &mended;
                                 again.rules.keep_preview = false;
                                 return analyse(reread(again.reader, result.deck), again, previous, nullptr, nullptr,
                                                options.reader.overlay)
                                     .diagnostics;
                             });
    diag::sort_by_location(result.diagnostics);
    // What the deck's own comments and the configuration say about the findings: every consumer
    // (the CLI, the deck tests, an editor) sees the same list.
    // A spliced main file holds a directive only if its old text or its new lines do (a directive
    // lies on one line): no pass over a 100 MB text to find none.
    if (previous && changed && changed->file == 0 && previous->marker_free.size() == previous->deck.sources.size() &&
        !previous->marker_free.empty() && previous->marker_free[0] && result.deck.sources.size() == 1) {
        const std::string_view text = result.deck.sources.file(0).text.view();
        result.marker_free = {
            !lint::may_hold_suppressions(text.substr(changed->begin, changed->new_end - changed->begin))};
    }
    lint::DirectiveScan searched_once;  // a run's shared includes are searched once (engine/shared_preview.hpp)
    if (options.share)
        searched_once = [share = options.share](const grammar::SourceFile& file, std::string_view marker) {
            return share->searches.contains(file.text, marker);
        };
    lint::apply_suppressions(result.deck.sources, result.diagnostics, grammar::format_of(result.deck),
                             &result.marker_free, searched_once);
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
    return check_file(path, with_documents);
}

CheckResult check_file(const std::string& path, const CheckOptions& options) {
    return check_read_file(path, grammar::read_deck(path, options.reader), options);
}

CheckResult check_read_file(const std::string& path, grammar::RawDeck deck, const CheckOptions& options) {
    return finish(std::move(deck), options, [&](const grammar::dyna::ReaderOptions& reader, const grammar::RawDeck&) {
        return grammar::read_deck(path, reader);
    });
}

namespace {
// recheck_deck; `take_from`: `previous` when the caller drops it afterwards.
CheckResult recheck_keeping(const std::string& path, const Documents& documents, const CheckOptions& options,
                            const CheckResult& previous, CheckResult* take_from) {
    CheckOptions with_documents = options;
    if (!documents.empty()) with_documents.reader.overlay = &documents;
    with_documents.rules.keep_preview = true;  // for the next re-check
    // An edit of an open main file inside one ordinary block: only its lines are read again.
    std::optional<grammar::SplicedDeck> spliced;
    if (documents.find(path) && previous.deck.sources.size() == 1 && previous.deck.sources.file(0).path == path)
        spliced =
            grammar::splice_edit(previous.deck, grammar::read_source_text(path, &documents), documents.revision(path));
    grammar::RawDeck deck = spliced ? std::move(spliced->deck) : grammar::read_deck(path, with_documents.reader);
    std::optional<OneThreadForSplicedRecheck> one_thread;
    if (spliced) one_thread.emplace();
    // Columns are taken only after an edit outside the bulk blocks: an edit inside one is followed by
    // the preview (engine/preview_after_edit.hpp), which reads the last model's columns.
    if (take_from && !(spliced && !is_bulk_keyword(deck.blocks[spliced->changed.block].keyword))) take_from = nullptr;
    return finish(
        std::move(deck), with_documents,
        [&](const grammar::dyna::ReaderOptions& reader, const grammar::RawDeck&) {
            return grammar::read_deck(path, reader);
        },
        &previous, spliced ? &spliced->changed : nullptr, take_from);
}
}  // namespace

CheckResult recheck_deck(const std::string& path, const Documents& documents, const CheckOptions& options,
                         const CheckResult& previous) {
    return recheck_keeping(path, documents, options, previous, nullptr);
}

CheckResult recheck_deck_taking(const std::string& path, const Documents& documents, const CheckOptions& options,
                                CheckResult& previous) {
    return recheck_keeping(path, documents, options, previous, &previous);
}

CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options,
                         std::optional<grammar::DeckFormat> format, const std::string& base_directory) {
    grammar::RawDeck deck = grammar::read_deck_buffer(std::move(text), name, base_directory, options.reader, format);
    return finish(std::move(deck), options,
                  [&](const grammar::dyna::ReaderOptions& reader, const grammar::RawDeck& original) {
                      // The buffer is the deck's first file: read again from its mended text, or from it.
                      const grammar::SourceFile& main = original.sources.file(0);
                      const std::string* mended = reader.overlay ? reader.overlay->find(main.path) : nullptr;
                      std::string again = mended ? *mended : std::string(std::string_view(main.text));
                      return grammar::read_deck_buffer(std::move(again), name, base_directory, reader, format);
                  });
}

CheckResult::CheckResult() = default;
CheckResult::CheckResult(const CheckResult&) = default;
CheckResult::CheckResult(CheckResult&&) = default;
CheckResult& CheckResult::operator=(const CheckResult&) = default;
CheckResult& CheckResult::operator=(CheckResult&&) noexcept = default;
CheckResult::~CheckResult() = default;

}  // namespace sphdeck::engine
