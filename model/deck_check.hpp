// The syntax pass over a read deck: every block with a schema has its cards decoded and
// checked (types, widths, ranges, card counts); unknown keywords are counted (DK001).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/keywords/schema.hpp"
#include "grammar/raw_deck.hpp"
#include "model/card_decoder.hpp"

namespace sphdeck::model {

struct DeckSummary {
    std::size_t particles = 0;         // *ELEMENT_SPH particles, NEND ranges expanded
    std::size_t unknown_keywords = 0;  // blocks without a schema
};

// Called for every decoded card: the block, its keyword match, the card spec and the values.
using CardVisitor = std::function<void(const grammar::Block&, const keywords::KeywordMatch&, const keywords::CardSpec&,
                                       grammar::CardLinePtr, const std::vector<FieldValue>&)>;

// Receives the cards of big blocks made of one repeated card (*NODE, *ELEMENT_SPH: millions of
// lines), which check_deck decodes on several threads. begin() and end() run on the calling
// thread; line() runs concurrently, once per line index, so it may only write that line's slot.
class BulkVisitor {
public:
    virtual ~BulkVisitor() = default;
    virtual bool wants(const keywords::KeywordMatch& match) const = 0;
    virtual void begin(const grammar::Block& block, std::size_t lines, int threads) = 0;
    virtual void line(const grammar::Block& block, std::size_t index, int thread, const grammar::CardLine& line,
                      const std::vector<FieldValue>& values) = 0;
    // line() for a line CardDecoder::read_row read (its FieldValues would hold these numbers and flags) that
    // stands for one node or particle (a particle's NEND blank). Same thread rules as line().
    virtual void row(const grammar::Block& block, std::size_t index, int thread, const PlainRow& row) = 0;
    // After every line(), before end(): the NEND range of line `index` is refused (the deck's
    // nodes cannot hold it); that line stands for NID alone.
    virtual void drop_range(std::size_t index) = 0;
    virtual void end(const grammar::Block& block) = 0;
    // Before begin(): whether the block's nodes or particles were copied from the last check instead
    // (model/bulk_reuse.hpp); then no line() follows. Only a block the last check decoded cleanly is.
    virtual bool reuse(const grammar::Block&, const keywords::CardSpec&) { return false; }
    // After end(): every line of the block took the plain path and made no finding and no NEND range.
    virtual void decoded_cleanly(const grammar::Block&, const keywords::CardSpec&) {}
    // When reuse() said no: whether the block's lines around an edit were copied from the last check;
    // then lines [first, last) of the block are left to line() (thread 0), and kept_around() says
    // whether they decoded cleanly (kept) or not (the copy undone: the block is decoded whole).
    struct Around {
        std::size_t first = 0, last = 0;
    };
    virtual std::optional<Around> reuse_around(const grammar::Block&, const keywords::CardSpec&) {
        return std::nullopt;
    }
    virtual bool kept_around(const grammar::Block&, const keywords::CardSpec&, bool) { return false; }
};

// Decodes every card of every known block, reporting into `out` in deck order; `visit` (optional)
// sees each decoded card in deck order, which is how the model is built without decoding twice.
// Blocks that `bulk` wants skip `visit` and go to `bulk` instead, decoded in parallel.
DeckSummary check_deck(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, const CardVisitor& visit = {},
                       BulkVisitor* bulk = nullptr);

}  // namespace sphdeck::model
