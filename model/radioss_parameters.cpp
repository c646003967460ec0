// Radioss /PARAMETER: reading the definitions, resolving references (model/radioss_parameters.hpp).
#include "model/radioss_parameters.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "grammar/parameters.hpp"  // to_upper
#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/fields.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

namespace {

std::string_view trim_parameter(std::string_view s) { return grammar::trim_blanks(s); }

void report_parameter(std::vector<diag::Diagnostic>& out, const char* code, diag::Severity s, std::string message,
                      grammar::Span span) {
    out.push_back(diag::Diagnostic{code, s, std::move(message), span, {}});
}

bool in_engine_deck(const grammar::RawDeck& deck, const grammar::Block& b) {
    if (!b.span.valid()) return false;
    const grammar::FileId root = deck.sources.include_chain(b.span.file).front();
    return rad::is_engine_file_name(deck.sources.file(root).display_name);
}

// The name of a kind sphdeck does not evaluate: the first cell of the card, up to a comma.
RadiossParameter unevaluated(const grammar::RawDeck& deck, const grammar::CardLine& line) {
    RadiossParameter p;
    const std::string_view text = deck.text(line);
    const std::string_view cell = text.substr(0, std::min<std::size_t>({text.size(), std::size_t{10}, text.find(',')}));
    p.name = std::string(trim_parameter(cell));
    const auto column = static_cast<std::uint32_t>(cell.find_first_not_of(" \t") + 1);
    p.span = grammar::Span{line.file, line.line, column, column + static_cast<std::uint32_t>(p.name.size())};
    return p;
}

}  // namespace

std::optional<RadiossParameterReference> radioss_parameter_reference(std::string_view token) {
    RadiossParameterReference r;
    if (!token.empty() && token.front() == '-') {
        r.negated = true;
        token.remove_prefix(1);
    }
    if (token.size() < 2) return std::nullopt;
    if (token.front() == '&') {
        r.name = token.substr(1);
        return r;
    }
    if (token.front() != '[') return std::nullopt;
    const std::size_t close = token.find(']');
    if (close == std::string_view::npos) {
        r.name = token.substr(1);
        r.closed = false;
        return r;
    }
    if (close == 1 || close + 1 != token.size()) return std::nullopt;  // "[]" or "[a]b": no reference
    r.name = token.substr(1, close - 1);
    return r;
}

const RadiossParameter* RadiossParameters::find(std::string_view name) const {
    auto it = by_name_.find(std::string(name));
    return it == by_name_.end() ? nullptr : &definitions_[it->second];
}

void RadiossParameters::define(RadiossParameter p, std::vector<diag::Diagnostic>& out) {
    if (const RadiossParameter* first = find(p.name)) {
        diag::Diagnostic d{"DK014",
                           diag::Severity::Warning,
                           fmt::format("parameter '{}' is defined twice; the starter's choice is not documented, "
                                       "sphdeck keeps the first definition",
                                       p.name),
                           p.span,
                           {}};
        d.notes.push_back({first->span, "first defined here"});
        out.push_back(std::move(d));
        return;
    }
    by_name_.emplace(p.name, definitions_.size());
    definitions_.push_back(std::move(p));
}

void RadiossParameters::collect(const grammar::RawDeck& deck, int version, RadiossCardDecoder& decoder,
                                std::vector<diag::Diagnostic>& out) {
    std::vector<RadiossValue> values;
    for (std::size_t i = 0; i < deck.blocks.size(); ++i) {
        const grammar::Block& b = deck.blocks[i];
        if (b.keyword.rfind("/PARAMETER/", 0) != 0 || in_engine_deck(deck, b)) continue;
        const auto segments = rad::path_segments(b.keyword);  // PARAMETER, scope, type, id
        const std::string_view scope = segments.size() > 1 ? segments[1] : "";
        const std::string_view type = segments.size() > 2 ? segments[2] : "";
        grammar::CardLinePtr line = deck.begin_lines(b);
        grammar::CardLinePtr end = deck.end_lines(b);
        if (line != end) ++line;  // the title line
        if (line == end) {
            report_parameter(out, "DK008", diag::Severity::Error, "/PARAMETER without its name and value card", b.span);
            continue;
        }
        const rad::KeywordSpec* spec = rad::find_keyword(b.keyword);
        // The name and value card of the table found: a header the tables read otherwise (a family's text-only
        // table, for /PARAMETER//GLOBAL/REAL with its empty segment) gives no value to evaluate.
        const rad::FormatSpec* format = spec ? &spec->format_for(version) : nullptr;
        const rad::CardSpec* card = format && !format->cards.empty() ? &format->cards.front() : nullptr;
        const bool evaluated_kind = scope == "GLOBAL" && (type == "INTEGER" || type == "REAL");
        if (!evaluated_kind || !card || card->fields.size() < 2) {
            RadiossParameter p = unevaluated(deck, *line);
            p.block = i;
            const std::string why =
                evaluated_kind ? fmt::format("sphdeck reads no name and value card for the header {}", b.keyword)
                               : std::string("sphdeck reads /PARAMETER/GLOBAL/INTEGER and REAL only");
            report_parameter(out, "DK001", diag::Severity::Info,
                             fmt::format("/PARAMETER/{}/{} '{}' is not evaluated ({}): cells that use it are not "
                                         "checked",
                                         scope, type, p.name, why),
                             p.name.empty() ? b.span : p.span);
            if (!p.name.empty()) define(std::move(p), out);
            continue;
        }
        decoder.set_block(i);  // a value may use the parameters defined before it
        decoder.decode(*line, *card, version, false, values);
        RadiossParameter p;
        p.name = std::string(values.at(0).text);
        p.span = values[0].span;
        p.block = i;
        p.kind = type == "INTEGER" ? RadiossParameter::Kind::Integer : RadiossParameter::Kind::Real;
        p.value = values.at(1).valid ? values[1].number : 0.0;
        if (line + 1 != end)
            report_parameter(out, "DK009", diag::Severity::Warning,
                             fmt::format("/PARAMETER takes one name and value card; {} more line(s) ignored",
                                         end - line - 1),
                             grammar::Span{line[1].file, line[1].line, 1,
                                           std::max<std::uint32_t>(deck.length(line[1]), 1) + 1});
        if (p.name.empty()) {
            report_parameter(out, "DK008", diag::Severity::Error, "the parameter name (columns 1-10) is blank", p.span);
            continue;
        }
        define(std::move(p), out);
    }
}

std::optional<double> RadiossParameters::value_of(const RadiossParameterReference& ref, std::size_t block,
                                                  bool integer_cell, std::string_view field, grammar::Span span,
                                                  std::vector<diag::Diagnostic>& out) const {
    if (!ref.closed) {
        report_parameter(out, "DK012", diag::Severity::Error,
                         fmt::format("'[{}' has no closing ']' in field {}: a reference must fit in its cell (reader "
                                     "message 100105)",
                                     ref.name, field),
                         span);
        return std::nullopt;
    }
    const RadiossParameter* p = find(ref.name);
    if (!p) {
        std::string message = fmt::format("undefined parameter '{}'", ref.name);
        for (const RadiossParameter& d : definitions_)
            if (grammar::to_upper(d.name) == grammar::to_upper(ref.name)) {
                message += fmt::format("; did you mean '{}'? (names are case-sensitive)", d.name);
                break;
            }
        report_parameter(out, "DK012", diag::Severity::Error, std::move(message), span);
        return std::nullopt;
    }
    if (p->block >= block) {
        diag::Diagnostic d{"DK012",
                           diag::Severity::Error,
                           fmt::format("parameter '{}' is used before its definition; the starter needs the "
                                       "/PARAMETER first (reader message 100106)",
                                       ref.name),
                           span,
                           {}};
        d.notes.push_back({p->span, "defined here"});
        out.push_back(std::move(d));
        return std::nullopt;
    }
    if (p->kind == RadiossParameter::Kind::NotEvaluated) return std::nullopt;  // reported at its definition
    if (integer_cell && p->kind == RadiossParameter::Kind::Real) {
        report_parameter(out, "DK013", diag::Severity::Error,
                         fmt::format("real parameter '{}' used in integer field {}", ref.name, field), span);
        return std::nullopt;
    }
    return ref.negated ? -p->value : p->value;
}

}  // namespace sphdeck::model
