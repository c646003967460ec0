#include "model/joined_lines.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include <fmt/format.h>

#include "model/card_decoder.hpp"
#include "model/shift_diagnosis.hpp"

namespace sphdeck::model {
namespace {

constexpr std::size_t max_tries_per_line = 16;

bool plain_fixed(std::string_view text) { return text.find_first_of(",\t") == std::string_view::npos; }

std::string_view without_trailing_blanks(std::string_view text) {
    const std::size_t end = text.find_last_not_of(" \r");
    return end == std::string_view::npos ? std::string_view{} : text.substr(0, end + 1);
}

// Where a line may have been two: where a number runs into a word; after a word, at a column of the blanks before the
// next word that puts the next word at the end (or the start) of a field of one of `cards` once the rest stands at
// column 1 (the second line's own blanks before its first value), leftmost first.
std::vector<std::size_t> split_points(std::string_view text, std::span<const keywords::CardSpec* const> cards,
                                      grammar::CardFormat format) {
    std::vector<std::uint32_t> ends, starts;
    for (const keywords::CardSpec* c : cards)
        for (const grammar::FixedField& f : card_layout(*c, format).positions)
            ends.push_back(f.start + f.width), starts.push_back(f.start);
    const auto has = [](const std::vector<std::uint32_t>& v, std::size_t x) {
        return std::find(v.begin(), v.end(), x) != v.end();
    };
    std::vector<std::size_t> points;
    const std::size_t last = without_trailing_blanks(text).size();
    // First where a number runs into a word (`1upper`): a line that ends in a value joined to a left-aligned one
    // (the next part's heading) leaves no blank between them.
    const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
    const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    for (std::size_t p = 1; p < last && points.size() < max_tries_per_line; ++p)
        if (digit(text[p - 1]) && letter(text[p]) &&
            !(text[p] == 'e' || text[p] == 'E' || text[p] == 'd' || text[p] == 'D'))
            points.push_back(p);
    for (std::size_t p = 1; p < last && points.size() < max_tries_per_line; ++p) {
        if (text[p - 1] == ' ' || text[p] != ' ') continue;
        const std::size_t s = text.find_first_not_of(' ', p);
        const std::size_t e = std::min(text.find(' ', s), last);
        for (std::size_t q = p; q <= s && points.size() < max_tries_per_line; ++q)
            if (has(ends, e - q) || has(starts, s - q)) points.push_back(q);
    }
    return points;
}

std::vector<std::size_t> word_ends(std::string_view text) {
    std::vector<std::size_t> ends;
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] != ' ' && (i + 1 == text.size() || text[i + 1] == ' ')) ends.push_back(i + 1);
    return ends;
}

bool missing_card_finding(const diag::Diagnostic& d, const grammar::Block& block) {
    return d.code == "DK008" && d.span.file == block.span.file && d.span.line == block.span.line;
}

// The block reads a card short from `line` on: the keyword misses a card, or `line` holds what a second line's text
// makes there (text past the card's columns, text that is no number in a number field, a free value too long);
// and no line is read past the last card (a line too many is a card late, not short), and no finding on `line`
// carries a safe fix (a value moved across a field end: its mend is known).
bool reads_card_short(std::span<const diag::Diagnostic> found, const grammar::Block& block,
                      const grammar::CardLine& line) {
    constexpr std::string_view spilled[] = {"DK002", "DK003", "DK005", "DK006"};
    bool short_of = false;
    for (const diag::Diagnostic& d : found) {
        if (d.code == "DK009") return false;
        const bool on_line = d.span.file == line.file && d.span.line == line.line;
        if (on_line && std::any_of(d.fixes.begin(), d.fixes.end(), [](const diag::Fix& f) { return f.safe; }))
            return false;
        short_of = short_of || missing_card_finding(d, block) ||
                   (on_line && std::find(std::begin(spilled), std::end(spilled), d.code) != std::end(spilled));
    }
    return short_of;
}

bool any_misread_from(std::span<const diag::Diagnostic> found, const grammar::Block& block,
                      const grammar::CardLine& line) {
    return std::any_of(found.begin(), found.end(),
                       [&](const diag::Diagnostic& d) { return misread_from(d, block, line); });
}

std::string card_name(const keywords::CardSpec& card) {
    return card.name.empty() ? std::string("a card") : std::string(card.name);
}

std::uint32_t first_word_column(std::string_view text, std::size_t from) {
    return static_cast<std::uint32_t>(std::min(text.find_first_not_of(' ', from), text.size()) + 1);
}

// DK037 at `line`, whose text from column p + 1 was a line of its own (`effect`: what the join makes of it), with
// its fix: a line end there. Unsafe: the line end may have been meant elsewhere in the blanks, and a card may have
// been meant between the two.
diag::Diagnostic joined_finding(const grammar::CardLine& line, std::string_view text, std::size_t p,
                                const std::string& effect, const std::string& second) {
    const auto column = static_cast<std::uint32_t>(p + 1);
    diag::Diagnostic d{"DK037",
                       diag::Severity::Warning,
                       fmt::format("two lines made one: the line end before column {} was deleted, so {}", column,
                                   effect),
                       grammar::Span{line.file, line.line, first_word_column(text, p),
                                     static_cast<std::uint32_t>(without_trailing_blanks(text).size() + 1)},
                       {}};
    d.fixes.push_back(
        {fmt::format("break the line before column {}, so that its text from there is read as {}", column, second),
         false,
         {{grammar::Span{line.file, line.line, column, column}, "\n"}}});
    return d;
}

const ReadOnceLine* read_once(std::span<const ReadOnceLine> lines, grammar::CardLinePtr line) {
    for (const ReadOnceLine& l : lines)
        if (l.line == line) return &l;
    return nullptr;
}

}  // namespace

bool words_in_place(std::string_view text, const keywords::CardSpec& card, grammar::CardFormat format) {
    const std::vector<grammar::FixedField>& fields = card_layout(card, format).positions;
    const auto number_like = [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.' || c == '&';
    };
    bool any = false, words = false;
    for (std::size_t s = text.find_first_not_of(' '); s < text.size() && s != std::string_view::npos;) {
        std::size_t e = text.find(' ', s);
        if (e == std::string_view::npos) e = text.size();
        const auto field = std::find_if(fields.begin(), fields.end(), [&](const grammar::FixedField& f) {
            return s >= f.start && s < f.start + f.width;
        });
        if (field == fields.end()) return false;
        const auto& spec = card.fields[static_cast<std::size_t>(field - fields.begin())];
        const std::size_t end = field->start + field->width;
        if (spec.type == keywords::FieldType::Text)
            words = words || !number_like(text[s]);
        else if (e > end || (e != end && s != field->start) || !number_like(text[s]))
            return false;  // out of place, or a word read as an id label: no line a person typed for this card
        any = true;
        s = text.find_first_not_of(' ', e);
    }
    // A heading or title of numbers alone is the card after it (DK032), not a line a mend would make.
    const bool text_card = !card.fields.empty() && card.fields[0].type == keywords::FieldType::Text;
    return any && (!text_card || words);
}

bool diagnose_joined_line(const grammar::RawDeck& deck, const grammar::Block& block,
                          std::span<const keywords::CardSpec* const> cards, std::span<const ReadOnceLine> lines,
                          const Replay& replay, std::vector<diag::Diagnostic>& out, std::size_t from) {
    const auto found = std::span<const diag::Diagnostic>(out).subspan(from);
    for (const ReadOnceLine& c : lines) {
        const std::string_view text = deck.text(*c.line);
        if (!c.card || !plain_fixed(text) || !reads_card_short(found, block, *c.line)) continue;
        for (const std::size_t p : split_points(text, cards, block.format)) {
            std::vector<ReplayLine> mended;
            std::size_t second = 0;
            for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l) {
                if (l != c.line) {
                    mended.push_back({l, deck.text(*l)});
                    continue;
                }
                mended.push_back({l, text.substr(0, p)});
                second = mended.size();
                mended.push_back({l, text.substr(p)});
            }
            const auto read_as = replay(mended);
            if (!read_as || !(*read_as)[second - 1] || !(*read_as)[second] ||
                !words_in_place(text.substr(0, p), *(*read_as)[second - 1], block.format) ||
                !words_in_place(text.substr(p), *(*read_as)[second], block.format))
                continue;
            const grammar::CardLine& line = *c.line;
            diag::Diagnostic d =
                joined_finding(line, text, p,
                               fmt::format("{} of {} is read as part of this line and the block a card "
                                           "short (broken there, the block reads cleanly)",
                                           card_name(*(*read_as)[second]), block.keyword),
                               card_name(*(*read_as)[second]));
            fold_explained(out, from, std::move(d),
                           [&](const diag::Diagnostic& f) { return misread_from(f, block, line); });
            return true;
        }
    }
    return false;
}

void diagnose_joined_repeated_lines(const grammar::RawDeck& deck, const grammar::Block& block,
                                    const keywords::CardSpec& card, bool only_card,
                                    std::span<const grammar::CardLinePtr> past_fields,
                                    std::vector<diag::Diagnostic>& out, std::size_t from) {
    constexpr std::size_t max_lines = 4;
    if (block.line_count == 0) return;
    const grammar::CardLinePtr begin = deck.begin_lines(block), end = deck.end_lines(block);
    const grammar::FileId file = begin->file;
    if ((end - 1)->file != file) return;  // lines of one file, in order: found by their numbers
    const keywords::CardSpec* const only = &card;
    const std::span<const keywords::CardSpec* const> cards(&only, 1);
    std::vector<diag::Diagnostic> scratch;
    CardDecoder decoder(deck, scratch);
    std::vector<FieldValue> values;
    const auto reads_cleanly = [&](const grammar::CardLine& line, std::string_view piece) {
        scratch.clear();
        decoder.decode_text(block, line, piece, card, values);
        return scratch.empty() && !decoder.text_past_fields();  // nothing left past a piece's fields either
    };
    // A line of the card holds two values at least (a node and its x, a point's abscissa and ordinate): one value
    // past the fields is no line joined (a point line's stray 7.0 in DK029_past_fields_silent.k).
    const std::size_t fewest_words = std::min<std::size_t>(2, card.fields.size());
    const auto line_like = [&](std::string_view piece) { return word_ends(piece).size() >= fewest_words; };
    // The two pieces' words in the card's fields, or where each other's are, the shorter one leaving out the
    // longer one's last values (a block's lines written alike: the habit tells the columns where a layout's width
    // is in doubt, *ELEMENT_SPH's NEND).
    const auto in_place = [&](std::string_view first, std::string_view second) {
        if (words_in_place(first, card, block.format) && words_in_place(second, card, block.format)) return true;
        const std::vector<std::size_t> a = word_ends(first), b = word_ends(second);
        const std::size_t common = std::min(a.size(), b.size());
        return common > 0 && std::equal(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(common), b.begin());
    };
    std::vector<grammar::CardLinePtr> lines(past_fields.begin(), past_fields.end());  // with text past the fields
    for (std::size_t i = from; only_card && i < out.size() && lines.size() < max_lines; ++i) {
        if (out[i].code != "DK006" || out[i].span.file != file) continue;
        const std::uint32_t number = out[i].span.line;
        const grammar::CardLinePtr at =
            std::lower_bound(begin, end, number,
                             [](const grammar::CardLine& l, std::uint32_t n) { return l.line < n; });
        if (at != end && at->line == number && std::find(lines.begin(), lines.end(), at) == lines.end())
            lines.push_back(at);
    }
    std::sort(lines.begin(), lines.end(),
              [](grammar::CardLinePtr a, grammar::CardLinePtr b) { return a->line < b->line; });
    for (const grammar::CardLinePtr at : lines) {
        const std::string_view text = deck.text(*at);
        if (!plain_fixed(text)) continue;
        for (const std::size_t p : split_points(text, cards, block.format)) {
            if (!line_like(text.substr(0, p)) || !line_like(text.substr(p)) || !reads_cleanly(*at, text.substr(0, p)) ||
                !reads_cleanly(*at, text.substr(p)) || !in_place(text.substr(0, p), text.substr(p)))
                continue;
            diag::Diagnostic d = joined_finding(
                *at, text, p,
                fmt::format("another line of {} is read as part of this one, what lies past its fields ignored "
                            "(broken there, both lines read cleanly)",
                            block.keyword),
                fmt::format("a line of {}", block.keyword));
            const grammar::CardLine& line = *at;
            fold_explained(out, from, std::move(d), [&](const diag::Diagnostic& f) {
                return f.code == "DK006" && f.span.file == line.file && f.span.line == line.line;
            });
            break;
        }
    }
}

bool diagnose_split_line(const grammar::RawDeck& deck, const grammar::Block& block, std::span<const ReadOnceLine> lines,
                         const Replay& replay, std::vector<diag::Diagnostic>& out, std::size_t from) {
    const auto found = std::span<const diag::Diagnostic>(out).subspan(from);
    for (const ReadOnceLine& c : lines) {
        if (c.line == deck.begin_lines(block)) continue;
        const grammar::CardLinePtr above = c.line - 1;
        const ReadOnceLine* head = read_once(lines, above);
        if (!head || !head->card || above->file != c.line->file || above->line + 1 != c.line->line) continue;
        const std::string_view a = without_trailing_blanks(deck.text(*above)), b = deck.text(*c.line);
        const std::size_t b_first = b.find_first_not_of(' ');
        if (a.empty() || b_first == std::string_view::npos || !plain_fixed(a) || !plain_fixed(b) ||
            !any_misread_from(found, block, *above))
            continue;
        // The line above must look like a line of its card on its own: a heading of numbers alone is the card after it
        // (DK032), not the start of a heading.
        if (!words_in_place(a, *head->card, block.format)) continue;
        const std::size_t b_end = std::min(b.find(' ', b_first), b.size());
        // The blanks between the two pieces that put b's first word at the end (or the start) of a field of the
        // card the line above is read as, after the line above's last word.
        std::vector<std::size_t> pads;
        // A heading or title broken between two words: one blank between them; a piece of numbers alone is a card.
        if (!head->card->fields.empty() && head->card->fields.front().type == keywords::FieldType::Text) {
            if (!words_in_place(b, *head->card, block.format)) continue;
            pads.push_back(b_first == 0 ? 1 : 0);
        }
        for (const grammar::FixedField& f : card_layout(*head->card, block.format).positions) {
            const std::size_t end = f.start + f.width;
            if (end >= a.size() + b_end && end - b_end - a.size() + b_first >= 1)
                pads.push_back(end - b_end - a.size());
            if (f.start >= a.size() + b_first && f.start - a.size() >= 1) pads.push_back(f.start - b_first - a.size());
        }
        std::sort(pads.begin(), pads.end());
        pads.erase(std::unique(pads.begin(), pads.end()), pads.end());
        if (pads.size() > max_tries_per_line) pads.resize(max_tries_per_line);
        for (const std::size_t pad : pads) {
            std::string joined(a);
            joined.append(pad, ' ');
            joined.append(without_trailing_blanks(b));
            if (!words_in_place(joined, *head->card, block.format)) continue;
            std::vector<ReplayLine> mended;
            for (grammar::CardLinePtr l = deck.begin_lines(block); l != deck.end_lines(block); ++l)
                if (l == above)
                    mended.push_back({l, joined});
                else if (l != c.line)
                    mended.push_back({l, deck.text(*l)});
            if (!replay(mended)) continue;
            const grammar::CardLine& line = *c.line;
            const auto at = static_cast<std::uint32_t>(a.size() + pad + 1);
            diag::Diagnostic d{
                "DK038",
                diag::Severity::Warning,
                fmt::format("this line goes on from the line above it: broken off by a line end typed inside the "
                            "card, it is read as {} (joined to the line above, its text from column {} there, the "
                            "block reads cleanly)",
                            c.card
                                ? fmt::format("{} of {}, and the lines after it one card late", card_name(*c.card),
                                              block.keyword)
                                : fmt::format("a line past the last card of {}, which LS-DYNA ignores", block.keyword),
                            at),
                grammar::Span{line.file, line.line, static_cast<std::uint32_t>(b_first + 1),
                              static_cast<std::uint32_t>(without_trailing_blanks(b).size() + 1)},
                {}};
            // Unsafe: where the piece goes on the line above is read from the fields, a judgement; a comment keeps
            // the piece's text.
            const std::string_view above_text = deck.text(*above);
            d.fixes.push_back(
                {fmt::format("join the line to the line above (its text from column {} there) and make it a comment",
                             at),
                 false,
                 {{grammar::Span{above->file, above->line, static_cast<std::uint32_t>(a.size() + 1),
                                 static_cast<std::uint32_t>(above_text.size() + 1)},
                   joined.substr(a.size())},
                  {grammar::Span{line.file, line.line, 1, 1}, "$"}}});
            fold_explained(out, from, std::move(d),
                           [&](const diag::Diagnostic& f) { return misread_from(f, block, *above); });
            return true;
        }
    }
    return false;
}

}  // namespace sphdeck::model
