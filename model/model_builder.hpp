// Builds the Model while the syntax pass decodes the cards (one decode per line), then turns
// the keyword records into the typed parts of the model.
#pragma once

#include <array>
#include <mutex>
#include <vector>

#include "diag/diagnostic.hpp"
#include "grammar/raw_deck.hpp"
#include "model/bulk_reuse.hpp"
#include "model/deck_check.hpp"
#include "model/id_run.hpp"
#include "model/model.hpp"
#include "model/shared_bulk.hpp"

namespace sphdeck::model {

class ModelBuilder {
public:
    // `previous`: the last check, whose cleanly decoded bulk blocks are copied where unchanged (the
    // editor's re-check, model/bulk_reuse.hpp); null decodes every block.
    explicit ModelBuilder(const grammar::RawDeck& deck, const BulkReuse* previous = nullptr);

    // The CardVisitor of check_deck.
    void on_card(const grammar::Block& block, const keywords::KeywordMatch& match, const keywords::CardSpec& card,
                 grammar::CardLinePtr line, const std::vector<FieldValue>& values);

    // Typed extraction; reports model-level findings (IDIM without a value) into `out`.
    Model finish(std::vector<diag::Diagnostic>& out);

    // Big *NODE and *ELEMENT_SPH blocks, decoded in parallel by check_deck.
    BulkVisitor& bulk_visitor() { return bulk_; }

    // The bulk blocks decoded cleanly or copied, for the next re-check (after finish()).
    std::vector<DecodedBulkBlock> take_decoded_bulk() { return std::move(decoded_bulk_); }

    // The run's shared bulk blocks (model/shared_bulk.hpp): a block kept there is copied from it, a
    // block decoded cleanly is offered to it. Before the first card.
    void share_bulk_with(SharedBulkBlocks* shared) { shared_ = shared; }
    // The shared blocks the nodes and particles came from (after finish()).
    const BulkProvenance& provenance() const { return provenance_; }

private:
    // Writes each line's node or particle into a slot sized in advance; lines that are not exactly
    // one entry (an unreadable id, an NEND range) are rare and are fixed up in end(), in order.
    class Bulk : public BulkVisitor {
    public:
        explicit Bulk(ModelBuilder& owner) : owner_(owner) {}
        bool wants(const keywords::KeywordMatch& match) const override;
        void begin(const grammar::Block& block, std::size_t lines, int threads) override;
        void line(const grammar::Block& block, std::size_t index, int thread, const grammar::CardLine& line,
                  const std::vector<FieldValue>& values) override;
        void row(const grammar::Block& block, std::size_t index, int thread, const PlainRow& row) override;
        void drop_range(std::size_t index) override;
        void end(const grammar::Block& block) override;
        bool reuse(const grammar::Block& block, const keywords::CardSpec& card) override;
        void decoded_cleanly(const grammar::Block& block, const keywords::CardSpec& card) override;
        std::optional<Around> reuse_around(const grammar::Block& block, const keywords::CardSpec& card) override;
        bool kept_around(const grammar::Block& block, const keywords::CardSpec& card, bool clean) override;

    private:
        struct Irregular {
            std::size_t index;   // line in the block
            long long last = 0;  // last id of an NEND range; unused for a skipped line
            bool skipped = false;
        };
        struct WideId {  // an id that did not fit its column's 4 bytes, set after the threads
            std::size_t slot;
            long long id;
            bool part;  // the particles' part column (else the ids or the particles' nodes)
        };
        // line() and row(): the line's `count` fields, field i's FieldValue::valid and number given by `field(i)`.
        template <typename Field>
        void put(std::size_t index, int thread, std::size_t count, const Field& field);
        // begin(); `runs`: the id columns kept as runs while they are (the parallel decoding's blocks).
        void begin_slots(const grammar::Block& block, std::size_t lines, int threads, bool runs);
        // Column c of the ids: 0 the node ids or the particles' nodes, 1 the particles' parts.
        IdColumn& id_column(int c);
        void open_id_column(int c);  // sized for the block's lines, once (any thread)
        void write_run(int c, int thread, const IdRun& run);
        void settle_id_columns();  // after the threads: one sequence each, or written out
        void set_wide_ids();
        void end_nodes();
        void end_particles();
        bool reuse_shared(const grammar::Block& block, const keywords::CardSpec& card);
        bool take_whole(const DecodedBulkBlock& same, bool particles, std::uint32_t first_line);

        ModelBuilder& owner_;
        bool particles_ = false;
        bool volume_ = false;
        std::size_t base_ = 0;                           // first slot of the block in the arrays
        std::vector<std::vector<Irregular>> irregular_;  // per thread
        std::vector<std::vector<WideId>> wide_;          // per thread
        // The ids as runs (model/id_run.hpp) while deferred_ids_: per thread and id column, and whether the
        // run ended (the thread writes its ids into the column since). A column is sized only once one ends.
        bool deferred_ids_ = false;
        std::size_t lines_ = 0;
        std::vector<std::array<IdRun, 2>> runs_;
        std::vector<std::array<char, 2>> run_ended_;  // char: threads write their own
        std::mutex opening_;
        std::array<bool, 2> opened_{};  // under opening_
    };

    void add_node(const std::vector<FieldValue>& values);
    void add_particles(const grammar::Block& block, const std::vector<FieldValue>& values, std::uint32_t line);

    const grammar::RawDeck& deck_;
    Model model_;
    IdLinkCollector links_;
    const grammar::Block* current_block_ = nullptr;
    Bulk bulk_{*this};
    const BulkReuse* previous_ = nullptr;
    std::vector<DecodedBulkBlock> decoded_bulk_;
    SharedBulkBlocks* shared_ = nullptr;
    BulkProvenance provenance_;
};

// Reads the whole deck into a Model in one pass: decode + build. Diagnostics go to `out`.
Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary = nullptr);

// The same for the editor's re-check: `previous` as ModelBuilder's; `decoded` receives the bulk blocks
// the next re-check may copy.
Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary,
                  const BulkReuse* previous, std::vector<DecodedBulkBlock>& decoded);

// The same sharing the run's decoded bulk blocks (`shared`, may be null); `provenance` receives the
// shared blocks the nodes and particles came from.
Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary,
                  const BulkReuse* previous, std::vector<DecodedBulkBlock>& decoded, SharedBulkBlocks* shared,
                  BulkProvenance* provenance);

}  // namespace sphdeck::model
