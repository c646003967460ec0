// Internal to model/radioss_*.cpp: fills the Model and its RadiossFacts from decoded cards.
// The walker (radioss_decoder.cpp) calls begin, card (per line) and end for every block; the
// keyword handlers live in radioss_build_mesh.cpp and radioss_build_sph.cpp; finish
// (radioss_finish.cpp) resolves what needs the whole deck (particle masses, planes, groups).
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/model.hpp"
#include "model/radioss_card_decoder.hpp"

namespace sphdeck::model {

// One block as the walker sees it: the keyword, the path segments after its prefix, the title.
struct RadiossBlock {
    const grammar::Block* block = nullptr;
    const grammar::radioss::KeywordSpec* spec = nullptr;
    std::vector<std::string> args;         // upper case: /SPHBCS/SLIDE/1 → {"SLIDE", "1"}
    std::vector<std::string> written;      // as written
    std::vector<grammar::Span> arg_spans;  // their columns on the header line
    std::string title;
    int format = 0;       // `since` of the card format read
    int version = 0;      // the deck's version
    bool engine = false;  // in the engine deck
};

class RadiossBuilder {
public:
    RadiossBuilder(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, int version);

    void begin(const RadiossBlock& b);
    void card(const RadiossBlock& b, std::size_t card, std::uint32_t line, const std::vector<RadiossValue>& values);
    // A card of another table than the block's (a law's generated cards under /MAT), kept for
    // value(name).
    void named_card(const std::vector<RadiossValue>& values) { cards_.push_back(values); }
    void end(const RadiossBlock& b);
    Model finish();
    // The facts being gathered, for what the walker records itself (ids of generated cards).
    RadiossFacts& facts() { return facts_; }

private:
    // Once cards of the open block, by card index (empty when the block had no such line).
    std::vector<std::vector<RadiossValue>> cards_;

    const RadiossValue* value(std::string_view name) const;
    // The first of `names` a card of the block holds (the first when none does).
    std::string_view first_named(std::initializer_list<std::string_view> names) const;
    template <typename T>
    StarterValue<T> starter(std::string_view name, const RadiossBlock& b) const;
    StarterValue<std::string> text(std::string_view name, const RadiossBlock& b) const;
    std::optional<long long> header_id(const RadiossBlock& b, std::size_t arg, std::string_view what);
    void report(const char* code, diag::Severity s, std::string message, grammar::Span span);

    // Per-line handlers of repeated cards (radioss_build_mesh.cpp, radioss_build_sph.cpp).
    void add_node(const std::vector<RadiossValue>& v);
    void add_particle(const RadiossBlock& b, std::uint32_t line, const std::vector<RadiossValue>& v);
    void add_element(const RadiossBlock& b, std::size_t card, std::uint32_t line, const std::vector<RadiossValue>& v);
    void add_group_members(const std::vector<RadiossValue>& v);
    void add_initial_state(const RadiossBlock& b, std::size_t card, std::uint32_t line,
                           const std::vector<RadiossValue>& v);

    // Per-block handlers.
    void end_begin(const RadiossBlock& b);
    void report_blank_version(const RadiossBlock& b, const RadiossValue& invers);
    void end_part(const RadiossBlock& b);
    void end_frame(const RadiossBlock& b);
    void end_group(const RadiossBlock& b);
    void end_sph_property(const RadiossBlock& b);
    void end_solid_property(const RadiossBlock& b, int type);
    void end_other_property(const RadiossBlock& b);
    void end_material(const RadiossBlock& b);
    void end_eos(const RadiossBlock& b);
    void end_sphglo(const RadiossBlock& b);
    void end_sphbcs(const RadiossBlock& b);
    void end_inout(const RadiossBlock& b);
    void end_reserve(const RadiossBlock& b);
    void end_dt(const RadiossBlock& b);

    // radioss_finish.cpp
    void resolve_particles();
    void resolve_frames();
    void resolve_planes();
    void resolve_groups();
    void resolve_links();
    void collect_surfaces();

    const grammar::RawDeck& deck_;
    std::vector<diag::Diagnostic>& out_;
    Model model_;
    RadiossFacts facts_;
    std::optional<long long> block_id_;       // the id of the open block, when it has one
    std::vector<long long> pending_members_;  // /GRNOD members of the open block
    std::vector<long long> pending_tetra10_;  // /TETRA10: the id line waiting for its nodes
    std::uint32_t pending_tetra10_line_ = 0;
    std::vector<std::pair<long long, std::vector<long long>>> part_groups_;  // /GRNOD/PART: id → parts
};

// "/MAT/HYD_VISC" → 6; -1 when unknown.
int radioss_law(std::string_view name);

}  // namespace sphdeck::model
