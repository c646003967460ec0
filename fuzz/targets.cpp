#include "fuzz/targets.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "diag/render_github.hpp"
#include "diag/render_json.hpp"
#include "diag/render_text.hpp"
#include "text/apply_edits.hpp"
#include "edit/format_deck.hpp"
#include "engine/check.hpp"
#include "engine/deck_diff.hpp"
#include "grammar/read_deck.hpp"
#include "grammar/dyna/expression.hpp"
#include "grammar/dyna/keyword_arguments.hpp"
#include "lint/rule_catalog.hpp"
#include "lsp/json_rpc.hpp"

namespace sphdeck::fuzz {
namespace {

std::string text_of(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// Relative includes resolve against a folder that does not exist, so the fuzzer reads no files
// but the ones it names by absolute path (which the reader must survive too).
constexpr const char* no_folder = "/nonexistent-sphdeck-fuzz";

void render_all(const engine::CheckResult& r) {
    std::size_t bytes = 0;
    for (const diag::Diagnostic& d : r.diagnostics) {
        bytes += diag::render_concise(d, r.deck.sources).size();
        bytes += diag::render_full(d, r.deck.sources, diag::RenderOptions{true}).size();
        bytes += diag::render_github(d, r.deck.sources).size();
    }
    // JSON only: a SARIF document carries the documentation of every rule, the same whatever the
    // input, and rendering it would take nine tenths of each execution.
    auto report = diag::make_json_report(lint::rule_catalog());
    report->add(r.deck.sources, r.diagnostics);
    bytes += report->finish(diag::RunSummary{}).size();
    volatile std::size_t sink = bytes;  // keep the rendering from being optimised away
    (void)sink;
}

void check(const std::uint8_t* data, std::size_t size, const char* name, grammar::DeckFormat format) {
    engine::CheckOptions options;
    options.rules.geometry = true;
    engine::CheckResult r =
        engine::check_buffer(text_of(data, size), std::string(no_folder) + "/" + name, options, format, no_folder);
    render_all(r);
}

}  // namespace

void check_dyna_deck(const std::uint8_t* data, std::size_t size) {
    check(data, size, "fuzz.k", grammar::DeckFormat::LsDyna);
}

void check_radioss_deck(const std::uint8_t* data, std::size_t size) {
    check(data, size, "fuzz_0000.rad", grammar::DeckFormat::Radioss);
}

void parse_keyword_arguments(const std::uint8_t* data, std::size_t size) {
    const std::string text = text_of(data, size);
    (void)grammar::dyna::parse_keyword_arguments(text);
}

void evaluate_expression(const std::uint8_t* data, std::size_t size) {
    const std::string text = text_of(data, size);
    // A few names with values that test the arithmetic's edges; the rest are undefined.
    const auto lookup = [](std::string_view name) -> std::optional<double> {
        if (name == "a" || name == "A") return 2.5;
        if (name == "zero") return 0.0;
        if (name == "big") return 1e308;
        if (name == "tiny") return 5e-324;
        if (name == "neg") return -1.0;
        if (name == "inf") return std::numeric_limits<double>::infinity();
        return std::nullopt;
    };
    const grammar::ExpressionResult r = grammar::evaluate_expression(text, lookup);
    if (!r.ok() && (r.offset > text.size() || r.length == 0)) __builtin_trap();  // the documented contract
}

void format_dyna_deck(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return;
    edit::FormatOptions options;
    options.headers = (data[0] & 1) != 0;
    options.to_fixed = (data[0] & 2) != 0;
    const std::string text = text_of(data + 1, size - 1);
    engine::CheckOptions check;
    check.rules.geometry = false;  // the values are what count here; the check target runs the geometry
    const std::string name = std::string(no_folder) + "/fuzz.k";
    const auto format = [&](const engine::CheckResult& r, const std::string& original) {
        const edit::FormatResult f = edit::format_deck(r.deck, r.diagnostics, {0}, options);
        std::vector<diag::TextEdit> own;
        for (const diag::TextEdit& e : f.edits)
            if (e.span.file == 0) own.push_back(e);
        return text::apply_edits(original, own).text;
    };
    engine::CheckResult before;
    try {
        before = engine::check_buffer(text, name, check, grammar::DeckFormat::LsDyna, no_folder);
    } catch (const std::exception&) {
        return;  // not a deck at all (empty, binary): refused before any formatting
    }
    // format's quick way (the reading alone, edit::format_deck_without_findings): whenever it answers, it
    // answers as the formatter given the findings does, line for line and kept line for kept line.
    if (const auto quick = edit::format_deck_without_findings(before.deck, {0}, options)) {
        const edit::FormatResult full = edit::format_deck(before.deck, before.diagnostics, {0}, options);
        if (quick->changes != full.changes || quick->kept != full.kept || quick->edits.size() != full.edits.size() ||
            quick->kept_lines.size() != full.kept_lines.size())
            __builtin_trap();
        for (std::size_t i = 0; i < full.edits.size(); ++i)
            if (quick->edits[i].span.line != full.edits[i].span.line ||
                quick->edits[i].replacement != full.edits[i].replacement)
                __builtin_trap();
        for (std::size_t i = 0; i < full.kept_lines.size(); ++i)
            if (quick->kept_lines[i].line != full.kept_lines[i].line ||
                quick->kept_lines[i].reason != full.kept_lines[i].reason)
                __builtin_trap();
    }
    const std::string formatted = format(before, text);
    if (formatted == text) return;
    const engine::CheckResult after =
        engine::check_buffer(formatted, name, check, grammar::DeckFormat::LsDyna, no_folder);
    if (!engine::diff_decks(before, after, 0.0).equal()) __builtin_trap();  // a value changed
    if (format(after, formatted) != formatted) __builtin_trap();            // not idempotent
}

void read_lsp_messages(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(text_of(data, size));
    // A small bound, so the fuzzer reaches the skipping of oversized bodies with small inputs.
    lsp::MessageReader reader(in, 1024);
    // Each read consumes at least one byte or ends: the loop cannot outlast the input.
    for (std::size_t reads = 0; reads <= size + 1; ++reads) {
        const lsp::ReadResult r = reader.next();
        if (r.status == lsp::ReadStatus::end) return;
    }
    __builtin_trap();  // a read that consumed nothing: the reader would spin on a live stream
}

Target find_target(std::string_view name) {
    if (name == "dyna_check") return check_dyna_deck;
    if (name == "radioss_check") return check_radioss_deck;
    if (name == "dyna_read") return read_dyna_deck;
    if (name == "radioss_read") return read_radioss_deck;
    if (name == "keyword_arguments") return parse_keyword_arguments;
    if (name == "expression") return evaluate_expression;
    if (name == "lsp_messages") return read_lsp_messages;
    if (name == "format_dyna") return format_dyna_deck;
    return nullptr;
}

}  // namespace sphdeck::fuzz
