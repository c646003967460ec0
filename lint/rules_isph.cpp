// SPH014: heat transfer coefficients of incompressible SPH (*CONTROL_SPH_INCOMPRESSIBLE IHTC 1)
// computed from fluid properties that the deck does not give.
#include <fmt/format.h>
#include <optional>

#include "lint/rules.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::lint {
namespace {

bool isph_starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// The decoded cards of a block whose layout has no condition nor table (one line per card, in
// order): *CONTROL_SPH_INCOMPRESSIBLE, *MAT_SPH_INCOMPRESSIBLE_FLUID. These keywords come from the
// generated layouts, which the model does not read; their values were already checked when the
// deck was read, so the decoder's findings are dropped here.
std::vector<std::vector<model::FieldValue>> decoded_cards(const grammar::RawDeck& deck, const grammar::Block& b,
                                                          const keywords::KeywordMatch& match) {
    std::vector<std::vector<model::FieldValue>> out;
    std::vector<diag::Diagnostic> dropped;
    model::CardDecoder decoder(deck, dropped);
    const auto cards = keywords::cards_for(match);
    std::size_t next = 0;
    for (grammar::CardLinePtr l = deck.begin_lines(b); l != deck.end_lines(b) && next < cards.size(); ++l, ++next) {
        if (cards[next]->unknown_layout || cards[next]->present_if ||
            cards[next]->repeat == keywords::CardRepeat::Repeated)
            break;
        decoder.decode(b, *l, *cards[next], out.emplace_back());
    }
    return out;
}

const model::FieldValue* isph_field_value(const std::vector<std::vector<model::FieldValue>>& cards,
                                          std::string_view name) {
    for (const auto& card : cards)
        for (const auto& v : card)
            if (v.spec->name == name) return &v;
    return nullptr;
}

}  // namespace

void check_isph(RuleContext& c) {
    if (c.model.radioss || include_missing(c)) return;  // a missing include may hold the fluid materials
    std::optional<grammar::Span> htc;                   // IHTC 1 of *CONTROL_SPH_INCOMPRESSIBLE
    struct Fluid {
        grammar::Span where;
        std::string id;
        bool cp = false, lambda = false;  // given and > 0
    };
    std::vector<Fluid> fluids;
    for (const grammar::Block& b : c.deck.blocks) {
        const bool control = b.keyword == "*CONTROL_SPH_INCOMPRESSIBLE";
        const bool fluid = isph_starts_with(b.keyword, "*MAT_SPH_INCOMPRESSIBLE_FLUID");
        if (!control && !fluid) continue;
        const auto match = keywords::find_keyword(b.keyword);
        if (!match || !match->unknown_options.empty()) continue;
        const auto cards = decoded_cards(c.deck, b, *match);
        if (control) {
            const model::FieldValue* v = isph_field_value(cards, "IHTC");
            if (v && v->explicit_value && v->valid && v->number == 1) htc = v->span;
            continue;
        }
        const model::FieldValue* mid = isph_field_value(cards, "MID");
        if (!mid) continue;
        auto positive = [&](std::string_view name) {
            const model::FieldValue* v = isph_field_value(cards, name);
            return v && v->explicit_value && v->valid && v->number > 0;
        };
        fluids.push_back({mid->span, std::string(mid->text), positive("CP"), positive("LAMBDA")});
    }
    if (!htc) return;
    if (fluids.empty()) {
        c.report("SPH014", *htc,
                 "IHTC 1 computes heat transfer coefficients from the fluid properties of "
                 "*MAT_SPH_INCOMPRESSIBLE_FLUID, and the deck has none");
        return;
    }
    for (const Fluid& f : fluids) {
        if (f.cp && f.lambda) continue;
        const char* missing = !f.cp && !f.lambda ? "CP and LAMBDA" : !f.cp ? "CP" : "LAMBDA";
        c.report("SPH014", f.where,
                 fmt::format("*MAT_SPH_INCOMPRESSIBLE_FLUID {} leaves {} blank or not positive, and IHTC 1 computes "
                             "heat transfer coefficients from them",
                             f.id, missing))
            .notes.push_back({*htc, "IHTC 1 here"});
    }
}

}  // namespace sphdeck::lint
