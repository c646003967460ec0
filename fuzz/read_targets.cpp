// The shallow deck targets: read and decode only (what engine::check_buffer does before the rules). Apart
// from targets.cpp so that their executables link the reading rooms alone (text, diag, grammar, model): the
// fuzzer then neither builds nor scans the coverage counters of the rules, renderers and editor code that
// these targets never run.
#include <string>
#include <vector>

#include "fuzz/targets.hpp"
#include "grammar/read_deck.hpp"
#include "model/model_builder.hpp"
#include "model/radioss_decoder.hpp"

namespace sphdeck::fuzz {
namespace {

// As in targets.cpp: relative includes resolve against a folder that does not exist.
constexpr const char* read_only_folder = "/nonexistent-sphdeck-fuzz";

void read_and_decode(const std::uint8_t* data, std::size_t size, const char* name, grammar::DeckFormat format) {
    const grammar::dyna::ReaderOptions options;
    const grammar::RawDeck deck =
        grammar::read_deck_buffer(std::string(reinterpret_cast<const char*>(data), size),
                                  std::string(read_only_folder) + "/" + name, read_only_folder, options, format);
    std::vector<diag::Diagnostic> found = deck.diagnostics;
    const model::Model model = format == grammar::DeckFormat::Radioss ? model::build_radioss_model(deck, found)
                                                                      : model::build_model(deck, found);
    volatile std::size_t sink = found.size() + model.particles.size();  // keep the decoding from being optimised away
    (void)sink;
}

}  // namespace

void read_dyna_deck(const std::uint8_t* data, std::size_t size) {
    read_and_decode(data, size, "fuzz.k", grammar::DeckFormat::LsDyna);
}

void read_radioss_deck(const std::uint8_t* data, std::size_t size) {
    read_and_decode(data, size, "fuzz_0000.rad", grammar::DeckFormat::Radioss);
}

}  // namespace sphdeck::fuzz
