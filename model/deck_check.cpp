#include "model/deck_check.hpp"
#include "model/flood_guard.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <numeric>
#include <string>

#include "grammar/lone_value_shift.hpp"
#include "grammar/shifted_line.hpp"
#include "grammar/value.hpp"
#include "model/card_sequence.hpp"
#include "model/blank_card.hpp"
#include "model/case_blocks.hpp"
#include "model/lost_asterisk.hpp"
#include "model/missing_card.hpp"
#include "model/missing_heading.hpp"
#include "model/particle_ranges.hpp"
#include "model/joined_lines.hpp"
#include "model/repeated_line.hpp"
#include "model/shift_diagnosis.hpp"
#include "model/unknown_keywords.hpp"
#include "text/text_window.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sphdeck::model {
namespace {

using keywords::CardRepeat;
using keywords::CardSpec;
using keywords::FieldType;

// Below this many lines a block is decoded on the calling thread: starting threads costs more.
constexpr std::size_t bulk_min_lines = 8192;

int available_threads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

// Whether NEND reads the same 8 wide (columns 33-40, a blank read as 0) as 10 wide (33-42): then
// the readers that disagree on its width agree on this line (LS-PrePost writes a `0` in column 42).
bool same_nend_both_widths(std::string_view text, const FieldValue& nend) {
    if (!nend.valid || text.size() <= 32) return false;
    const grammar::IntegerValue narrow = grammar::parse_integer(text.substr(32, 8));
    if (narrow.status == grammar::NumberStatus::Blank) return nend.number == 0;
    return narrow.status == grammar::NumberStatus::Ok && static_cast<double>(narrow.value) == nend.number;
}

// Particles one *ELEMENT_SPH card stands for (its range already checked), and the NEND width
// warning (DK023).
std::size_t count_particles(const grammar::RawDeck& deck, const grammar::CardLine& line, grammar::CardFormat format,
                            const std::vector<FieldValue>& values, std::vector<diag::Diagnostic>& out) {
    // NID, PID, MASS, NEND: NEND > NID generates the range NID..NEND.
    const std::size_t n = 1 + range_extra(values);
    // Sources disagree on NEND's width (lsdyna-format.md §3); we read 33-42 and flag 41-42. Text in
    // 41-42 makes NEND written, so the line is looked at again only then (this runs once per particle).
    if (format != grammar::CardFormat::Standard || values.size() < 4 || !values[3].explicit_value) return n;
    std::string_view text = deck.text(line);
    if (text.size() > 40 && !grammar::is_blank(text.substr(40, 2)) && !grammar::is_free_format(text) &&
        !same_nend_both_widths(text, values[3]))
        out.push_back({"DK023",
                       diag::Severity::Warning,
                       "NEND reaches columns 41-42; some readers stop NEND at column 40",
                       values[3].span,
                       {}});
    return n;
}

// The reader's findings on a parameter's name (undefined, its case): where the cards fall changes neither.
bool parameter_finding(const diag::Diagnostic& d) { return d.code == "DK012" || d.code == "DK024"; }

// Walks the lines of one block against its card sequence (model/card_sequence.hpp), decoding and
// reporting each line.
class BlockWalker {
public:
    BlockWalker(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, const CardVisitor& visit,
                BulkVisitor* bulk)
        : deck_(deck), out_(out), decoder_(deck, out), visit_(visit), bulk_(bulk) {}

    void walk(const grammar::Block& block, const keywords::KeywordMatch& match, DeckSummary& summary,
              FloodBound& bound) {
        suspects_.clear();
        lost_.clear();
        heading_ = {};
        blanks_.clear();
        copies_.clear();
        read_once_.clear();
        past_fields_.clear();
        early_.reset();
        const std::size_t walk_from = out_.size();
        CardSequence sequence(match);
        const std::vector<const CardSpec*>& cards = sequence.cards();
        if (bulk_ && bulk_->wants(match) && cards.size() == 1 && cards[0]->repeat == CardRepeat::Repeated &&
            !cards[0]->present_if && block.line_count >= bulk_min_lines)
            return walk_in_parallel(block, *cards[0], summary, bound);
        const bool particles = block.keyword.rfind("*ELEMENT_SPH", 0) == 0;
        // Blank lines after a whole group of repeated cards (*PART's heading and card 2) are spacing before the
        // next keyword, as blank lines past a keyword's last card are (report_extra), not a heading.
        grammar::CardLinePtr spacing_from = deck_.end_lines(block);
        while (spacing_from != deck_.begin_lines(block) && blank_card_line(deck_.text(spacing_from[-1])))
            --spacing_from;
        std::size_t walked = 0;
        for (grammar::CardLinePtr l = deck_.begin_lines(block); l != deck_.end_lines(block); ++l) {
            if (l == spacing_from && sequence.group_done()) break;
            if (++walked % trim_lines == 0) bound.trim(out_);
            const CardSpec* next = sequence.next();
            if (!next && sequence.layout_unknown()) {  // generated layout ends here
                note_lost_in_unread(deck_, block, l, lost_);
                return;
            }
            if (!next) {
                // The first line past the last card: a piece of the card above broken off, perhaps (DK038).
                if (!match.schema->generated && !blank_card_line(deck_.text(*l))) read_once_.push_back({l, nullptr});
                report_extra(block, l, cards.size());
                return;
            }
            const CardSpec& card = *next;
            note_lost_asterisk(*l, card.fields.empty() || card.fields[0].type == FieldType::Text);
            if (!heading_.line && sequence.card_after()) note_missing_heading(block, l, card, *sequence.card_after());
            note_blank_card(block, l, card);
            note_repeated_line(block, l, card);
            note_read_once(l, card, match);
            if (!early_ && out_.size() == walk_from) note_early_card(block, l, card, match, cards);
            const std::size_t found_before = out_.size();
            decoder_.decode(block, *l, card, values_);
            note_alignment(block, l, card,
                           std::any_of(out_.begin() + static_cast<std::ptrdiff_t>(found_before), out_.end(),
                                       [](const diag::Diagnostic& d) { return d.severity == diag::Severity::Error; }));
            note_suspect(block, l, card, out_.size() > found_before || decoder_.glued() || decoder_.text_past_fields());
            if (card.repeat == CardRepeat::Repeated && decoder_.text_past_fields()) note_past_fields(l);
            std::optional<diag::Diagnostic> refused;
            if (particles) refused = take_range(values_);
            sequence.advance(card, values_);  // conditions look at header cards
            if (visit_) visit_(block, match, card, l, values_);
            if (particles) summary.particles += count_particles(deck_, *l, block.format, values_, out_);
            if (refused) out_.push_back(std::move(*refused));  // last of the line's findings, as in parallel
        }
        if (const CardSpec* missing = sequence.missing_card()) report_missing(block, *missing);
    }

    // The lines the shift diagnosis looks at (model/shift_diagnosis.hpp), filled by walk().
    const std::vector<SuspectLine>& suspects() const { return suspects_; }
    // Lines that are keyword names without their '*' (model/lost_asterisk.hpp), filled by walk().
    const std::vector<LostAsteriskLine>& lost_asterisks() const { return lost_; }
    // A *PART heading that reads as the card after it (model/missing_heading.hpp), and that card.
    struct HeadingSuspect {
        grammar::CardLinePtr line = nullptr;
        const CardSpec* next = nullptr;
        bool reals_read_as_ids = false;  // the line after it, read as `next`, holds reals in its id fields
    };
    const HeadingSuspect& heading_suspect() const { return heading_; }
    // The first blank lines the walk read as cards read once, with a data line after them (model/blank_card.hpp).
    const std::vector<BlankCardLine>& blank_cards() const { return blanks_; }
    // The first data lines that repeat the line above them, read as cards read once (model/repeated_line.hpp).
    const std::vector<RepeatedLine>& repeated_lines() const { return copies_; }
    // The first lines of repeated cards with text between their fields' end and the last significant column
    // (model/joined_lines.hpp).
    const std::vector<grammar::CardLinePtr>& past_fields_lines() const { return past_fields_; }
    // The first data lines read as cards read once, hand-written layouts only (model/joined_lines.hpp), and the
    // first line past the keyword's last card (its card: none).
    const std::vector<ReadOnceLine>& read_once_lines() const { return read_once_; }
    // The first line read as a card before the one its `$#` ruler names, when no line above it made a finding
    // (model/missing_card.hpp).
    const std::optional<EarlyCardLine>& early_card() const { return early_; }

    // Whether the block's lines, `blank` left out, read without a finding: each decoded as the card the walk
    // would give it then (blocks of up to max_replayed_lines; longer ones: no). A parameter's name findings (one
    // defined in a deck that includes this file) say nothing of where the cards fall and are left out.
    bool reads_without(const grammar::Block& block, const keywords::KeywordMatch& match, grammar::CardLinePtr blank) {
        if (!replayable(block)) return false;
        std::vector<ReplayLine> lines;
        for (grammar::CardLinePtr l = deck_.begin_lines(block); l != deck_.end_lines(block); ++l)
            if (l != blank) lines.push_back({l, deck_.text(*l)});
        return replay(block, match, lines).has_value();
    }

    static bool replayable(const grammar::Block& block) {
        constexpr std::size_t max_replayed_lines = 1000;
        return block.line_count <= max_replayed_lines;
    }

    // The block read from `lines` (texts that may differ from the deck's: a line split in two, two lines joined):
    // the card each line is read as when every one reads without a finding (a parameter's name findings
    // aside, as above) and no card is missing; nothing otherwise. Lines past the last card are clean only
    // when blank (their card: none).
    std::optional<std::vector<const CardSpec*>> replay(const grammar::Block& block, const keywords::KeywordMatch& match,
                                                       std::span<const ReplayLine> lines) {
        std::vector<diag::Diagnostic> found;
        CardDecoder decoder(deck_, found);
        CardSequence sequence(match);
        std::vector<FieldValue> values;
        std::vector<const CardSpec*> cards;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const CardSpec* card = sequence.next();
            if (!card) {
                if (sequence.layout_unknown()) break;
                for (; i < lines.size(); ++i)
                    if (!blank_card_line(lines[i].text)) return std::nullopt;
                break;
            }
            decoder.decode_text(block, *lines[i].line, lines[i].text, *card, values);
            if (!std::all_of(found.begin(), found.end(), parameter_finding)) return std::nullopt;
            sequence.advance(*card, values);
            cards.push_back(card);
        }
        if (sequence.missing_card()) return std::nullopt;
        cards.resize(lines.size(), nullptr);
        return cards;
    }

    // DK029 for the lines of one value pushed into the next field, when (all but 1% of) the other numbers
    // the walk saw end at their field's end (grammar/lone_value_shift.hpp). Called once, after the last block.
    void report_lone_shifts() {
        constexpr std::uint64_t min_aligned = 4;  // a deck with fewer numbers shows no habit
        // A stray left-aligned number or two in a deck of hundreds is no habit of writing left.
        if (alignment_.right < min_aligned || alignment_.other * 100 > alignment_.right) return;
        for (const LoneCandidate& c : lone_) {
            // A line the `$#` header above already showed shifted (model/shift_diagnosis.cpp) is reported once.
            const bool reported = std::any_of(out_.begin(), out_.end(), [&](const diag::Diagnostic& d) {
                return d.code == "DK029" && d.span.file == c.line->file && d.span.line == c.line->line;
            });
            if (reported) continue;
            out_.push_back(lone_value_finding(deck_, *c.block, *c.line, *c.card, c.shift,
                                              layout_of(*c.card, c.block->format), c.refused));
        }
    }

private:
    struct LoneCandidate {
        const grammar::Block* block = nullptr;
        grammar::CardLinePtr line = nullptr;
        const CardSpec* card = nullptr;
        grammar::LoneShift shift;
        bool refused = false;  // the line as written makes an error (a required field left blank)
    };
    static constexpr std::size_t max_lone_candidates = 64;

    std::span<const grammar::FixedField> layout_of(const CardSpec& card, grammar::CardFormat format) {
        if (layout_card_ != &card || layout_format_ != format) {
            layout_card_ = &card, layout_format_ = format;
            layout_ = &card_layout(card, format);
        }
        return layout_->positions;
    }

    // A line from column 1 that is a keyword name without its '*' (only lines starting with a letter are looked up).
    void note_lost_asterisk(const grammar::CardLine& line, bool read_as_text) {
        constexpr std::size_t max_lost = 8;
        const std::string_view text = deck_.text(line);
        if (lost_.size() >= max_lost || text.empty() || !std::isalpha(static_cast<unsigned char>(text.front()))) return;
        if (auto lost = lost_asterisk_line(line.file, line.line, text, read_as_text)) lost_.push_back(std::move(*lost));
    }

    // A *PART heading line, or a `_TITLE` option's title line, that reads as the card after it: the heading or
    // title was left out.
    void note_missing_heading(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card,
                              const CardSpec& next) {
        // HEADING in the hand-written *PART, TITLE in generated layouts (*PART_INERTIA, *PART_CONTACT) and in
        // the title card a `_TITLE` option reads first.
        if (card.fields.empty() || (card.fields[0].name != "HEADING" && card.fields[0].name != "TITLE")) return;
        const std::string_view text = deck_.text(*line);
        if (block.keyword.rfind("*PART", 0) != 0) {
            if (card.fields[0].name == "TITLE" && reads_as_card(text, layout_of(next, block.format), next))
                heading_ = {line, &next, false};
            return;
        }
        if (!reads_as_integer_card(text, layout_of(next, block.format), next)) return;
        const bool reals = line + 1 != deck_.end_lines(block) &&
                           reals_in_id_fields(deck_.text(line[1]), layout_of(next, block.format), next);
        heading_ = {line, &next, reals};
    }

    // A blank line read as a card read once, with a data line after it in the block: spacing, perhaps.
    void note_blank_card(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card) {
        constexpr std::size_t max_blanks = 4;
        if (blanks_.size() >= max_blanks || card.repeat == CardRepeat::Repeated || !blank_card_line(deck_.text(*line)))
            return;
        const bool text_card = std::all_of(card.fields.begin(), card.fields.end(), [](const keywords::FieldSpec& f) {
            return f.type == FieldType::Text || f.type == FieldType::Unused;
        });
        for (grammar::CardLinePtr l = line + 1; l != deck_.end_lines(block); ++l)
            if (!blank_card_line(deck_.text(*l))) {
                blanks_.push_back({line, &card, text_card});
                return;
            }
    }

    // A line read as a card read once that repeats the line above it: a copy, perhaps.
    void note_repeated_line(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card) {
        constexpr std::size_t max_copies = 4;
        if (copies_.size() < max_copies && card.repeat != CardRepeat::Repeated &&
            repeats_line_above(deck_, block, line))
            copies_.push_back({line, &card});
    }

    void note_past_fields(grammar::CardLinePtr line) {
        constexpr std::size_t max_past_fields = 4;
        if (past_fields_.size() < max_past_fields) past_fields_.push_back(line);
    }

    // The lines a joined or split line's diagnosis tries to mend (model/joined_lines.hpp). Hand-written layouts
    // only, as note_early_card: a generated one may misread a deck the solver reads, and a mend may then read
    // cleanly by chance.
    void note_read_once(grammar::CardLinePtr line, const CardSpec& card, const keywords::KeywordMatch& match) {
        constexpr std::size_t max_read_once = 16;
        if (read_once_.size() < max_read_once && card.repeat != CardRepeat::Repeated && !match.schema->generated)
            read_once_.push_back({line, &card});
    }

    // A line read once as `card` whose `$#` ruler names a later card of the keyword (a card cut above it).
    // Hand-written layouts only: a generated one may hold a card the deck leaves out by a condition pydyna
    // does not state (*FREQUENCY_DOMAIN_FRF's N11 card), and the ruler would then be right and the layout not.
    void note_early_card(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card,
                         const keywords::KeywordMatch& match, const std::vector<const CardSpec*>& cards) {
        if (card.repeat == CardRepeat::Repeated || match.schema->generated) return;
        early_ = early_card_line(deck_, block, line, card, cards);
    }

    // Tallies how the line's numbers sit in their fields, or keeps it as a lone shifted value. `refused`: the
    // line as written made an error.
    void note_alignment(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card, bool refused) {
        if (card.fields.empty() || (card.fields[0].type == FieldType::Text && card.fields[0].width >= 70)) return;
        const std::string_view text = deck_.text(*line);
        const auto slots = layout_of(card, block.format);
        // A lone value read as an integer written as a real (DK004) is still lone.
        if (lone_.size() < max_lone_candidates)
            if (auto lone = grammar::find_lone_shift(text, slots, layout_->types)) {
                lone_.push_back({&block, line, &card, std::move(*lone), refused});
                return;
            }
        if (!grammar::is_free_format(text)) grammar::tally_alignment(text, slots, layout_->types, alignment_);
    }

    // A line that made a finding, or the first line of a card under a `$#` header (one a block for
    // repeated cards: the header check reads back over the line above).
    void note_suspect(const grammar::Block& block, grammar::CardLinePtr line, const CardSpec& card, bool found) {
        if (suspects_.size() >= max_suspect_lines) return;
        if (!suspects_.empty() && suspects_.back().line == line) return;
        const bool first_of_card = card.repeat != CardRepeat::Repeated || line == deck_.begin_lines(block);
        if (found || (first_of_card && !header_above(deck_, *line).empty())) suspects_.push_back({line, &card});
    }

    // The bulk path: the lines of the first findings (the lines of a block are in file order).
    void note_bulk_suspects(const grammar::Block& block, const CardSpec& card, std::size_t from) {
        grammar::CardLinePtr begin = deck_.begin_lines(block);
        grammar::CardLinePtr end = deck_.end_lines(block);
        for (std::size_t i = from; i < out_.size() && suspects_.size() < max_suspect_lines; ++i) {
            const grammar::Span& at = out_[i].span;
            if (!suspects_.empty() && suspects_.back().line->line == at.line) continue;
            grammar::CardLinePtr l =
                std::lower_bound(begin, end, at.line,
                                 [](const grammar::CardLine& c, std::uint32_t n) { return c.line < n; });
            if (l != end && l->line == at.line && l->file == at.file) suspects_.push_back({l, &card});
        }
    }

    // A refused NEND range is reported and its NEND marked unusable, so that neither the model
    // nor the particle count expands it.
    std::optional<diag::Diagnostic> take_range(std::vector<FieldValue>& values) {
        auto problem = ranges_.take(range_extra(values));
        if (!problem) return std::nullopt;
        values[3].valid = false;
        return range_error(values[3].span, *problem);
    }

    // Every line of `block` is one `card`: contiguous ranges of lines go to the threads, and their
    // findings are appended range after range, so the order is the same as on one thread.
    void walk_in_parallel(const grammar::Block& block, const CardSpec& card, DeckSummary& summary, FloodBound& bound) {
        const std::size_t n = block.line_count;
        const bool particles = block.keyword.rfind("*ELEMENT_SPH", 0) == 0;
        // Decoded cleanly last time (no finding, one particle a line): copied, or copied around an edit.
        if (bulk_->reuse(block, card) || decode_around(block, card, particles)) {
            if (particles) summary.particles += n;
            return;
        }
        const int threads = available_threads();
        std::vector<std::vector<diag::Diagnostic>> found(static_cast<std::size_t>(threads));
        std::vector<FloodBound> bounds(static_cast<std::size_t>(threads), FloodBound(0));
        std::vector<std::size_t> counted(static_cast<std::size_t>(threads), 0);
        std::vector<char> all_plain(static_cast<std::size_t>(threads), 1);  // char: threads write their own
        std::vector<std::vector<std::size_t>> past_fields(static_cast<std::size_t>(threads));  // first few a thread
        const grammar::CardLinePtr lines = deck_.begin_lines(block);
        // Ranges longer than the deck's nodes are refused on the threads; the deck's running
        // budget is spent afterwards, range by range in line order.
        struct Range {
            std::size_t index, extra;
            grammar::Span nend;
        };
        std::vector<std::vector<Range>> ranges(static_cast<std::size_t>(threads));
        if (particles) ranges_.nodes();
        bulk_->begin(block, n, threads);
#pragma omp parallel num_threads(threads)
        {
#ifdef _OPENMP
            const int t = omp_get_thread_num();
            const int team = omp_get_num_threads();
#else
            const int t = 0, team = 1;
#endif
            const std::size_t first = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(team);
            const std::size_t last = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(team);
            auto& out = found[static_cast<std::size_t>(t)];
            CardDecoder decoder(deck_, out);
            std::vector<FieldValue> values;
            PlainRow row;
            std::size_t count = 0;
            std::size_t released = first;  // lines whose text went back (a mapped file's pages)
            FloodBound& trimmed = bounds[static_cast<std::size_t>(t)];
            grammar::CardLinePtr at = lines + static_cast<std::ptrdiff_t>(first);  // line i: this thread's own walk
            // The block's text read through a window of the thread's own (text/text_window.hpp).
            const text::FileId file = lines->file;
            text::TextWindow window(deck_.sources.file(file).text);
            // What decode_bulk would do with a line read_row did not take whole, without trying again.
            const auto decode_line = [&](std::size_t i, const grammar::CardLine& line, const grammar::CardLine* next,
                                         CardDecoder::RowRead read) {
                if (read == CardDecoder::RowRead::NotPlain) {
                    decoder.decode(block, line, card, values);
                    all_plain[static_cast<std::size_t>(t)] = 0;
                } else if (!decoder.decode_bulk(block, line, card, values, next)) {
                    all_plain[static_cast<std::size_t>(t)] = 0;
                }
                if (auto& past = past_fields[static_cast<std::size_t>(t)];
                    decoder.text_past_fields() && past.size() < 4)
                    past.push_back(i);
                std::optional<std::string> refused;
                if (particles) {
                    refused = ranges_.check_alone(range_extra(values));
                    if (refused)
                        values[3].valid = false;
                    else if (std::size_t extra = range_extra(values))
                        ranges[static_cast<std::size_t>(t)].push_back({i, extra, values[3].span});
                }
                bulk_->line(block, i, t, line, values);
                if (particles) count += count_particles(deck_, line, block.format, values, out);
                if (refused) out.push_back(range_error(values[3].span, *refused));
            };
            // Line i, `next` the block's line after it (where it ends, known) and `through_next` the bytes from
            // its start to next's, when held. Most lines: numbers only, one node or particle (a particle's NEND
            // blank: no range, no DK023).
            const auto take = [&](std::size_t i, const grammar::CardLine& line, const grammar::CardLine* next,
                                  std::string_view through_next) {
                if (i - released == release_lines) release_text(lines[released], line), released = i;
                if ((i - first + 1) % trim_lines == 0) trimmed.trim(out);
                const CardDecoder::RowRead read = decoder.read_row(block, line, card, row, next, through_next);
                if (read == CardDecoder::RowRead::Read && !(particles && row.is_written(3))) {
                    bulk_->row(block, i, t, row);
                    count += particles ? 1 : 0;
                    return;
                }
                decode_line(i, line, next, read);
            };
            for (std::size_t i = first; i < last;) {
                // The lines of a run (one stride on consecutive lines: what a preprocessor writes), each followed
                // by the next of the run: their bytes come from one view of the window, not a view a line.
                const grammar::CardLinePtr::RunPlace run = at.run_place();
                std::size_t batch = std::min({std::size_t{run.after}, last - i, n - 1 - i});
                if (run.stride > 0) batch = std::min(batch, std::max<std::size_t>(1, window_bytes / run.stride));
                const grammar::CardLine head = *at;
                if (batch > 1 && head.file == file) {
                    const std::string_view view = window.from(head.offset, batch * run.stride);
                    if (view.size() >= batch * run.stride) {
                        for (std::size_t k = 0; k < batch; ++k) {
                            const auto offset = static_cast<std::uint32_t>(k * run.stride);
                            const grammar::CardLine line{file, head.line + static_cast<std::uint32_t>(k),
                                                         head.offset + offset};
                            const grammar::CardLine next{file, line.line + 1, line.offset + run.stride};
                            take(i + k, line, &next, view.substr(offset, run.stride));
                        }
                        i += batch, at += static_cast<std::ptrdiff_t>(batch);
                        continue;
                    }
                }
                const bool followed = i + 1 < n;  // by a line of the block: where this one ends, known
                ++at;
                const grammar::CardLine next = followed ? *at : grammar::CardLine{};
                std::string_view through_next;  // the line and its line break, when the next line follows it
                if (followed && head.file == file && next.file == file && next.offset > head.offset)
                    through_next =
                        window.from(head.offset, next.offset - head.offset).substr(0, next.offset - head.offset);
                take(i, head, followed ? &next : nullptr, through_next);
                ++i;
            }
            counted[static_cast<std::size_t>(t)] = count;
            trimmed.trim(out);
        }
        for (const FloodBound& b : bounds) bound.merge(b);
        for (std::size_t t = 0; t < ranges.size(); ++t) {
            bool refused = false;
            for (const Range& r : ranges[t])
                if (auto problem = ranges_.take(r.extra)) {
                    found[t].push_back(range_error(r.nend, *problem));
                    bulk_->drop_range(r.index);
                    counted[t] -= r.extra;
                    refused = true;
                }
            // Back to line order, each refusal last among its line's findings (as in the serial walk).
            if (refused)
                std::stable_sort(found[t].begin(), found[t].end(),
                                 [](const diag::Diagnostic& a, const diag::Diagnostic& b) {
                                     return a.span.line < b.span.line;
                                 });
        }
        bulk_->end(block);
        const bool clean = std::all_of(all_plain.begin(), all_plain.end(), [](char plain) { return plain != 0; }) &&
                           std::all_of(found.begin(), found.end(), [](const auto& part) { return part.empty(); }) &&
                           std::all_of(ranges.begin(), ranges.end(), [](const auto& part) { return part.empty(); });
        if (clean) bulk_->decoded_cleanly(block, card);
        summary.particles += std::accumulate(counted.begin(), counted.end(), std::size_t{0});
        const std::size_t merged_from = out_.size();
        for (auto& part : found)
            out_.insert(out_.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
        note_bulk_suspects(block, card, merged_from);
        for (const auto& part : past_fields)
            for (std::size_t i : part) note_past_fields(lines + static_cast<std::ptrdiff_t>(i));
        for (const SuspectLine& s : suspects_) note_lost_asterisk(*s.line, false);  // a keyword name misread as a line
    }

    // The lines an edit changed in a bulk block whose other lines were copied from the last check: kept
    // when they decode cleanly as well (then the block makes no finding), else the block is decoded whole.
    bool decode_around(const grammar::Block& block, const CardSpec& card, bool particles) {
        const std::optional<BulkVisitor::Around> around = bulk_->reuse_around(block, card);
        if (!around) return false;
        std::vector<diag::Diagnostic> found;
        CardDecoder decoder(deck_, found);
        std::vector<FieldValue> values;
        grammar::CardLinePtr lines = deck_.begin_lines(block);
        bool clean = true;
        for (std::size_t i = around->first; clean && i < around->last; ++i) {
            const grammar::CardLine next = i + 1 < block.line_count ? lines[i + 1] : grammar::CardLine{};
            clean = decoder.decode_bulk(block, lines[i], card, values, i + 1 < block.line_count ? &next : nullptr) &&
                    !(particles && range_extra(values) > 0);
            if (!clean) break;
            bulk_->line(block, i, 0, lines[i], values);
            if (particles) count_particles(deck_, lines[i], block.format, values, found);
        }
        return bulk_->kept_around(block, card, clean && found.empty());
    }

    // The text of lines [from, to) of one block is decoded: a mapped file's pages go back, so that
    // decoding keeps the model, not the deck, resident (text/source_text.hpp).
    static constexpr std::size_t release_lines = 65536;
    // Lines between two trims of the findings past the flood bound (model/flood_guard.hpp): the
    // findings of a block of broken lines never grow far past the bound while it is walked.
    static constexpr std::size_t trim_lines = 4096;
    // The most bytes of a run of lines taken from a window in one view: the window's buffer.
    static constexpr std::size_t window_bytes = text::TextWindow::default_bytes;
    void release_text(const grammar::CardLine& from, const grammar::CardLine& to) const {
        if (from.file == to.file) deck_.sources.file(from.file).text.release(from.offset, to.offset);
    }

    // Blank lines past a keyword's last card hold no value, so ignoring them loses nothing: LS-PrePost
    // and hand-written decks leave them before the next keyword (a blank line that stands for a
    // mandatory card is another matter: it is read as that card).
    void report_extra(const grammar::Block& block, grammar::CardLinePtr from, std::size_t expected) {
        const bool all_blank = std::all_of(from, deck_.end_lines(block), [&](const grammar::CardLine& l) {
            return deck_.text(l).find_first_not_of(" \t") == std::string_view::npos;
        });
        if (all_blank) return;
        for (grammar::CardLinePtr l = from; l != deck_.end_lines(block); ++l) note_lost_asterisk(*l, false);
        std::size_t extra = static_cast<std::size_t>(deck_.end_lines(block) - from);
        const grammar::CardLine line = *from;
        out_.push_back({"DK009",
                        diag::Severity::Warning,
                        fmt::format("{} takes {} card(s); {} more line(s) ignored", block.keyword, expected, extra),
                        grammar::Span{line.file, line.line, 1, 2},
                        {}});
    }

    // A mandatory card the block ended before (optional and repeated cards may be absent).
    void report_missing(const grammar::Block& block, const CardSpec& missing) {
        out_.push_back(
            {"DK008",
             diag::Severity::Error,
             fmt::format("{} is missing its {}", block.keyword, missing.name.empty() ? "card" : missing.name),
             block.span,
             {}});
    }

    const grammar::RawDeck& deck_;
    std::vector<diag::Diagnostic>& out_;
    CardDecoder decoder_;
    const CardVisitor& visit_;
    BulkVisitor* bulk_;
    RangeBudget ranges_{deck_};
    std::vector<FieldValue> values_;
    std::vector<SuspectLine> suspects_;
    std::vector<LostAsteriskLine> lost_;
    HeadingSuspect heading_;
    std::vector<BlankCardLine> blanks_;
    std::vector<RepeatedLine> copies_;
    std::vector<ReadOnceLine> read_once_;
    std::vector<grammar::CardLinePtr> past_fields_;
    std::optional<EarlyCardLine> early_;
    grammar::AlignmentTally alignment_;
    std::vector<LoneCandidate> lone_;
    const CardSpec* layout_card_ = nullptr;
    grammar::CardFormat layout_format_ = grammar::CardFormat::Standard;
    const CardLayout* layout_ = nullptr;
};

// A keyword that may appear once, where it appeared and in which case ("": every case).
struct CaseSpan {
    std::string case_id;
    grammar::Span span;
};

const CaseSpan* first_in_run(const std::vector<CaseSpan>& seen, const std::string& case_id) {
    for (const CaseSpan& s : seen)
        if (same_run(s.case_id, case_id)) return &s;
    return nullptr;
}

// DK018. Two copies in one file are an error: one of them is a slip. A copy in another file (an include
// that overrides the main deck's settings, or the reverse) is a warning naming the copy that takes effect:
// LS-DYNA reads a deck in order and each *CONTROL card it reads sets the options again, so the copy read
// last wins (the manual does not say so in words; sphdeck's model reads them the same way, model/extract.cpp).
diag::Diagnostic duplicate_control(const grammar::RawDeck& deck, const keywords::KeywordSchema& schema,
                                   const grammar::Span& again, const grammar::Span& first) {
    if (again.file == first.file)
        return {"DK018",
                diag::Severity::Error,
                fmt::format("{} appears more than once", schema.name),
                again,
                {{first, "first defined here"}}};
    const auto& first_file = deck.sources.file(first.file).display_name;
    return {"DK018",
            diag::Severity::Warning,
            fmt::format("{} appears again, after the copy in {}: this copy, read last, is the one that takes effect",
                        schema.name, first_file),
            again,
            {{first,
              fmt::format("{} set here first; every value of it is replaced by the copy read later", schema.name)}}};
}

bool skip_cards(const std::string& keyword) {
    // Read by the reader itself (includes, parameters) or free text.
    return keyword == "*COMMENT" || keyword.rfind("*INCLUDE", 0) == 0 || keyword.rfind("*PARAMETER", 0) == 0 ||
           keyword == "*END";
}

}  // namespace

DeckSummary check_deck(const grammar::RawDeck& deck, std::vector<diag::Diagnostic>& out, const CardVisitor& visit,
                       BulkVisitor* bulk) {
    DeckSummary summary;
    BlockWalker walker(deck, out, visit, bulk);
    UnknownKeywords unknown;
    std::map<const keywords::KeywordSchema*, std::vector<CaseSpan>> seen_unique;
    std::string current_case;  // inside *CASE_BEGIN_n ... *CASE_END_n: "n"; else empty (every case)
    for (const grammar::Block& block : deck.blocks) {
        if (block.keyword == "*") continue;  // a bare '*' line: the reader reported it
        track_case(block.keyword, current_case);
        auto match = keywords::find_keyword(block.keyword);
        if (!match || !match->unknown_options.empty()) {
            const std::size_t before = out.size();
            unknown.add(deck, block, out);
            if (block.line_count > 0) {
                std::vector<LostAsteriskLine> lost;
                note_lost_in_unread(deck, block, deck.begin_lines(block), lost);
                diagnose_lost_asterisks(deck, block, lost, out, before);
            }
            ++summary.unknown_keywords;
            continue;
        }
        // Only *CONTROL_ keywords: every include file legitimately starts with its own *KEYWORD.
        if (match->schema->unique && match->schema->name.rfind("*CONTROL_", 0) == 0) {
            auto& seen = seen_unique[match->schema];
            if (const CaseSpan* first = first_in_run(seen, current_case))
                out.push_back(duplicate_control(deck, *match->schema, block.span, first->span));
            seen.push_back({current_case, block.span});
        }
        if (block.keyword == "*COMMENT" || block.keyword.rfind("*PARAMETER", 0) == 0) {
            // Lines the reader takes (parameters) or keeps as text: a keyword name among them lost its '*'.
            std::vector<LostAsteriskLine> lost;
            if (block.keyword == "*COMMENT")
                note_lost_in_comment(deck, block, lost);
            else if (block.line_count > 0)
                note_lost_in_unread(deck, block, deck.begin_lines(block), lost);
            diagnose_lost_asterisks(deck, block, lost, out, out.size());
        }
        if (skip_cards(block.keyword) || match->schema->free_text) continue;
        const std::size_t before = out.size();
        FloodBound bound(before);
        walker.walk(block, *match, summary, bound);
        const CardSequence sequence(*match);
        // Two lines of a repeated card made one: a block of that card alone (nodes, particles), or its last card
        // after cards read once (a curve's points).
        if (const auto& cards = sequence.cards();
            !match->schema->generated && !cards.empty() && cards.back()->repeat == keywords::CardRepeat::Repeated)
            diagnose_joined_repeated_lines(deck, block, *cards.back(), cards.size() == 1, walker.past_fields_lines(),
                                           out, before);
        diagnose_shifts(deck, block, walker.suspects(), out, before);
        diagnose_lost_asterisks(deck, block, walker.lost_asterisks(), out, before);
        const auto& blanks = walker.blank_cards();
        const auto& copies = walker.repeated_lines();
        const auto& read_once = walker.read_once_lines();
        const bool replayable = BlockWalker::replayable(block);
        const Replay replay = [&](std::span<const ReplayLine> lines) { return walker.replay(block, *match, lines); };
        // A blank line first, when it is not a heading or title (a blank one is often meant): the line a person
        // typed. Then two lines made one, which a card cut above (DK035) or a copy can look like; a line broken in
        // two, which a blank heading read as a card too many can.
        const bool blank_titles =
            std::all_of(blanks.begin(), blanks.end(), [](const BlankCardLine& b) { return b.text_card; });
        const auto blank_cause = [&] {
            return !blanks.empty() &&
                   diagnose_blank_card(
                       deck, block, blanks,
                       [&](grammar::CardLinePtr blank) { return walker.reads_without(block, *match, blank); }, out,
                       before);
        };
        bool blank_misread = !blank_titles && blank_cause();
        const bool joined = !blank_misread && replayable &&
                            diagnose_joined_line(deck, block, sequence.cards(), read_once, replay, out, before);
        const bool copy_misread =
            !joined && !blank_misread && !copies.empty() &&
            diagnose_repeated_line(
                deck, block, copies,
                [&](grammar::CardLinePtr copy) { return walker.reads_without(block, *match, copy); }, out, before);
        const bool split = !joined && !blank_misread && !copy_misread && replayable &&
                           diagnose_split_line(deck, block, read_once, replay, out, before);
        if (!joined && !copy_misread && !split && blank_titles) blank_misread = blank_cause();
        if (const auto& early = walker.early_card(); early && !joined && !blank_misread && !copy_misread && !split)
            diagnose_missing_card(deck, block, *early, out, before);
        // A heading after a blank line or a copy that misread is its symptom (the next card read as a heading).
        const auto after = [](const grammar::CardLine& line, const grammar::CardLine& cause) {
            return line.file == cause.file && line.line >= cause.line;
        };
        if (const auto& h = walker.heading_suspect(); h.line && !joined && !split &&
                                                      !(blank_misread && after(*h.line, *blanks.front().line)) &&
                                                      !(copy_misread && after(*h.line, *copies.front().line)))
            diagnose_missing_heading(deck, block, *h.line, *h.next, h.reals_read_as_ids, out, before);
        bound.annotate(out, before, block.keyword);
    }
    walker.report_lone_shifts();
    unknown.finish(out);
    return summary;
}

}  // namespace sphdeck::model
