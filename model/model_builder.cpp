#include "model/model_builder.hpp"

#include <algorithm>
#include <type_traits>

#include "grammar/number_cast.hpp"
#include "model/extract.hpp"
#include "model/particle_ranges.hpp"

namespace sphdeck::model {

namespace {
// The text a record keeps for a field: as written, except that a &name in an id field (an integer
// or label field: SECID, MID, NSID...) stands for the id it resolved to, so the rules that match
// ids by text see the id the solver reads (issue 26, class A).
std::string record_text(const FieldValue& v) {
    const bool id_field = v.spec->type == keywords::FieldType::Integer || v.spec->type == keywords::FieldType::Label;
    const bool reference =
        !v.text.empty() && (v.text[0] == '&' || (v.text.size() > 1 && v.text[0] == '-' && v.text[1] == '&'));
    if (id_field && reference && v.valid) return std::to_string(static_cast<long long>(v.number));
    return std::string(v.text);
}

// One block's lines are known before its cards are decoded: grow the arrays once, not by doubling.
void reserve_more(Nodes& n, std::size_t more) {
    const std::size_t size = n.id.size() + more;
    n.id.reserve(size), n.x.reserve(size), n.y.reserve(size), n.z.reserve(size);
}
void reserve_more(Particles& p, std::size_t more) {
    const std::size_t size = p.node.size() + more;
    p.node.reserve(size), p.part.reserve(size), p.mass.reserve(size), p.volume.reserve(size), p.line.reserve(size);
}

// Every column at `size` entries.
void resize_columns(Nodes& n, std::size_t size) {
    n.id.resize(size), n.x.resize(size), n.y.resize(size), n.z.resize(size);
}
void resize_columns(Particles& p, std::size_t size) {
    p.node.resize(size), p.part.resize(size), p.mass.resize(size), p.volume.resize(size), p.line.resize(size);
}

// A cleanly decoded block taken whole from where it was decoded before (the last check's model, or a
// shared block of the run): its `count` nodes or particles, one a line, from `from` in those columns.
// Returns the block's first slot in `n` or `p`.
std::size_t append_block(Nodes& n, const IdColumn& id, const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& z, std::size_t from, std::size_t count) {
    const std::size_t slot = n.id.size();
    const auto copy = [&](const auto& source, auto& target) {
        const auto begin = source.begin() + static_cast<std::ptrdiff_t>(from);
        target.insert(target.end(), begin, begin + static_cast<std::ptrdiff_t>(count));
    };
    n.id.append(id, from, count);
    copy(x, n.x), copy(y, n.y), copy(z, n.z);
    return slot;
}

// The same for particles; the block's keyword gives their volume flag, and its lines from `first_line`
// on (in RawDeck::lines) are theirs in this deck.
std::size_t append_block(Particles& p, const IdColumn& node, const IdColumn& part, const std::vector<double>& mass,
                         std::size_t from, std::size_t count, bool volume, std::uint32_t first_line) {
    const std::size_t slot = p.size();
    const auto begin = mass.begin() + static_cast<std::ptrdiff_t>(from);
    p.node.append(node, from, count), p.part.append(part, from, count);
    p.mass.insert(p.mass.end(), begin, begin + static_cast<std::ptrdiff_t>(count));
    p.volume.resize(slot + count, volume);
    p.line.append_run(count, first_line, 1);
    return slot;
}
}  // namespace

ModelBuilder::ModelBuilder(const grammar::RawDeck& deck, const BulkReuse* previous) : deck_(deck), previous_(previous) {
    model_.memory2_given = !deck.keyword_arguments.memory2.empty();
}

void ModelBuilder::add_node(const std::vector<FieldValue>& v) {
    if (v.size() < 4 || !v[0].valid) return;  // a node without a usable id is already reported
    Nodes& n = model_.nodes;
    n.id.push_back(grammar::saturating_integer<long long>(v[0].number));
    n.x.push_back(v[1].number);
    n.y.push_back(v[2].number);
    n.z.push_back(v[3].number);
}

void ModelBuilder::add_particles(const grammar::Block& block, const std::vector<FieldValue>& v, std::uint32_t index) {
    if (v.size() < 3 || !v[0].valid) return;
    Particles& p = model_.particles;
    const long long first = grammar::saturating_integer<long long>(v[0].number);
    // NEND > NID generates NID..NEND with the same part and mass (lsdyna-sph-cards.md §3); the
    // syntax pass has refused ranges the deck's nodes cannot hold.
    const long long last = first + static_cast<long long>(range_extra(v));
    const long long part = v[1].valid ? grammar::saturating_integer<long long>(v[1].number) : -1;
    const bool volume = block.keyword.find("_VOLUME") != std::string::npos;
    for (long long id = first; id <= last; ++id) {
        p.node.push_back(id);
        p.part.push_back(part);
        p.mass.push_back(v[2].valid ? v[2].number : 0.0);
        p.volume.push_back(volume);
        p.line.push_back(index);
    }
}

void ModelBuilder::on_card(const grammar::Block& block, const keywords::KeywordMatch& match, const keywords::CardSpec&,
                           grammar::CardLinePtr line, const std::vector<FieldValue>& values) {
    // Generated layouts are checked, not read into the model, but the ids they name are followed.
    if (match.schema->generated) return links_.on_card(match, values);
    const std::string_view name = match.schema->name;
    const bool new_block = current_block_ != &block;
    current_block_ = &block;
    if (name == "*NODE") {
        if (new_block) reserve_more(model_.nodes, block.line_count);
        return add_node(values);
    }
    if (name == "*ELEMENT_SPH") {
        if (new_block) reserve_more(model_.particles, block.line_count);
        return add_particles(block, values, line.index());
    }
    // Hand-written schemas may mark ids too (*DEFINE_SPH_MESH_BOX IPID): followed like generated ones.
    for (const FieldValue& v : values)
        if (!v.spec->refers_to.empty()) {
            links_.on_card(match, values);
            break;
        }
    if (new_block) {
        current_block_ = &block;
        KeywordRecord record;
        record.schema = match.schema;
        record.keyword = block.keyword;
        for (const auto* option : match.options) record.options.push_back(option->suffix);
        record.span = block.span;
        model_.records.push_back(std::move(record));
    }
    std::vector<FieldRecord> row;
    row.reserve(values.size());
    for (const FieldValue& v : values) {
        if (v.spec->type == keywords::FieldType::Unused) continue;
        row.push_back(
            FieldRecord{v.spec->name, v.spec->type, v.number, record_text(v), v.explicit_value, v.valid, v.span});
    }
    model_.records.back().rows.push_back(std::move(row));
}

bool ModelBuilder::Bulk::wants(const keywords::KeywordMatch& match) const {
    return match.schema->name == "*NODE" || match.schema->name == "*ELEMENT_SPH";
}

void ModelBuilder::Bulk::begin(const grammar::Block& block, std::size_t lines, int threads) {
    begin_slots(block, lines, threads, true);
}

void ModelBuilder::Bulk::begin_slots(const grammar::Block& block, std::size_t lines, int threads, bool runs) {
    particles_ = block.keyword.rfind("*ELEMENT_SPH", 0) == 0;
    volume_ = block.keyword.find("_VOLUME") != std::string::npos;
    irregular_.assign(static_cast<std::size_t>(threads), {});
    wide_.assign(static_cast<std::size_t>(threads), {});
    // A long block's ids are kept as runs while they are: its id columns are sized only when one ends.
    deferred_ids_ = runs && lines >= IdColumn::compact_min_entries;
    lines_ = lines;
    runs_.assign(deferred_ids_ ? static_cast<std::size_t>(threads) : 0, {});
    run_ended_.assign(deferred_ids_ ? static_cast<std::size_t>(threads) : 0, {});
    opened_ = {};
    if (particles_) {
        Particles& p = owner_.model_.particles;
        base_ = p.size();
        if (deferred_ids_) {
            p.mass.resize(base_ + lines), p.volume.resize(base_ + lines), p.line.resize(base_ + lines);
        } else {
            resize_columns(p, base_ + lines);
        }
        // One particle a line: the block's lines are one run (an irregular line is undone in end()).
        p.line.resize(base_);
        p.line.append_run(lines, block.first_line, 1);
    } else {
        Nodes& n = owner_.model_.nodes;
        base_ = n.id.size();
        if (deferred_ids_)
            n.x.resize(base_ + lines), n.y.resize(base_ + lines), n.z.resize(base_ + lines);
        else
            resize_columns(n, base_ + lines);
    }
}

IdColumn& ModelBuilder::Bulk::id_column(int c) {
    Model& m = owner_.model_;
    return !particles_ ? m.nodes.id : c == 0 ? m.particles.node : m.particles.part;
}

void ModelBuilder::Bulk::open_id_column(int c) {
    const std::lock_guard lock(opening_);
    if (opened_[static_cast<std::size_t>(c)]) return;
    id_column(c).resize(base_ + lines_);
    opened_[static_cast<std::size_t>(c)] = true;
}

void ModelBuilder::Bulk::write_run(int c, int thread, const IdRun& run) {
    IdColumn& column = id_column(c);
    for (std::size_t k = 0; k < run.count; ++k) {
        const std::size_t slot = base_ + run.start + k;
        if (!column.set_narrow(slot, run.at(k)))
            wide_[static_cast<std::size_t>(thread)].push_back({slot, run.at(k), c == 1});
    }
}

void ModelBuilder::Bulk::settle_id_columns() {
    if (!deferred_ids_) return;
    deferred_ids_ = false;
    for (int c = 0; c < (particles_ ? 2 : 1); ++c) {
        const auto at = static_cast<std::size_t>(c);
        // The threads' runs, in line order, chained into one (every line gave an id): the column is that.
        bool chained = base_ == 0 && !opened_[at] && id_column(c).empty();
        std::size_t next = 0;
        long long first = 0, step = 0;
        for (std::size_t t = 0; t < runs_.size() && chained; ++t) {
            const IdRun& run = runs_[t][at];
            if (run.count == 0) continue;
            if (run.start != next) chained = false;
            if (next == 0) {
                first = run.first, step = run.count > 1 ? run.step : 0;
            } else {
                if (next == 1) step = run.first - first;  // the first run was one id
                chained = chained && run.first == first + step * static_cast<long long>(run.start) &&
                          (run.count < 2 || run.step == step);
            }
            next = run.end();
        }
        if (chained && next == lines_) {
            id_column(c).assign_sequence(first, step, lines_);
            continue;
        }
        open_id_column(c);
        for (std::size_t t = 0; t < runs_.size(); ++t)
            if (!run_ended_[t][at]) write_run(c, static_cast<int>(t), runs_[t][at]);
    }
    runs_.clear(), run_ended_.clear();
}

template <typename Field>
void ModelBuilder::Bulk::put(std::size_t index, int thread, std::size_t count, const Field& field) {
    const std::size_t slot = base_ + index;
    auto& irregular = irregular_[static_cast<std::size_t>(thread)];
    auto& wide = wide_[static_cast<std::size_t>(thread)];
    // An id too wide for its column's 4 bytes is set after the threads (IdColumn::set_narrow). While the
    // thread's ids of a column run on (IdRun), nothing is written; the first that does not, writes them out.
    const auto set = [&](IdColumn& column, bool is_part, long long id) {
        if (deferred_ids_) {
            const int c = is_part ? 1 : 0;
            const auto t = static_cast<std::size_t>(thread);
            IdRun& run = runs_[t][static_cast<std::size_t>(c)];
            if (!run_ended_[t][static_cast<std::size_t>(c)]) {
                if (run.extend(index, id)) return;
                open_id_column(c);
                write_run(c, thread, run);
                run_ended_[t][static_cast<std::size_t>(c)] = 1;
            }
        }
        if (!column.set_narrow(slot, id)) wide.push_back({slot, id, is_part});
    };
    const auto [id_valid, id] = field(0);
    if (!particles_) {
        if (count < 4 || !id_valid) return irregular.push_back({index, 0, true});  // as add_node
        Nodes& n = owner_.model_.nodes;
        set(n.id, false, grammar::saturating_integer<long long>(id));
        n.x[slot] = field(1).second, n.y[slot] = field(2).second, n.z[slot] = field(3).second;
        return;
    }
    if (count < 3 || !id_valid) return irregular.push_back({index, 0, true});  // as add_particles
    Particles& p = owner_.model_.particles;
    const long long node = grammar::saturating_integer<long long>(id);
    set(p.node, false, node);
    const auto [part_valid, part] = field(1);
    set(p.part, true, part_valid ? grammar::saturating_integer<long long>(part) : -1);
    const auto [mass_valid, mass] = field(2);
    p.mass[slot] = mass_valid ? mass : 0.0;
    p.volume[slot] = volume_;
    // The particle's line is the block's run laid in begin(): first_line + index. An NEND range: line().
}

void ModelBuilder::Bulk::line(const grammar::Block&, std::size_t index, int thread, const grammar::CardLine&,
                              const std::vector<FieldValue>& v) {
    put(index, thread, v.size(), [&](std::size_t i) { return std::pair<bool, double>(v[i].valid, v[i].number); });
    if (particles_ && v.size() >= 3 && v[0].valid)
        if (const std::size_t extra = range_extra(v))
            irregular_[static_cast<std::size_t>(thread)].push_back(
                {index, grammar::saturating_integer<long long>(v[0].number) + static_cast<long long>(extra), false});
}

void ModelBuilder::Bulk::row(const grammar::Block&, std::size_t index, int thread, const PlainRow& r) {
    // A row stands for one node or particle: no NEND range.
    put(index, thread, r.count, [&](std::size_t i) { return std::pair<bool, double>(r.is_valid(i), r.number[i]); });
}

void ModelBuilder::Bulk::drop_range(std::size_t index) {
    for (auto& list : irregular_) {
        auto it = std::lower_bound(list.begin(), list.end(), index,
                                   [](const Irregular& entry, std::size_t i) { return entry.index < i; });
        if (it != list.end() && it->index == index && !it->skipped) return void(list.erase(it));
    }
}

void ModelBuilder::Bulk::set_wide_ids() {
    for (const auto& list : wide_)
        for (const WideId& w : list) {
            if (!particles_)
                owner_.model_.nodes.id.set(w.slot, w.id);
            else
                (w.part ? owner_.model_.particles.part : owner_.model_.particles.node).set(w.slot, w.id);
        }
    wide_.clear();
}

void ModelBuilder::Bulk::end(const grammar::Block&) {
    settle_id_columns();
    set_wide_ids();
    bool regular = true;
    for (const auto& list : irregular_) regular = regular && list.empty();
    if (!regular && particles_) end_particles();
    if (!regular && !particles_) end_nodes();
    irregular_.clear();
}

bool ModelBuilder::Bulk::reuse(const grammar::Block& block, const keywords::CardSpec& card) {
    if (!owner_.previous_) return owner_.shared_ && reuse_shared(block, card);
    const DecodedBulkBlock* same = same_bulk_block(*owner_.previous_, owner_.deck_, block, card);
    if (!same) return false;
    // A clean block is one entry a line: its particles' lines are this block's, wherever it moved.
    const Model& before = owner_.previous_->model;
    const bool particles = block.keyword.rfind("*ELEMENT_SPH", 0) == 0;
    // Columns a re-check before this one took (BulkReuse::take_from) are gone: decoded again.
    if (same->first_slot + same->line_count > (particles ? before.particles.size() : before.nodes.id.size()))
        return false;
    if (take_whole(*same, particles, block.first_line)) {
        owner_.decoded_bulk_.push_back(decoded_bulk_block(owner_.deck_, block, card, 0));
        return true;
    }
    const std::size_t slot = particles
                                 ? append_block(owner_.model_.particles, before.particles.node, before.particles.part,
                                                before.particles.mass, same->first_slot, same->line_count,
                                                block.keyword.find("_VOLUME") != std::string::npos, block.first_line)
                                 : append_block(owner_.model_.nodes, before.nodes.id, before.nodes.x, before.nodes.y,
                                                before.nodes.z, same->first_slot, same->line_count);
    owner_.decoded_bulk_.push_back(decoded_bulk_block(owner_.deck_, block, card, slot));
    return true;
}

// The whole of a column of the last model, which its owner drops after this check, moved instead of
// copied: only into empty columns, from a block that is all of its column (one *NODE, one
// *ELEMENT_SPH block: the big decks' shape). A clean block's particles all carry its keyword's volume
// flag; their lines are this block's run.
bool ModelBuilder::Bulk::take_whole(const DecodedBulkBlock& same, bool particles, std::uint32_t first_line) {
    const BulkReuse& previous = *owner_.previous_;
    if (!previous.take_from || !previous.taken || same.first_slot != 0) return false;
    Model& before = *previous.take_from;
    Model& now = owner_.model_;
    if (particles) {
        if (now.particles.size() != 0 || same.line_count != before.particles.size()) return false;
        now.particles.node = std::move(before.particles.node);
        now.particles.part = std::move(before.particles.part);
        now.particles.mass = std::move(before.particles.mass);
        now.particles.volume = std::move(before.particles.volume);
        now.particles.line = ParticleLines{};
        now.particles.line.append_run(same.line_count, first_line, 1);
        before.particles = Particles{};
        previous.taken->particles = true;
        previous.taken->particle_count = same.line_count;
    } else {
        if (now.nodes.id.size() != 0 || same.line_count != before.nodes.id.size()) return false;
        now.nodes = std::move(before.nodes);
        before.nodes = Nodes{};
        previous.taken->nodes = true;
        previous.taken->node_count = same.line_count;
    }
    return true;
}

// The block as another deck of the run decoded it: its columns appended, its particles' lines its own.
bool ModelBuilder::Bulk::reuse_shared(const grammar::Block& block, const keywords::CardSpec& card) {
    std::shared_ptr<const SharedBulkBlock> kept = owner_.shared_->find(owner_.deck_, block, card);
    if (!kept) return false;
    const std::size_t slot =
        kept->particles ? append_block(owner_.model_.particles, kept->ids, kept->part, kept->mass, 0, kept->ids.size(),
                                       kept->volume != 0, block.first_line)
                        : append_block(owner_.model_.nodes, kept->ids, kept->x, kept->y, kept->z, 0, kept->ids.size());
    owner_.decoded_bulk_.push_back(decoded_bulk_block(owner_.deck_, block, card, slot));
    owner_.provenance_.add(std::move(kept));
    return true;
}

void ModelBuilder::Bulk::decoded_cleanly(const grammar::Block& block, const keywords::CardSpec& card) {
    owner_.decoded_bulk_.push_back(decoded_bulk_block(owner_.deck_, block, card, base_));
    if (owner_.shared_) owner_.provenance_.add(owner_.shared_->offer(owner_.deck_, block, card, owner_.model_, base_));
}

std::optional<BulkVisitor::Around> ModelBuilder::Bulk::reuse_around(const grammar::Block& block,
                                                                    const keywords::CardSpec& card) {
    const BulkReuse* previous = owner_.previous_;
    if (!previous || !previous->changed) return std::nullopt;
    const grammar::SplicedLines& changed = *previous->changed;
    const std::size_t added = changed.new_card_end - changed.first_card;
    const std::size_t removed = changed.old_card_end - changed.first_card;
    for (const DecodedBulkBlock& before : previous->blocks) {
        // The block the edit fell in: the lines before the edit are the same, those after it moved.
        if (before.card != &card || before.format != block.format || before.keyword != block.keyword ||
            before.file != changed.file || before.first_line != block.first_line ||
            changed.first_card < before.first_line || changed.old_card_end > before.first_line + before.line_count ||
            std::size_t{block.line_count} + removed != std::size_t{before.line_count} + added ||
            block.line_count == 0 || owner_.deck_.begin_lines(block)->file != changed.file)
            continue;
        begin_slots(block, block.line_count, 1, false);  // the block's slots, as for a block decoded on one thread
        const std::size_t head = changed.first_card - before.first_line;  // lines before the edit
        const std::size_t tail = before.line_count - (changed.old_card_end - before.first_line);
        const std::size_t old_tail = before.first_slot + (changed.old_card_end - before.first_line);
        const std::size_t new_tail = head + added;
        const auto copy = [&](const auto& source, auto& target) {
            if constexpr (std::is_same_v<std::decay_t<decltype(target)>, IdColumn>) {
                target.copy_from(source, before.first_slot, head, base_);
                target.copy_from(source, old_tail, tail, base_ + new_tail);
            } else {
                const auto from = source.begin() + static_cast<std::ptrdiff_t>(before.first_slot);
                std::copy(from, from + static_cast<std::ptrdiff_t>(head),
                          target.begin() + static_cast<std::ptrdiff_t>(base_));
                const auto rest = source.begin() + static_cast<std::ptrdiff_t>(old_tail);
                std::copy(rest, rest + static_cast<std::ptrdiff_t>(tail),
                          target.begin() + static_cast<std::ptrdiff_t>(base_ + new_tail));
            }
        };
        if (particles_) {
            const Particles& old = previous->model.particles;
            Particles& p = owner_.model_.particles;
            copy(old.node, p.node), copy(old.part, p.part), copy(old.mass, p.mass), copy(old.volume, p.volume);
            // A clean block is one particle a line: the lines are the block's run that begin() laid.
        } else {
            const Nodes& old = previous->model.nodes;
            Nodes& n = owner_.model_.nodes;
            copy(old.id, n.id), copy(old.x, n.x), copy(old.y, n.y), copy(old.z, n.z);
        }
        return Around{head, head + added};
    }
    return std::nullopt;
}

bool ModelBuilder::Bulk::kept_around(const grammar::Block& block, const keywords::CardSpec& card, bool clean) {
    set_wide_ids();
    for (const auto& list : irregular_) clean = clean && list.empty();
    irregular_.clear();
    if (clean) {
        owner_.decoded_bulk_.push_back(decoded_bulk_block(owner_.deck_, block, card, base_));
        return true;
    }
    if (particles_)
        resize_columns(owner_.model_.particles, base_);
    else
        resize_columns(owner_.model_.nodes, base_);
    return false;
}

// Threads own contiguous ranges of lines in thread order, so the concatenated lists are sorted.
void ModelBuilder::Bulk::end_nodes() {
    Nodes& n = owner_.model_.nodes;
    std::size_t write = base_, read = base_;
    for (const auto& list : irregular_)
        for (const Irregular& skip : list) {
            for (; read < base_ + skip.index; ++read, ++write)
                n.id.set(write, n.id[read]), n.x[write] = n.x[read], n.y[write] = n.y[read], n.z[write] = n.z[read];
            ++read;  // the skipped line's slot
        }
    for (; read < n.id.size(); ++read, ++write)
        n.id.set(write, n.id[read]), n.x[write] = n.x[read], n.y[write] = n.y[read], n.z[write] = n.z[read];
    resize_columns(n, write);
}

// Skipped lines drop out and NEND ranges expand (NID..NEND, same part and mass): rebuilt in order.
void ModelBuilder::Bulk::end_particles() {
    Particles& p = owner_.model_.particles;
    Particles rebuilt;
    auto copy = [&](std::size_t from, long long id) {
        rebuilt.node.push_back(id), rebuilt.part.push_back(p.part[from]), rebuilt.mass.push_back(p.mass[from]);
        rebuilt.volume.push_back(p.volume[from]), rebuilt.line.push_back(p.line[from]);
    };
    std::size_t read = base_;
    for (const auto& list : irregular_)
        for (const Irregular& entry : list) {
            for (; read < base_ + entry.index; ++read) copy(read, p.node[read]);
            if (!entry.skipped)
                for (long long id = p.node[read]; id <= entry.last; ++id) copy(read, id);
            ++read;
        }
    for (; read < p.size(); ++read) copy(read, p.node[read]);
    resize_columns(p, base_);
    p.node.append(rebuilt.node, 0, rebuilt.node.size()), p.part.append(rebuilt.part, 0, rebuilt.part.size());
    p.mass.insert(p.mass.end(), rebuilt.mass.begin(), rebuilt.mass.end());
    p.volume.insert(p.volume.end(), rebuilt.volume.begin(), rebuilt.volume.end());
    for (std::uint32_t line : rebuilt.line.all()) p.line.push_back(line);
}

Model ModelBuilder::finish(std::vector<diag::Diagnostic>& out) {
    model_.id_references = links_.take();
    extract_typed(deck_, model_, out);
    compact_bulk_ids(model_);
    return std::move(model_);
}

Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary) {
    std::vector<DecodedBulkBlock> decoded;
    return build_model(deck, out, summary, nullptr, decoded);
}

Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary,
                  const BulkReuse* previous, std::vector<DecodedBulkBlock>& decoded) {
    return build_model(deck, out, summary, previous, decoded, nullptr, nullptr);
}

Model build_model(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, DeckSummary* summary,
                  const BulkReuse* previous, std::vector<DecodedBulkBlock>& decoded, SharedBulkBlocks* shared,
                  BulkProvenance* provenance) {
    ModelBuilder builder(deck, previous);
    builder.share_bulk_with(shared);
    DeckSummary s = check_deck(
        deck, out,
        [&](const grammar::Block& b, const keywords::KeywordMatch& m, const keywords::CardSpec& c,
            grammar::CardLinePtr l, const std::vector<FieldValue>& v) { builder.on_card(b, m, c, l, v); },
        &builder.bulk_visitor());
    if (summary) *summary = s;
    Model model = builder.finish(out);
    decoded = builder.take_decoded_bulk();
    if (provenance) *provenance = builder.provenance();
    return model;
}

}  // namespace sphdeck::model
