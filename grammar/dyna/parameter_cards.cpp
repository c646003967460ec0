#include "grammar/dyna/parameter_cards.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <tuple>

#include "grammar/dyna/expression.hpp"
#include "grammar/fields.hpp"
#include "grammar/undefined_parameter.hpp"
#include "grammar/value.hpp"

namespace sphdeck::grammar::dyna {
namespace {

struct Context {
    RawDeck& deck;
    const Block& block;
    bool local;
};

void report_parameter_finding(RawDeck& deck, const char* code, diag::Severity s, std::string message, Span span) {
    deck.diagnostics.push_back(diag::Diagnostic{code, s, std::move(message), span, {}});
}

// The name field: its first non-blank character is the type letter (R, I or C, any case),
// the name follows, glued or after blanks ("RSHLTHK" == "R  SHLTHK").
bool split_type_and_name(std::string_view field, ParameterType& type, std::string_view& name) {
    std::size_t i = 0;
    while (i < field.size() && field[i] == ' ') ++i;
    if (i == field.size()) return false;
    switch (std::toupper(static_cast<unsigned char>(field[i]))) {
        case 'R': type = ParameterType::Real; break;
        case 'I': type = ParameterType::Integer; break;
        case 'C': type = ParameterType::Character; break;
        default: return false;
    }
    name = field.substr(i + 1);
    while (!name.empty() && (name.front() == ' ' || name.front() == '\t')) name.remove_prefix(1);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t' || name.back() == '\r')) name.remove_suffix(1);
    return !name.empty();
}

// Applies *PARAMETER_DUPLICATION to a new definition; false when it must not be added.
bool accept_definition(Context& c, const Parameter& p) {
    const Parameter* old = c.deck.parameters.find_existing(p.name, p.span.file);
    if (!old) return true;
    if (old->name != p.name) {
        report_parameter_finding(c.deck, "DK024", diag::Severity::Warning,
                                 "parameter '" + p.name + "' differs from '" + old->name + "' only by case", p.span);
    }
    const std::string what = "parameter '" + p.name + "' is defined again";
    switch (c.deck.parameters.duplication) {
        case Duplication::WarnKeepFirst:
            report_parameter_finding(c.deck, "DK014", diag::Severity::Warning,
                                     what + "; the first definition is kept (DFLAG 1)", p.span);
            return false;
        case Duplication::WarnReplace:
            report_parameter_finding(c.deck, "DK014", diag::Severity::Warning,
                                     what + "; the new value replaces it (DFLAG 2)", p.span);
            return true;
        case Duplication::Error:
            report_parameter_finding(c.deck, "DK014", diag::Severity::Error, what + " (DFLAG 3 forbids it)", p.span);
            return false;
        case Duplication::SilentReplace: return true;
        case Duplication::SilentKeepFirst: return false;
    }
    return false;
}

void define(Context& c, Parameter p) {
    p.scope = c.local ? p.span.file + 1 : 0;
    if (accept_definition(c, p)) c.deck.parameters.define(std::move(p));
}

// A value written in a *PARAMETER card; it may itself refer to an earlier parameter.
bool value_of(Context& c, const Field& field, ParameterType type, Parameter& p) {
    if (type == ParameterType::Character) {
        p.text = std::string(classify_value(field.text).text);
        return true;
    }
    ValueToken token = classify_value(field.text);
    if (token.shape == ValueShape::Parameter) {
        auto found = c.deck.parameters.find(token.name, field.span.file, c.deck.parameters.epoch());
        if (!found.parameter) {
            c.deck.diagnostics.push_back(undefined_parameter(c.deck.parameters,
                                                             reference_in_field(token, field.text, field.span, 0),
                                                             field.span, field.span.file, c.deck.parameters.epoch()));
            return false;
        }
        if (found.parameter->type == ParameterType::Character) {
            report_parameter_finding(c.deck, "DK012", diag::Severity::Error,
                                     "undefined parameter '" + std::string(token.name) + "'", field.span);
            return false;
        }
        p.number = token.negated ? -found.parameter->number : found.parameter->number;
    } else {
        RealValue v = to_real(token);
        if (v.status != NumberStatus::Ok) {
            report_parameter_finding(c.deck, "DK003", diag::Severity::Error,
                                     "parameter value '" + std::string(token.text) + "' is not a number", field.span);
            return false;
        }
        p.number = v.value;
    }
    if (type == ParameterType::Integer) {
        if (p.number != std::trunc(p.number))
            report_parameter_finding(c.deck, "DK004", diag::Severity::Warning,
                                     "integer parameter '" + p.name + "' given a non-integral value; truncated",
                                     field.span);
        p.number = std::trunc(p.number);
    }
    return true;
}

void read_pairs(Context& c, const CardLine& line) {
    static constexpr FixedField pair_fields[] = {{0, 10},  {10, 10}, {20, 10}, {30, 10},
                                                 {40, 10}, {50, 10}, {60, 10}, {70, 10}};
    std::vector<FixedField> positions;
    widen(pair_fields, c.block.format, positions);
    std::vector<Field> fields;
    std::string_view text = c.deck.text(line);
    CutReport cut = cut_fields(text, line, positions, significant_width(positions, c.block.format), fields);
    if (cut.has_tab) {
        auto tab = static_cast<std::uint32_t>(text.find('\t'));
        report_parameter_finding(c.deck, "DK016", diag::Severity::Warning,
                                 "tab in a fixed-format card: columns become ambiguous",
                                 Span{line.file, line.line, tab + 1, tab + 2});
    }
    for (std::size_t i = 0; i + 1 < fields.size(); i += 2) {
        ParameterType type;
        std::string_view name;
        if (is_blank(fields[i].text)) continue;
        if (!split_type_and_name(fields[i].text, type, name)) {
            report_parameter_finding(c.deck, "DK013", diag::Severity::Error,
                                     "parameter name '" + std::string(fields[i].text) +
                                         "' must start with its type letter R, I or C",
                                     fields[i].span);
            continue;
        }
        Parameter p;
        p.name = std::string(name);
        p.type = type;
        p.span = fields[i].span;
        if (value_of(c, fields[i + 1], type, p)) define(c, std::move(p));
    }
}

// PRMR in columns 1-10, the expression in 11-80; following lines with blank columns 1-10 continue it.
void read_expressions(Context& c) {
    CardLinePtr begin = c.deck.begin_lines(c.block);
    CardLinePtr end = c.deck.end_lines(c.block);
    for (CardLinePtr l = begin; l != end;) {
        std::string_view text = c.deck.text(*l);
        const std::size_t fixed_width = c.block.format == CardFormat::Long ? 20 : 10;
        // Free format: a comma in the name field ends the name there ("Rf_r, 2-f_f"), and the
        // expression is the rest of the line (commas inside it belong to it: max(a,b)).
        const std::size_t comma = text.substr(0, std::min(text.size(), fixed_width)).find(',');
        const bool free_format = comma != std::string_view::npos;
        const std::size_t name_width = free_format ? comma : fixed_width;
        const std::size_t expression_start = free_format ? comma + 1 : fixed_width;
        std::string_view name_field = text.substr(0, std::min(text.size(), name_width));
        CardLinePtr first = l++;
        if (is_blank(name_field)) continue;
        std::string expression(text.size() > expression_start ? text.substr(expression_start) : std::string_view{});
        while (l != end) {
            std::string_view next = c.deck.text(*l);
            if (!is_blank(next.substr(0, std::min(next.size(), fixed_width))) || is_blank(next)) break;
            expression += ' ';
            expression += next.substr(std::min(next.size(), fixed_width));
            ++l;
        }
        Span name_span{first->file, first->line, 1, static_cast<std::uint32_t>(name_field.size() + 1)};
        Span expression_span{first->file, first->line, static_cast<std::uint32_t>(expression_start + 1),
                             static_cast<std::uint32_t>(std::max(text.size(), expression_start + 1) + 1)};
        ParameterType type;
        std::string_view name;
        if (!split_type_and_name(name_field, type, name)) {
            report_parameter_finding(c.deck, "DK015", diag::Severity::Error,
                                     "parameter name '" + std::string(name_field) + "' must start with R, I or C",
                                     name_span);
            continue;
        }
        std::string undefined;
        auto lookup = [&](std::string_view ref) -> std::optional<double> {
            auto found = c.deck.parameters.find(ref, first->file, c.deck.parameters.epoch());
            if (!found.parameter || found.parameter->type == ParameterType::Character) return std::nullopt;
            return found.parameter->number;
        };
        if (std::string_view tab_at = text; tab_at.find('\t') != std::string_view::npos)
            report_parameter_finding(c.deck, "DK016", diag::Severity::Warning,
                                     "tab in a fixed-format card: columns become ambiguous",
                                     Span{first->file, first->line, static_cast<std::uint32_t>(tab_at.find('\t') + 1),
                                          static_cast<std::uint32_t>(tab_at.find('\t') + 2)});
        ExpressionResult r = evaluate_expression(expression, lookup);
        if (!r.ok()) {
            const char* code = r.error == ExpressionError::UndefinedParameter ? "DK012" : "DK015";
            Span where = expression_span;
            if (first == l - 1 && r.offset + expression_start < text.size()) {  // single line: point at the token
                where.column = static_cast<std::uint32_t>(expression_start + r.offset + 1);
                where.end_column = static_cast<std::uint32_t>(where.column + std::max<std::size_t>(r.length, 1));
            }
            report_parameter_finding(c.deck, code, diag::Severity::Error,
                                     "in expression of '" + std::string(name) + "': " + r.message, where);
            continue;
        }
        Parameter p;
        p.name = std::string(name);
        p.type = type;
        p.number = type == ParameterType::Integer ? std::trunc(r.value) : r.value;  // Fortran INT() truncates
        p.span = name_span;
        if (type == ParameterType::Character) {
            report_parameter_finding(c.deck, "DK013", diag::Severity::Error,
                                     "a character parameter cannot take an expression", name_span);
            continue;
        }
        define(c, std::move(p));
    }
}

void read_duplication(Context& c) {
    if (c.block.line_count == 0) return;
    const CardLine& line = *c.deck.begin_lines(c.block);
    IntegerValue flag = parse_integer(c.deck.text(line).substr(0, 10));
    if (flag.status == NumberStatus::Blank) return;
    Span span{line.file, line.line, 1, 11};
    if (flag.status != NumberStatus::Ok || flag.value < 1 || flag.value > 5) {
        report_parameter_finding(c.deck, "DK007", diag::Severity::Error, "DFLAG must be 1 to 5", span);
        return;
    }
    c.deck.parameters.duplication = static_cast<Duplication>(flag.value);
}

}  // namespace

void group_redefinitions(RawDeck& deck) {
    constexpr std::string_view prefix = "parameter '", again = "' is defined again";
    constexpr std::size_t listed_notes = 3, listed_names = 8;  // the count says the rest
    auto& all = deck.diagnostics;
    struct Group {
        std::size_t first;
        std::vector<std::string> names;
    };
    std::map<std::tuple<FileId, std::string>, Group> groups;  // file, what the redefinition does
    std::vector<bool> drop(all.size(), false);
    std::vector<std::size_t> merged_into(all.size(), 0);
    for (std::size_t i = 0; i < all.size(); ++i) {
        const diag::Diagnostic& d = all[i];
        if (d.code != "DK014" || d.severity != diag::Severity::Warning || d.message.rfind(prefix, 0) != 0) continue;
        const std::size_t end = d.message.find(again);
        if (end == std::string::npos) continue;
        std::string name = d.message.substr(prefix.size(), end - prefix.size());
        auto [it, fresh] = groups.try_emplace({d.span.file, d.message.substr(end + again.size())}, Group{i, {}});
        it->second.names.push_back(std::move(name));
        if (fresh) continue;
        drop[i] = true;
        merged_into[i] = it->second.first;
        diag::Diagnostic& first = all[it->second.first];
        if (it->second.names.size() <= listed_notes + 1)
            first.notes.push_back({d.span, "'" + it->second.names.back() + "' is defined again here"});
    }
    for (auto& [key, group] : groups) {
        diag::Diagnostic& first = all[group.first];
        if (group.names.size() > 1) {
            std::string names;
            for (std::size_t k = 0; k < group.names.size() && k < listed_names; ++k)
                names += (k ? ", " : "") + group.names[k];
            first.message += "; " + std::to_string(group.names.size()) +
                             " parameters of this file are defined again (" + names +
                             (group.names.size() > listed_names ? ", ..." : "") + ")";
        }
        first.notes.push_back({Span{},
                               "*PARAMETER_DUPLICATION 4 (replace) or 5 (keep the first) redefines silently "
                               "where it is meant (defaults in an include overridden by the deck)"});
    }
    // A DK024 (names differing by case) on the line of a DK014 joins it: one finding per line.
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (all[i].code != "DK024" || drop[i]) continue;
        for (std::size_t j = 0; j < all.size(); ++j)
            if (j != i && all[j].code == "DK014" && all[j].span.file == all[i].span.file &&
                all[j].span.line == all[i].span.line) {
                const std::size_t into = drop[j] ? merged_into[j] : j;
                all[into].notes.push_back({all[i].span, all[i].message});
                drop[i] = true;
                break;
            }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (!drop[i]) {
            if (kept != i) all[kept] = std::move(all[i]);
            ++kept;
        }
    all.resize(kept);
}

void define_parameters(RawDeck& deck, const Block& block) {
    const std::string& k = block.keyword;
    Context c{deck, block, k.find("_LOCAL") != std::string::npos};
    if (k == "*PARAMETER_DUPLICATION") return read_duplication(c);
    if (k.rfind("*PARAMETER_EXPRESSION", 0) == 0) return read_expressions(c);
    for (CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) read_pairs(c, *l);
}

}  // namespace sphdeck::grammar::dyna
