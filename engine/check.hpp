// "Check these documents": the one pipeline behind `sphdeck check`, the other commands that read a
// deck, `sphdeck verify`, the deck-driven tests and (next) the editor server. Read the deck and its
// includes (from disk, or from in-memory documents laid over it), decode and build the model, run
// the rules, apply suppressions and settings. lint/ owns the rules and never reads a file; this does.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "engine/documents.hpp"
#include "engine/include_graph.hpp"
#include "engine/rule_reuse.hpp"
#include "grammar/dyna/reader.hpp"
#include "grammar/raw_deck.hpp"
#include "grammar/read_deck.hpp"
#include "lint/config.hpp"
#include "lint/rule_context.hpp"
#include "model/bulk_reuse.hpp"
#include "model/deck_check.hpp"
#include "model/model.hpp"

namespace sphdeck::engine {

struct RunShare;  // engine/shared_preview.hpp

struct CheckOptions {
    grammar::dyna::ReaderOptions reader;  // its `overlay` is set by check_deck from the documents
    lint::RuleOptions rules;
    lint::Config
        config;  // sphdeck.toml merged with the command line; engine::options_for copies the solver into `rules`
    // What the decks of one run share: decoded bulk blocks and geometry previews (null: nothing shared).
    RunShare* share = nullptr;
};

struct CheckResult {
    // Declared here and defaulted in engine/check.cpp: the special members of this large aggregate are compiled
    // once, not in every room that copies, moves or drops one (issue 42).
    CheckResult();
    CheckResult(const CheckResult&);
    CheckResult(CheckResult&&);
    CheckResult& operator=(const CheckResult&);
    CheckResult& operator=(CheckResult&&) noexcept;
    ~CheckResult();

    grammar::RawDeck deck;
    std::vector<diag::Diagnostic> diagnostics;  // sorted by location
    model::DeckSummary summary;
    model::Model model;
    IncludeGraph includes;                             // the files the deck pulled in
    std::shared_ptr<const preproc::Preview> preview;   // when CheckOptions::rules.keep_preview (else null)
    std::vector<model::DecodedBulkBlock> bulk_blocks;  // what the next re-check may copy (model/bulk_reuse.hpp)
    std::vector<bool> marker_free;  // by file: no suppression directive in it (lint/suppressions.hpp), for a re-check
    // Each rule family's findings and the rules' id look-ups, for a re-check (engine/rule_reuse.hpp);
    // kept when CheckOptions::rules.keep_preview.
    RuleFindings rule_findings;
    lint::RuleContext::Lookups rule_lookups;
    // The columns of `model` a later re-check took instead of copying them (engine/recheck.hpp):
    // empty now, so the check is fit only to be dropped.
    model::BulkTaken taken;
};

// Checks the deck at `path`; its text and its includes' come from `documents` where they hold the
// path, else from disk. Throws std::runtime_error when the main deck cannot be read.
CheckResult check_deck(const std::string& path, const Documents& documents, const CheckOptions& options = {});

// The same with every file from disk.
CheckResult check_file(const std::string& path, const CheckOptions& options = {});

// check_file of a deck the caller has read already, `deck` = grammar::read_deck(path, options.reader):
// the same result without reading it a second time (`sphdeck format` reads first and checks only when
// a line changes).
CheckResult check_read_file(const std::string& path, grammar::RawDeck deck, const CheckOptions& options = {});

// A deck that exists only in memory under `name` (tests, fuzzing); relative includes are searched
// from `base_directory`. `format`: the reader to use (LS-DYNA unless told; nullopt detects it from the
// text and name).
CheckResult check_buffer(std::string text, const std::string& name, const CheckOptions& options = {},
                         std::optional<grammar::DeckFormat> format = grammar::DeckFormat::LsDyna,
                         const std::string& base_directory = ".");

}  // namespace sphdeck::engine
