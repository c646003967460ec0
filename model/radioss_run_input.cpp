// read_radioss_run_input: /RUN (engine deck: Tstop on its first data line, the "FINAL TIME" of the
// engine's listing, lectur.F) and /INIVEL (starter: hm_read_inivel.F), from the raw lines, and the
// keyword of every block for the solver's refusal list (refsolver/setup_radioss.cpp).
#include "model/radioss_run_input.hpp"

#include <algorithm>

#include "grammar/radioss/reader.hpp"
#include "grammar/value.hpp"

namespace sphdeck::model {

namespace {

bool comment_line(std::string_view t) { return !t.empty() && (t[0] == '#' || t[0] == '$'); }

std::string_view run_input_column(std::string_view line, std::size_t start, std::size_t width) {
    if (start >= line.size()) return {};
    return line.substr(start, std::min(width, line.size() - start));
}

// Blocks of the engine input: the engine deck's files, and a one-file deck's blocks before /END/ENGINE.
std::vector<bool> engine_blocks(const grammar::RawDeck& deck) {
    std::vector<bool> engine(deck.blocks.size(), false);
    std::vector<grammar::FileId> end_engine_roots;
    std::vector<std::size_t> end_engine_at;
    for (std::size_t b = 0; b < deck.blocks.size(); ++b) {
        const grammar::FileId root = deck.sources.include_chain(deck.blocks[b].span.file).front();
        engine[b] = grammar::radioss::is_engine_file_name(deck.sources.file(root).display_name);
        if (deck.blocks[b].keyword == "/END/ENGINE") end_engine_roots.push_back(root), end_engine_at.push_back(b);
    }
    for (std::size_t k = 0; k < end_engine_at.size(); ++k)
        for (std::size_t b = 0; b < end_engine_at[k]; ++b)
            if (deck.sources.include_chain(deck.blocks[b].span.file).front() == end_engine_roots[k]) engine[b] = true;
    return engine;
}

RadiossInitialVelocity read_inivel(const grammar::Block& block, const std::vector<std::string_view>& data) {
    RadiossInitialVelocity v;
    const std::size_t kind_end = block.keyword.find('/', 8);
    v.kind = block.keyword.substr(8, kind_end == std::string::npos ? std::string::npos : kind_end - 8);
    v.span = block.span;
    if (data.size() < 2) return v;  // the title, then the card
    const std::string_view card = data[1];
    bool ok = true;
    for (std::size_t k = 0; k < 3; ++k) {
        const grammar::RealValue r = grammar::parse_real(run_input_column(card, 20 * k, 20));
        ok = ok && (r.status == grammar::NumberStatus::Ok || r.status == grammar::NumberStatus::Blank);
        v.v[k] = r.status == grammar::NumberStatus::Ok ? r.value : 0.0;
    }
    const grammar::IntegerValue g = grammar::parse_integer(run_input_column(card, 60, 10));
    const grammar::IntegerValue s = grammar::parse_integer(run_input_column(card, 70, 10));
    v.group = g.status == grammar::NumberStatus::Ok ? g.value : 0;
    v.skew = s.status == grammar::NumberStatus::Ok ? s.value : 0;
    v.read = ok && (g.status == grammar::NumberStatus::Ok || g.status == grammar::NumberStatus::Blank) &&
             (s.status == grammar::NumberStatus::Ok || s.status == grammar::NumberStatus::Blank);
    return v;
}

}  // namespace

RadiossRunInput read_radioss_run_input(const grammar::RawDeck& deck) {
    RadiossRunInput in;
    const std::vector<bool> engine = engine_blocks(deck);
    for (std::size_t b = 0; b < deck.blocks.size(); ++b) {
        const grammar::Block& block = deck.blocks[b];
        in.blocks.push_back({block.keyword, block.span, engine[b]});
        const bool run = block.keyword == "/RUN" || block.keyword.rfind("/RUN/", 0) == 0;
        const bool inivel = block.keyword.rfind("/INIVEL/", 0) == 0;
        if (!(run && engine[b]) && !(inivel && !engine[b])) continue;
        std::vector<std::string_view> data;
        for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l)
            if (const std::string_view t = deck.text(*l); !comment_line(t)) data.push_back(t);
        if (inivel) {
            in.initial_velocities.push_back(read_inivel(block, data));
        } else if (!data.empty()) {
            const grammar::RealValue t = grammar::parse_real(run_input_column(data[0], 0, 20));
            if (t.status == grammar::NumberStatus::Ok) in.end_time = t.value, in.run_span = block.span;
        }
    }
    return in;
}

}  // namespace sphdeck::model
