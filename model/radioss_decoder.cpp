// The Radioss block walker: finds each header's keyword, picks the card format of the deck's
// version, takes the title line, cuts the cards and hands them to the builder.
#include "model/radioss_decoder.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <limits>
#include <map>

#include "grammar/radioss/cards.hpp"
#include "grammar/radioss/id_kinds.hpp"
#include "grammar/radioss/keyword_lookup.hpp"
#include "grammar/radioss/reader.hpp"
#include "grammar/value.hpp"
#include "model/radioss_builder.hpp"
#include "model/radioss_card_sequence.hpp"
#include "model/radioss_joined_title.hpp"
#include "model/radioss_other_formats.hpp"
#include "model/radioss_parameters.hpp"
#include "model/radioss_unknown_causes.hpp"
#include "grammar/fields.hpp"

namespace sphdeck::model {

namespace rad = grammar::radioss;

namespace {

std::string_view trim_line(std::string_view s) { return grammar::trim_blanks(s); }

bool is_number_text(std::string_view s) {
    return !s.empty() && grammar::parse_integer(s).status == grammar::NumberStatus::Ok;
}

// "/INTER/TYPE7/5" → "/INTER/TYPE7": the name without its ids, for grouping unknown keywords.
std::string keyword_name(std::string_view header) {
    std::string name;
    for (std::string_view s : rad::path_segments(header)) {
        s = trim_line(s);
        if (is_number_text(s)) break;
        name += '/';
        name += s;
    }
    return name.empty() ? std::string(header) : name;
}

// The header path's segments after the keyword prefix, with their columns.
void split_arguments(const grammar::Block& block, std::size_t prefix_segments, RadiossBlock& b) {
    const std::string_view upper = block.keyword, written = block.arguments;
    std::size_t i = 0, segment = 0;
    while (i < upper.size()) {
        if (upper[i] == '/') {
            ++i;
            continue;
        }
        std::size_t end = upper.find('/', i);
        if (end == std::string_view::npos) end = upper.size();
        if (segment++ >= prefix_segments) {
            b.args.emplace_back(upper.substr(i, end - i));
            b.written.emplace_back(written.substr(i, end - i));
            b.arg_spans.push_back(grammar::Span{block.span.file, block.span.line,
                                                block.span.column + static_cast<std::uint32_t>(i),
                                                block.span.column + static_cast<std::uint32_t>(end)});
        }
        i = end;
    }
}

class Walker {
public:
    Walker(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, int version)
        : deck_(deck), out_(out), version_(version), builder_(deck, out, version), decoder_(deck, out) {
        version_known_ = std::any_of(deck.blocks.begin(), deck.blocks.end(),
                                     [](const grammar::Block& b) { return b.keyword == "/BEGIN"; });
        for (grammar::FileId f = 0; f < deck.sources.size(); ++f) {
            grammar::FileId root = deck.sources.include_chain(f).front();
            engine_.push_back(rad::is_engine_file_name(deck.sources.file(root).display_name));
        }
    }

    void walk_all() {
        // /PARAMETER first: a reference to a later definition is reported, not just unknown.
        decoder_.set_parameters(&parameters_);
        parameters_.collect(deck_, version_, decoder_, out_);
        mark_engine_sections();
        for (const grammar::Block& block : deck_.blocks) {
            decoder_.set_block(static_cast<std::size_t>(&block - deck_.blocks.data()));
            walk(block);
        }
        decoder_.report_lone_shifts();
    }

    Model finish() { return builder_.finish(); }

    // Keeps each decoded block's header, title and single-card fields (for `sphdeck dump`).
    void record_into(RadiossReading* reading) { reading_ = reading; }
    void count_unknown() {
        if (!reading_) return;
        for (const auto& [name, u] : unknown_) reading_->unknown[name] = u.second;
    }

private:
    // DK001: a header neither the starter's CFG files nor sphdeck's tables know, at its line, with
    // the closest known name as an unsafe fix.
    void report_unknown(const grammar::Block& block, bool engine) {
        const std::string name = keyword_name(block.keyword);
        auto& u = unknown_[name];
        if (u.second++ == 0) u.first = block.span;
        if (auto cause = unknown_header_cause(deck_, block)) {
            out_.push_back(std::move(*cause));
            return;
        }
        auto cached = suggestions_.find(name);
        if (cached == suggestions_.end())
            cached =
                suggestions_.emplace(name, suggestions_.size() < 64 ? rad::suggest_keyword(name) : std::nullopt).first;
        const std::optional<std::string>& better = cached->second;
        std::string message = fmt::format("unknown keyword {}: {}", name,
                                          engine ? "the engine stops at a keyword it does not know"
                                                 : "no keyword of the starter's CFG files has this name");
        if (better) message += fmt::format("; did you mean {}?", *better);
        diag::Diagnostic d{"DK001", diag::Severity::Error, std::move(message), block.span, {}};
        d.notes.push_back({grammar::Span{}, "sphdeck reads the deck without this block: its cards are not checked"});
        if (better) {
            grammar::Span at = block.span;
            at.end_column = at.column + static_cast<std::uint32_t>(name.size());
            d.fixes.push_back({fmt::format("replace {} with {}", name, *better), false, {{at, *better}}});
        }
        out_.push_back(std::move(d));
    }

    // One-file decks: the blocks of a main file before its /END/ENGINE are the engine input.
    void mark_engine_sections() {
        engine_block_.assign(deck_.blocks.size(), false);
        for (std::size_t e = 0; e < deck_.blocks.size(); ++e) {
            if (deck_.blocks[e].keyword != "/END/ENGINE") continue;
            const grammar::FileId root = deck_.sources.include_chain(deck_.blocks[e].span.file).front();
            for (std::size_t b = 0; b < e; ++b)
                if (deck_.sources.include_chain(deck_.blocks[b].span.file).front() == root) engine_block_[b] = true;
        }
    }

    // The id a starter header defines, for the REF rules of generated cards: kept under the CFG type
    // letter of its kind (grammar/radioss/id_kinds.hpp: /TABLE/1/12 a function 'F', /FRAME/FIX/3 a
    // system 'Y', /SET/GENERAL/5 a set 'T'); kinds no generated cell links are not kept.
    void note_header_ids(const grammar::Block& block) {
        RadiossFacts& facts = builder_.facts();
        const auto segments = rad::path_segments(block.keyword);
        if (!segments.empty() && trim_line(segments.front()) == "SUBMODEL") facts.submodels = true;
        const auto header = rad::header_id(block.keyword);
        if (!header || !header->role || !header->role->defines) return;
        if (const char link = rad::link_of(header->role->kind)) facts.header_ids[link].insert(header->id);
    }

    void walk(const grammar::Block& block) {
        if (block.keyword == "/END" || block.keyword == "/END/ENGINE") return;
        const std::size_t index = static_cast<std::size_t>(&block - deck_.blocks.data());
        const bool engine = (block.span.file < engine_.size() && engine_[block.span.file]) || engine_block_[index];
        if (!engine) note_header_ids(block);
        const rad::KeywordLookup found = rad::lookup_keyword(block.keyword);
        std::size_t prefix = found.prefix_segments;
        const rad::KeywordSpec* spec = found.spec;
        const rad::KeywordSpec* cards = found.cards ? found.cards : spec;
        // The engine reads any header its REDKEY0 knows (the first five characters of the first
        // segment); the layouts of its keywords are sphdeck's own or none.
        if (engine && rad::is_engine_key(block.keyword) && (!spec || !spec->engine)) return;
        if (!found.known && !(spec && spec->engine)) {
            if (!engine && rad::is_engine_only_key(block.keyword)) {
                out_.push_back({"DK001",
                                diag::Severity::Info,
                                fmt::format("{} is an engine keyword: the starter ignores it; it belongs in the "
                                            "engine deck <run>_0001.rad",
                                            keyword_name(block.keyword)),
                                block.span,
                                {}});
                return;
            }
            report_unknown(block, engine);
        }
        if (!spec) return;  // known by name, nothing to read (/SUBMODEL, /ENDSUB)
        if (spec->engine != engine) {
            out_.push_back({"DK001",
                            diag::Severity::Info,
                            spec->engine ? fmt::format("{} is an engine keyword: the starter ignores it; it belongs "
                                                       "in the engine deck <run>_0001.rad",
                                                       keyword_name(block.keyword))
                                         : fmt::format("{} is a starter keyword: the engine deck ignores it",
                                                       keyword_name(block.keyword)),
                            block.span,
                            {}});
            return;
        }
        if (!spec->decoded) return;
        // A law-specific table ("/MAT/LAW2") reads its arguments after the family ("/MAT"), so
        // the builder sees the law name as it does for any other law.
        if (!spec->family.empty()) prefix = rad::path_segments(spec->family).size();

        RadiossBlock b;
        b.block = &block;
        b.spec = spec;
        b.engine = engine;
        b.version = version_;
        split_arguments(block, prefix, b);
        const rad::FormatSpec& format = cards->format_for(engine ? rad::latest_version : version_);
        b.format = format.since;
        grammar::CardLinePtr line = deck_.begin_lines(block);
        grammar::CardLinePtr end = deck_.end_lines(block);
        // A family's generic table read through a law's generated cards: the family says whether a
        // title follows (the CFG files of /MAT write the title in their export branches only).
        const bool titled = spec->fallback ? spec->title : cards->title;
        if (titled && !engine) {
            if (rad::is_v4(version_)) {
                // V4: the title is the rest of the header path (/PROP/TYPE34/7/title).
                for (std::size_t k = 1; k < b.written.size(); ++k) b.title += (k > 1 ? "/" : "") + b.written[k];
            } else if (line != end) {
                b.title = std::string(trim_line(deck_.text(*line)));
                ++line;
                // No card line after the title: the first card perhaps joined to it (DK037).
                if (line == end && !format.cards.empty())
                    if (auto joined = diagnose_joined_title(deck_, *(line - 1), format.cards.front(), version_,
                                                            keyword_name(block.keyword)))
                        out_.push_back(std::move(*joined));
            }
        }
        if (!spec->generated) builder_.begin(b);
        if (reading_) reading_->records.push_back({block.keyword, spec->name, b.title, block.span, b.format, {}, 0});
        walk_cards(b, *cards, format, line, end);
        if (!spec->generated) builder_.end(b);
    }

    // `table`: the keyword whose cards the lines are (b.spec, or the generated layout of a family
    // table's keyword); the builder sees the values only when they are b.spec's own.
    void walk_cards(const RadiossBlock& b, const rad::KeywordSpec& table, const rad::FormatSpec& format,
                    grammar::CardLinePtr line, grammar::CardLinePtr end) {
        const auto& cards = format.cards;
        RadiossCardSequence sequence(cards);
        const std::string newer = newer_format(table, format);
        const bool to_builder = &table == b.spec && !table.generated;
        // The generated cards of a law read through a family's generic table (/MAT): the builder
        // finds their values by name (model/radioss_build_sph.cpp, end_material).
        const bool by_name = &table != b.spec && b.spec->fallback;
        // A generated layout's older formats often end before columns decks of that version still
        // fill, silently for the starter: their trailing text is reported past the line's width only.
        const std::uint32_t quiet_until = table.generated && !newer.empty() ? rad::line_width(b.version) : 0;
        for (; line != end; ++line) {
            const auto next = sequence.next(deck_.text(*line));
            if (next.step == RadiossCardSequence::Step::Blank) continue;
            if (next.step == RadiossCardSequence::Step::Past) {
                report_extra(table, b.version, format, *line, static_cast<std::size_t>(end - line), newer);
                return;
            }
            const std::size_t found_before = out_.size();
            decoder_.decode(*line, cards[next.index], b.version, b.engine, values_, newer, table.trailing_checked,
                            quiet_until);
            if (table.generated && out_.size() > found_before)
                settle_trailing_text(out_, found_before, *line, deck_.text(*line), table, format, next.index, b.version,
                                     version_known_);
            sequence.advance(next.index, values_);
            if (!b.engine) note_id_uses(table);
            if (to_builder)
                builder_.card(b, next.index, line.index(), values_);
            else if (by_name && next.index < sequence.first_repeated())
                builder_.named_card(values_);
            if (reading_) record(next.index < sequence.first_repeated());
        }
    }

    // Ids the cells of a generated card name (FieldSpec::link), for the REF rules; 0 and negative
    // values name nothing.
    void note_id_uses(const rad::KeywordSpec& table) {
        for (const RadiossValue& v : values_)
            if (v.spec && v.spec->link && v.valid && v.explicit_value && v.number > 0)
                builder_.facts().id_uses.push_back({v.spec->link, static_cast<long long>(v.number), v.span,
                                                    std::string(v.spec->name), std::string(table.name)});
    }

    void record(bool single_card) {
        RadiossRecord& r = reading_->records.back();
        if (!single_card) {
            ++r.repeated_lines;
            return;
        }
        for (const RadiossValue& v : values_) {
            if (!v.spec) continue;
            const rad::Cell cell = v.spec->cell;
            if (cell == rad::Cell::Skip || cell == rad::Cell::Skip20) continue;
            const bool number = cell == rad::Cell::Int || cell == rad::Cell::Real;
            r.fields.push_back({v.spec->name, number, cell == rad::Cell::Int, v.explicit_value, v.valid, v.number,
                                std::string(v.text), v.span});
        }
    }

    // "format 2026 reads more fields" when the deck's version reads an older, shorter format.
    static std::string newer_format(const rad::KeywordSpec& spec, const rad::FormatSpec& format) {
        const rad::FormatSpec& newest = spec.formats.front();
        if (&newest == &format) return {};
        return fmt::format("{} reads more fields from format {}", spec.name, newest.since);
    }

    void report_extra(const rad::KeywordSpec& table, int version, const rad::FormatSpec& format,
                      const grammar::CardLine& line, std::size_t extra, const std::string& newer) {
        std::string message = fmt::format("{} takes {} card(s) in format {}; {} more line(s) ignored", table.name,
                                          format.cards.size(), format.since, extra);
        if (!newer.empty()) message += fmt::format(" ({}; the deck's Invers is {})", newer, version);
        out_.push_back({"DK009",
                        diag::Severity::Warning,
                        std::move(message),
                        grammar::Span{line.file, line.line, 1, std::max<std::uint32_t>(deck_.length(line), 1) + 1},
                        {}});
    }

    const grammar::RawDeck& deck_;
    std::vector<diag::Diagnostic>& out_;
    int version_;
    bool version_known_ = true;  // false: a fragment without /BEGIN, read with the newest formats
    RadiossBuilder builder_;
    RadiossCardDecoder decoder_;
    RadiossParameters parameters_;
    std::vector<RadiossValue> values_;
    std::vector<bool> engine_;        // per file: part of the engine deck
    std::vector<bool> engine_block_;  // per block: before /END/ENGINE in a one-file deck
    RadiossReading* reading_ = nullptr;
    std::map<std::string, std::pair<grammar::Span, std::size_t>> unknown_;
    std::map<std::string, std::optional<std::string>> suggestions_;  // per unknown name
};

}  // namespace

RadiossReading read_radioss_records(const grammar::RawDeck& deck) {
    RadiossReading reading;
    std::vector<diag::Diagnostic> ignored;  // check reports them; the dump only wants the values
    Walker walker(deck, ignored, radioss_version(deck));
    walker.record_into(&reading);
    walker.walk_all();
    walker.count_unknown();
    return reading;
}

int radioss_version(const grammar::RawDeck& deck) {
    for (const grammar::Block& b : deck.blocks) {
        if (b.keyword != "/BEGIN") continue;
        if (b.line_count < 2) return rad::latest_version;
        std::string_view text = trim_line(deck.text(deck.lines[b.first_line + 1]));
        text = text.substr(0, text.find_first_of(" \t,"));
        grammar::IntegerValue v = grammar::parse_integer(text);
        // An Invers past an int (the starter reads it with I10 into a 32-bit integer) is no version either.
        return v.status == grammar::NumberStatus::Ok && v.value > 0 && v.value <= std::numeric_limits<int>::max()
                   ? static_cast<int>(v.value)
                   : rad::latest_version;
    }
    return rad::latest_version;
}

Model build_radioss_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary) {
    Walker walker(deck, out, radioss_version(deck));
    walker.walk_all();
    Model model = walker.finish();
    if (summary) summary->particles = model.particles.size();
    return model;
}

}  // namespace sphdeck::model
