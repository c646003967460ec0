// The bulk lines' plain path (model/card_decoder_plain.cpp, issue 40 round 4): the fixed-width field readers
// give what the short readers give on the trimmed text (and from_chars), and a line the plain path takes, or
// reads as a numbers-only row, holds exactly the values decode() gives it, with no finding; the line's end
// found from the next line's start gives what the scan gives.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <charconv>
#include <cstring>
#include <random>
#include <string>

#include "grammar/read_deck.hpp"
#include "grammar/value_fast.hpp"
#include "model/card_decoder.hpp"

namespace test_plain_decode_cpp {

using namespace sphdeck;
namespace fast = grammar::fast_number;

namespace {

std::string trimmed(const std::string& s) {
    const std::size_t b = s.find_first_not_of(' ');
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// Text of `width` bytes from a small alphabet, numbers' characters and the troubles of real decks
// (blanks, signs, commas, tabs, a letter O for 0, Fortran exponents), or a number right-aligned in it.
std::string random_field(std::mt19937_64& rng, std::size_t width, bool real) {
    static const char alphabet[] = "   0123456789-+.eEdD,\tO";
    std::string s(width, ' ');
    switch (rng() % 10) {
        case 0:  // any bytes of the alphabet
            for (char& c : s) c = alphabet[rng() % (sizeof alphabet - 1)];
            return s;
        case 1: {  // a number as a preprocessor writes it, then one byte changed
            s = real ? fmt::format("{:16.8e}", std::ldexp(static_cast<double>(rng() % 2000000) - 1e6,
                                                          static_cast<int>(rng() % 200) - 100))
                     : fmt::format("{:8d}", static_cast<long long>(rng() % 200000000) - 100000000);
            s = s.substr(s.size() > width ? s.size() - width : 0);
            s.insert(0, width - s.size(), ' ');
            s[rng() % width] = alphabet[rng() % (sizeof alphabet - 1)];
            return s;
        }
        default: {  // a number as a preprocessor writes it
            s = real ? fmt::format("{:16.8e}", std::ldexp(static_cast<double>(rng() % 2000000) - 1e6,
                                                          static_cast<int>(rng() % 200) - 100))
                     : fmt::format("{:8d}", static_cast<long long>(rng() % 200000000) - 100000000);
            if (s.size() > width) s = s.substr(s.size() - width);
            s.insert(0, width - s.size(), ' ');
            if (rng() % 4 == 0) {  // left-aligned
                const std::string t = trimmed(s);
                s = t + std::string(width - t.size(), ' ');
            }
            return s;
        }
    }
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("plain decode: integer8 reads what short_integer reads on the trimmed text") {
    std::mt19937_64 rng(40);
    int numbers = 0;
    auto check = [&](const std::string& field) {
        REQUIRE(field.size() == 8);
        CAPTURE(field);
        long long value = 0;
        std::uint32_t lead = 0;
        const fast::FieldShape shape = fast::integer8(field.data(), value, lead);
        const std::string t = trimmed(field);
        if (shape == fast::FieldShape::Blank) CHECK(t.empty());
        if (shape != fast::FieldShape::Number) return;
        ++numbers;
        long long expected = 0;
        REQUIRE(grammar::plain_integer(t, expected));
        CHECK(value == expected);
        CHECK(field.substr(lead) == t);  // right-aligned: the number runs to the field's end
        long long by_from_chars = 0;
        CHECK(std::from_chars(t.data(), t.data() + t.size(), by_from_chars).ec == std::errc());
        CHECK(by_from_chars == value);
    };
    for (const char* edge : {"        ",  "       0",  "      -0",  "-0000000", "99999999", "-9999999", "       -",
                             "      --1", "  1 2   ",  "1       ",  "      +1", "     1.0", "     1e3", "       O",
                             "     1,2",  "\t      1", "      1\t", "00000000", " 1234567", "12345678"})
        if (std::strlen(edge) == 8) check(edge);
    for (int i = 0; i < 300000; ++i) check(random_field(rng, 8, false));
    CHECK(numbers > 100000);  // the shape a preprocessor writes is read here, not left to the short reader
    long long v = 0;
    std::uint32_t lead = 0;
    CHECK(fast::integer8("       1", v, lead) == fast::FieldShape::Number);
    CHECK(v == 1);
    CHECK(lead == 7);
    CHECK(fast::integer8("-1234567", v, lead) == fast::FieldShape::Number);
    CHECK(v == -1234567);
    CHECK(fast::integer8("1       ", v, lead) == fast::FieldShape::Other);  // left-aligned: the short reader's
    CHECK(fast::integer8("       -", v, lead) == fast::FieldShape::Other);
    CHECK(fast::integer8("        ", v, lead) == fast::FieldShape::Blank);
}

TEST_CASE("plain decode: e8_field16 reads what short_real and from_chars read, bit for bit") {
    std::mt19937_64 rng(41);
    int numbers = 0;
    auto check = [&](const std::string& field) {
        REQUIRE(field.size() == 16);
        CAPTURE(field);
        double value = 0.0;
        std::uint32_t lead = 0;
        if (!fast::e8_field16(field.data(), value, lead)) return;
        ++numbers;
        const std::string t = trimmed(field);
        CHECK(field.substr(lead) == t);
        double expected = 0.0;
        REQUIRE(grammar::plain_real(t, expected));
        CHECK(same_bits(value, expected));
        double by_from_chars = 0.0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), by_from_chars);
        CHECK(ec == std::errc());
        CHECK(end == t.data() + t.size());
        CHECK(same_bits(value, by_from_chars));
    };
    const char* edges[] = {"  0.00000000e+00", " -0.00000000e+00", "  9.99999999e+22",  "  9.99999999e-23",
                           "  1.00000000e+23", "  1.00000000e-99", " -4.94938015e-02",  "  1.00000000E-06",
                           "  1.00000000e-0 ", "  1.0000000e-006", " +1.00000000e+00",  "1.00000000e+00  ",
                           "  1,00000000e+00", "  1.00000000d+00", "  1.00000000e 00",  "  1.0000000Oe+00",
                           "  1.5-3         ", "  1.E+5         ", "\t 1.00000000e+00", " --1.0000000e+00"};
    for (const char* edge : edges) check(edge);
    for (int i = 0; i < 300000; ++i) check(random_field(rng, 16, true));
    // Every "%16.8e" whose decimal exponent scales exactly, both signs, every exponent from -30 to 30.
    for (int e = -30; e <= 30; ++e)
        for (int i = 0; i < 2000; ++i) {
            const double v = std::ldexp(static_cast<double>(rng() >> 11), -53) * std::pow(10.0, e) * (i % 2 ? -1 : 1);
            check(fmt::format("{:16.8e}", v));
        }
    CHECK(numbers > 150000);
    double v = 0.0;
    std::uint32_t lead = 0;
    CHECK(fast::e8_field16(" -4.94938015e-02", v, lead));
    CHECK(lead == 1);
    CHECK(v == -4.94938015e-02);
    CHECK(fast::e8_field16("  1.00000000e+31", v, lead) == false);  // 10^23: beyond exact scaling, short_real's
    CHECK(fast::e8_field16("  1.00000000e-06", v, lead));
    CHECK(lead == 2);
    CHECK(same_bits(v, 1e-6));
}

namespace {

struct Lines {
    std::string text;
    std::size_t lines = 0;
};

// A deck of one *NODE and one *ELEMENT_SPH block of random lines, fields made as above, now and then a
// line too long, a short one, a '\r' or a trailing comment-like tail.
std::string random_deck(std::mt19937_64& rng, int n) {
    std::string deck = "*KEYWORD\n*NODE\n";
    auto ending = [&](std::string& line) {
        if (rng() % 20 == 0) line += std::string(rng() % 12, ' ') + (rng() % 2 ? "x" : ",");
        if (rng() % 25 == 0) line.resize(rng() % (line.size() + 1));
        line += rng() % 10 == 0 ? "\r\n" : "\n";
    };
    for (int i = 0; i < n; ++i) {
        std::string line = random_field(rng, 8, false);
        for (int k = 0; k < 3; ++k) line += random_field(rng, 16, true);
        line += rng() % 3 ? std::string("       0       0") : random_field(rng, 8, false) + random_field(rng, 8, false);
        if (rng() % 4 == 0) line.resize(56);
        ending(line);
        deck += line;
    }
    deck += "*ELEMENT_SPH\n";
    for (int i = 0; i < n; ++i) {
        std::string line = random_field(rng, 8, false) + random_field(rng, 8, false) + random_field(rng, 16, true);
        if (rng() % 5 == 0) line += rng() % 2 ? fmt::format("{:8d}", rng() % 1000) : random_field(rng, 10, false);
        ending(line);
        deck += line;
    }
    return deck + "*END\n";
}

void check_same_values(const std::vector<model::FieldValue>& a, const std::vector<model::FieldValue>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        CAPTURE(i);
        CHECK(a[i].spec == b[i].spec);
        CHECK(a[i].span.file == b[i].span.file);
        CHECK(a[i].span.line == b[i].span.line);
        CHECK(a[i].span.column == b[i].span.column);
        CHECK(a[i].span.end_column == b[i].span.end_column);
        CHECK(a[i].text == b[i].text);
        CHECK(a[i].explicit_value == b[i].explicit_value);
        CHECK(a[i].valid == b[i].valid);
        CHECK(same_bits(a[i].number, b[i].number));
    }
}

}  // namespace

TEST_CASE("plain decode: a line the plain path takes holds decode()'s values; its row the same numbers") {
    std::mt19937_64 rng(42);
    const grammar::RawDeck deck = grammar::read_deck_buffer(random_deck(rng, 20000), "plain.k");
    std::vector<diag::Diagnostic> sink;
    model::CardDecoder plain(deck, sink);
    std::size_t taken = 0, rows = 0, lines = 0;
    for (const grammar::Block& block : deck.blocks) {
        const auto match = keywords::find_keyword(block.keyword);
        if (!match || (block.keyword != "*NODE" && block.keyword != "*ELEMENT_SPH")) continue;
        const keywords::CardSpec& card = match->schema->cards[0];
        const grammar::CardLinePtr begin = deck.begin_lines(block), end = deck.end_lines(block);
        for (grammar::CardLinePtr l = begin; l != end; ++l) {
            const grammar::CardLine line = *l;
            const grammar::CardLine after = l + 1 != end ? *(l + 1) : grammar::CardLine{};
            const grammar::CardLine* next = l + 1 != end ? &after : nullptr;
            CAPTURE(deck.text(line));
            ++lines;
            sink.clear();  // a line left to decode() reports there
            std::vector<diag::Diagnostic> found;
            model::CardDecoder full(deck, found);
            std::vector<model::FieldValue> expected, hinted, scanned;
            full.decode(block, line, card, expected);
            const bool took = plain.decode_bulk(block, line, card, hinted, next);
            // The end found by a scan: the same verdict and values.
            CHECK(plain.decode_bulk(block, line, card, scanned, nullptr) == took);
            check_same_values(hinted, scanned);
            if (took) {
                ++taken;
                CHECK(sink.empty());
                CHECK(found.empty());
                check_same_values(hinted, expected);
            }
            model::PlainRow row;
            const model::CardDecoder::RowRead read = plain.read_row(block, line, card, row, next);
            CHECK(read == (took ? model::CardDecoder::RowRead::Read : model::CardDecoder::RowRead::NotPlain));
            if (read != model::CardDecoder::RowRead::Read) continue;
            ++rows;
            REQUIRE(row.count == hinted.size());
            for (std::size_t i = 0; i < hinted.size(); ++i) {
                CAPTURE(i);
                CHECK(row.is_valid(i) == hinted[i].valid);
                CHECK(row.is_written(i) == hinted[i].explicit_value);
                CHECK(same_bits(row.number[i], hinted[i].number));
            }
        }
    }
    CHECK(lines == 40000);
    CHECK(taken > 10000);  // the lines a preprocessor writes go the plain way
    CHECK(taken < lines);  // and the broken ones do not
    CHECK(rows == taken);
}

}  // namespace test_plain_decode_cpp
