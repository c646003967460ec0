// sphdeck keyword NAME: a keyword's cards as the schema tables describe them (columns, types,
// defaults, allowed values, docs); `--list` prints every keyword the tables know. Names with a
// leading '/' are OpenRadioss cards (cli/keyword_radioss.cpp).
#include <algorithm>
#include <array>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/keyword_radioss.hpp"
#include "grammar/keywords/generated_layouts.hpp"
#include "grammar/keywords/schema.hpp"

namespace sphdeck::cli {
namespace {

using grammar::CardFormat;
using keywords::CardSpec;
using keywords::FieldSpec;
using keywords::FieldType;
using keywords::KeywordMatch;

struct KeywordArgs {
    std::string name;
    std::string format = "standard";
    std::string solver;  // --list: "lsdyna", "radioss" or both
    bool list = false;
};

std::string number(double v) { return fmt::format("{:g}", v); }

std::string field_name(const FieldSpec& f) {
    if (f.aliases.empty()) return std::string(f.name);
    return fmt::format("{} ({})", f.name, fmt::join(f.aliases, ", "));
}

std::string default_cell(const FieldSpec& f) {
    if (f.type == FieldType::Unused) return "";
    if (f.default_value)
        return f.zero_is_default ? fmt::format("{} (0 = default)", number(*f.default_value)) : number(*f.default_value);
    if (!f.default_text.empty()) return std::string(f.default_text);
    return f.required ? "none (required)" : "none";
}

// Enum values in table order; runs of three or more consecutive values shortened to "a..b".
std::string choice_list(const FieldSpec& f) {
    std::vector<std::string> parts;
    const auto& c = f.choices;
    for (std::size_t i = 0; i < c.size();) {
        std::size_t j = i;
        while (j + 1 < c.size() && c[j + 1].value == c[j].value + 1) ++j;
        if (j - i >= 2) {
            parts.push_back(fmt::format("{}..{}", c[i].value, c[j].value));
        } else {
            for (std::size_t k = i; k <= j; ++k) parts.push_back(std::to_string(c[k].value));
        }
        i = j + 1;
    }
    return fmt::format("{}", fmt::join(parts, ", "));
}

std::string allowed_cell(const FieldSpec& f) {
    if (!f.choices.empty()) return choice_list(f);
    if (!f.text_choices.empty()) return fmt::format("{}", fmt::join(f.text_choices, ", "));
    if (f.min && f.max) return fmt::format("[{}, {}]", number(*f.min), number(*f.max));
    if (f.min) return fmt::format(">= {}", number(*f.min));
    if (f.max) return fmt::format("<= {}", number(*f.max));
    return "";
}

std::string with_since(std::string_view text, std::string_view since) {
    return since.empty() ? std::string(text) : fmt::format("{} (since {})", text, since);
}

// One card as a table; enum meanings follow their row, aligned under the "allowed" column.
void print_card_table(const CardSpec& card, CardFormat format) {
    enum { Columns, Field, Type, Default, Allowed, Doc };
    std::vector<std::array<std::string, 6>> rows;
    rows.push_back({"columns", "field", "type", "default", "allowed", "doc"});
    const auto slots = keywords::layout(card, format);
    for (std::size_t i = 0; i < card.fields.size(); ++i) {
        const FieldSpec& f = card.fields[i];
        rows.push_back({fmt::format("{}-{}", slots[i].start + 1, slots[i].start + slots[i].width), field_name(f),
                        std::string(keywords::to_string(f.type)), default_cell(f), allowed_cell(f),
                        f.refers_to.empty() ? with_since(f.doc, f.since)
                                            : fmt::format("{} of a {}", with_since(f.doc, f.since), f.refers_to)});
    }
    std::array<std::size_t, 6> width{};
    for (const auto& row : rows)
        for (std::size_t c = 0; c < Doc; ++c) width[c] = std::max(width[c], row[c].size());
    const std::size_t allowed_at = 2 + width[Columns] + width[Field] + width[Type] + width[Default] + 8;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const auto& row = rows[r];
        std::string line = "  ";
        for (std::size_t c = 0; c < Doc; ++c) line += fmt::format("{:<{}}  ", row[c], width[c]);
        line += row[Doc];
        while (!line.empty() && line.back() == ' ') line.pop_back();
        fmt::print("{}\n", line);
        if (r == 0) continue;
        const FieldSpec& f = card.fields[r - 1];
        std::size_t value_width = 0;
        for (const auto& c : f.choices) value_width = std::max(value_width, std::to_string(c.value).size());
        for (const auto& c : f.choices)
            fmt::print("{:{}}{:>{}} = {}\n", "", allowed_at, c.value, value_width, with_since(c.meaning, c.since));
    }
}

// "DOF is one of -11, 11 or VAD == 4": the test, its `and` parts, then its `or` alternatives.
std::string condition_text(const keywords::CardCondition& c) {
    std::string out;
    if (!c.any_of.empty()) {
        std::vector<std::string> values;
        for (double v : c.any_of) values.push_back(number(v));
        out = fmt::format("{} is one of {}", c.field, fmt::join(values, ", "));
    } else {
        out = fmt::format("{} {} {}", c.field, keywords::to_string(c.compare), number(c.value));
    }
    for (const auto& a : c.all_of) out += " and " + condition_text(a);
    for (const auto& o : c.or_else) out += " or " + condition_text(o);
    return out;
}

std::string dyna_card_notes(const CardSpec& card, std::size_t index, std::size_t count, std::size_t group) {
    std::vector<std::string> notes{std::string(keywords::to_string(card.repeat))};
    if (card.repeat == keywords::CardRepeat::Repeated) notes.back() += ": one line per item until the next keyword";
    if (card.present_if) notes.push_back("read only when " + condition_text(*card.present_if));
    if (group > 0 && index + group >= count)
        notes.push_back(fmt::format("repeats in a group of {} cards until the next keyword", group));
    if (!card.since.empty()) notes.push_back(fmt::format("since {}", card.since));
    return fmt::format("{}", fmt::join(notes, "; "));
}

void print_keyword(const KeywordMatch& match, CardFormat format) {
    const keywords::KeywordSchema& k = *match.schema;
    std::string title(k.name);
    for (const auto* o : match.options) title += fmt::format("_{}", o->suffix);
    fmt::print("{}{}\n", title, k.unique ? "  (at most once per deck)" : "");
    if (!k.aliases.empty()) fmt::print("aliases: {}\n", fmt::join(k.aliases, ", "));
    if (!k.doc.empty()) fmt::print("{}\n", k.doc);
    if (k.free_text) fmt::print("data lines are free text, never split into fields\n");
    if (!k.options.empty()) {
        fmt::print("\noptions{}:\n", match.options.empty() ? " (add to the name to see their cards)" : " (* = given)");
        std::size_t w = 0;
        for (const auto& o : k.options) w = std::max(w, o.suffix.size() + 1);
        for (const auto& o : k.options) {
            const bool given = std::find(match.options.begin(), match.options.end(), &o) != match.options.end();
            std::string doc(o.doc);
            if (!o.aliases.empty()) doc += fmt::format(" (also _{})", fmt::join(o.aliases, ", _"));
            fmt::print("  {} {:<{}}  {}\n", given ? '*' : ' ', fmt::format("_{}", o.suffix), w, doc);
        }
    }
    const auto cards = keywords::cards_for(match);
    const std::size_t group = keywords::repeat_group_size(match);
    if (format != CardFormat::Standard)
        fmt::print("\ncolumns in {} format\n", format == CardFormat::Long ? "long (+)" : "i10 (%)");
    for (std::size_t i = 0; i < cards.size(); ++i) {
        const CardSpec& card = *cards[i];
        if (card.unknown_layout) {
            fmt::print("\n(further lines are not checked: their layout depends on values or on the solver version)\n");
            break;
        }
        fmt::print("\n{} ({})\n", card.name, dyna_card_notes(card, i, cards.size(), group));
        if (!card.doc.empty()) fmt::print("  {}\n", card.doc);
        print_card_table(card, format);
    }
}

void print_list(const std::string& solver) {
    std::vector<std::pair<std::string, std::string_view>> rows;
    std::size_t w = 0;
    const auto radioss = radioss_list_rows();
    if (solver != "lsdyna")
        for (const auto& [names, what] : radioss) {
            w = std::max(w, names.size());
            rows.emplace_back(names, what);
        }
    if (solver == "radioss") {
        for (const auto& [names, doc] : rows) fmt::print("{:<{}}  {}\n", names, w, doc);
        return;
    }
    for (const auto& k : keywords::all_keywords()) {
        std::string names(k.name);
        if (!k.aliases.empty()) names += fmt::format(" ({})", fmt::join(k.aliases, ", "));
        w = std::max(w, names.size());
        rows.emplace_back(std::move(names), k.doc);
    }
    // Every other LS-DYNA keyword, from the generated layouts (hand-written names are listed above).
    for (const auto& e : keywords::generated::layouts()) {
        auto match = keywords::find_keyword(e.name);
        if (match && match->schema->generated && match->schema->name == e.name)
            rows.emplace_back(std::string(e.name), "(layout generated from pydyna)");
    }
    for (const auto& [names, doc] : rows) fmt::print("{:<{}}  {}\n", names, w, doc);
}

// "; did you mean *A?" or "; did you mean *A, *B or *C?"; empty when nothing is close.
std::string suggestion(std::string_view name) {
    const auto similar = keywords::similar_keywords(name);
    if (similar.empty()) return "";
    if (similar.size() == 1) return fmt::format("; did you mean {}?", similar[0]);
    return fmt::format("; did you mean {} or {}?", fmt::join(similar.begin(), similar.end() - 1, ", "), similar.back());
}

CardFormat format_of(const std::string& s) {
    if (s == "long") return CardFormat::Long;
    if (s == "i10") return CardFormat::I10;
    return CardFormat::Standard;
}

int run_keyword(const KeywordArgs& args) {
    if (args.list) {
        print_list(args.solver);
        return exit_clean;
    }
    if (args.name.empty()) {
        fmt::print(stderr, "sphdeck keyword: give a keyword name (e.g. *CONTROL_SPH, /SPHGLO) or --list\n");
        return exit_usage;
    }
    if (args.name.front() == '/') {
        const auto* keyword = find_radioss_keyword(args.name);
        if (!keyword) {
            fmt::print(stderr,
                       "sphdeck: unknown OpenRadioss keyword '{}'{}\nrun 'sphdeck keyword --list --solver radioss' "
                       "for every one\n",
                       args.name, radioss_suggestion(args.name));
            return exit_usage;
        }
        print_radioss_keyword(*keyword);
        return exit_clean;
    }
    const auto match = keywords::find_keyword(args.name);
    if (!match || !match->unknown_options.empty()) {
        std::string why;
        if (match)
            why = fmt::format(" ({} has no option _{})", match->schema->name, fmt::join(match->unknown_options, ", _"));
        fmt::print(stderr, "sphdeck: unknown keyword '{}'{}{}\nrun 'sphdeck keyword --list' for every keyword\n",
                   args.name, why, suggestion(args.name));
        return exit_usage;
    }
    print_keyword(*match, format_of(args.format));
    return exit_clean;
}

}  // namespace

std::function<int()> setup_keyword(CLI::App& app) {
    auto args = std::make_shared<KeywordArgs>();
    app.add_option("name", args->name,
                   "keyword, with or without '*' and options: *CONTROL_SPH, mat_009; or an OpenRadioss card: /SPHGLO");
    app.add_flag("--list", args->list, "list every keyword the schema tables know");
    app.add_option("--solver", args->solver, "with --list: only the keywords of one solver")
        ->check(CLI::IsMember({"lsdyna", "radioss"}));
    app.add_option("--format", args->format, "LS-DYNA card format whose columns are shown")
        ->check(CLI::IsMember({"standard", "long", "i10"}))
        ->capture_default_str();
    return [args] { return run_keyword(*args); };
}

}  // namespace sphdeck::cli
