// The model's slim columns (issue 40 item 2): ids in 4 bytes while they fit (model/id_column.hpp) and
// each particle's line as runs (model/particle_lines.hpp) must read back exactly what was written,
// whatever the ids and lines, and the decoding must put the same values there on any thread count.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "grammar/read_deck.hpp"
#include "model/model_builder.hpp"

namespace test_id_column_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

std::vector<long long> values_of(const model::IdColumn& c) { return {c.begin(), c.end()}; }

struct Decoded {
    model::Model model;
    grammar::RawDeck deck;
};

Decoded decode(const std::string& text, bool parallel) {
    Decoded d{{}, grammar::read_deck_buffer(text, "ids.k")};
    std::vector<diag::Diagnostic> found;
    model::ModelBuilder builder(d.deck);
    model::check_deck(
        d.deck, found,
        [&](const grammar::Block& bl, const keywords::KeywordMatch& m, const keywords::CardSpec& c,
            grammar::CardLinePtr l, const std::vector<model::FieldValue>& v) { builder.on_card(bl, m, c, l, v); },
        parallel ? &builder.bulk_visitor() : nullptr);
    d.model = builder.finish(found);
    return d;
}

}  // namespace

TEST_CASE("id column: ids that fit and ids that do not read back as written") {
    const long long big = 3'000'000'000LL, low = -2'147'483'648LL;  // past int32, and int32's own minimum
    model::IdColumn c{1, 2, big, -1, low, 7};
    CHECK(c.size() == 6);
    CHECK(c.narrow());
    CHECK(values_of(c) == std::vector<long long>{1, 2, big, -1, low, 7});
    CHECK(c.bytes() < 6 * sizeof(long long) + 2 * 16 + 1);

    c.set(0, big + 1);  // a narrow entry becomes wide
    c.set(2, 5);        // a wide entry becomes narrow
    c.set(4, low + 1);  // wide to narrow at the edge
    CHECK(values_of(c) == std::vector<long long>{big + 1, 2, 5, -1, low + 1, 7});
    CHECK(c.at(0) == big + 1);
    CHECK_THROWS(c.at(6));

    c.resize(1);  // the wide entry left, kept
    c.push_back(4);
    CHECK(values_of(c) == std::vector<long long>{big + 1, 4});
    c.pop_back();
    CHECK(values_of(c) == std::vector<long long>{big + 1});

    // Many wide ids: the column holds them all in 8 bytes and still reads the same.
    model::IdColumn wide;
    std::vector<long long> expected;
    for (long long i = 0; i < 5000; ++i) {
        const long long id = i % 3 == 0 ? big + i : i;
        wide.push_back(id), expected.push_back(id);
    }
    CHECK_FALSE(wide.narrow());
    CHECK(values_of(wide) == expected);
    wide.set(3, 3);
    expected[3] = 3;
    CHECK(values_of(wide) == expected);

    // Columns compare by value whatever their storage.
    model::IdColumn same(expected.begin(), expected.end());
    CHECK(same == wide);
    model::IdColumn narrow_copy;
    narrow_copy.append(wide, 1, 2);  // entries 1 and 2: 1, 2
    CHECK(narrow_copy == model::IdColumn{1, 2});
    CHECK_FALSE(narrow_copy == model::IdColumn{1, 3});
}

TEST_CASE("id column: copies, inserts and the common runs the preview's follow-up compares") {
    model::IdColumn a{10, 20, 30, 40, 50}, b{10, 20, 31, 40, 50};
    CHECK(first_difference(a, b, 5) == 2);
    CHECK(common_tail(a, 5, b, 5, 5) == 2);
    b.set(2, 30);
    CHECK(first_difference(a, b, 5) == 5);
    b.set(4, 6'000'000'000LL);  // wide: compared entry by entry
    CHECK(first_difference(a, b, 5) == 4);
    CHECK(common_tail(a, 5, b, 5, 5) == 0);

    model::IdColumn c{1, 2, 3, 4};
    c.copy_from(b, 3, 2, 1);  // b[3], b[4] -> c[1], c[2]
    CHECK(values_of(c) == std::vector<long long>{1, 40, 6'000'000'000LL, 4});
    c.insert(c.begin() + 1, 9);
    CHECK(values_of(c) == std::vector<long long>{1, 9, 40, 6'000'000'000LL, 4});
    c.erase(c.begin() + 3);
    CHECK(values_of(c) == std::vector<long long>{1, 9, 40, 4});
    // Read through iterators as a vector would be.
    CHECK(*std::max_element(c.begin(), c.end()) == 40);
    CHECK(std::find(c.begin(), c.end(), 4) - c.begin() == 3);
}

TEST_CASE("id column: a column that runs first + step * i kept as two numbers reads and writes as before") {
    const std::size_t n = 20000;  // past compact()'s least size
    model::IdColumn ids, parts;
    for (std::size_t i = 0; i < n; ++i) ids.push_back(7 + 3 * static_cast<long long>(i)), parts.push_back(4);
    const std::vector<long long> written = values_of(ids);
    REQUIRE(ids.compact());
    REQUIRE(parts.compact());
    CHECK(ids.sequence());
    CHECK(ids.heap_bytes() == 0);  // the entries were given back, not only emptied
    CHECK(ids.bytes() == 0);
    CHECK(ids.size() == n);
    CHECK(values_of(ids) == written);
    CHECK(ids[n - 1] == 7 + 3 * static_cast<long long>(n - 1));
    CHECK(parts[n - 1] == 4);
    CHECK(*std::max_element(ids.begin(), ids.end()) == ids.back());

    // Compared with one of the same entries written out, and with another sequence.
    model::IdColumn same;
    for (long long v : written) same.push_back(v);
    CHECK(ids == same);
    CHECK(same == ids);
    CHECK(first_difference(ids, same, n) == n);
    CHECK(common_tail(ids, n, same, n, n) == n);
    model::IdColumn other = same;
    REQUIRE(other.compact());
    CHECK(other == ids);
    CHECK_FALSE(parts == ids);
    same.set(n - 2, -1);
    CHECK_FALSE(ids == same);
    CHECK(first_difference(ids, same, n) == n - 2);
    CHECK(common_tail(ids, n, same, n, n) == 1);

    // The parallel decoding's write goes to set() on a sequence; any change writes the entries out.
    CHECK_FALSE(ids.set_narrow(5, 1));
    model::IdColumn changed = ids;
    changed.set(5, 1);
    CHECK_FALSE(changed.sequence());
    CHECK(changed[5] == 1);
    CHECK(changed[6] == written[6]);
    CHECK(changed.size() == n);
    model::IdColumn longer = ids;
    longer.push_back(6'000'000'000LL);
    CHECK(longer.size() == n + 1);
    CHECK(longer[n] == 6'000'000'000LL);
    CHECK(longer[n - 1] == written[n - 1]);
    model::IdColumn shorter = ids;
    shorter.resize(3);
    CHECK(values_of(shorter) == std::vector<long long>{7, 10, 13});

    // Copied from: appended and laid over entries of a written-out column.
    model::IdColumn appended{1, 2};
    appended.append(ids, 10, 3);
    CHECK(values_of(appended) == std::vector<long long>{1, 2, 37, 40, 43});
    appended.copy_from(parts, 0, 2, 0);
    CHECK(values_of(appended) == std::vector<long long>{4, 4, 37, 40, 43});

    // Not a sequence, or too short to be worth it: left as it is.
    CHECK_FALSE(same.compact());
    model::IdColumn small{1, 2, 3};
    CHECK_FALSE(small.compact());
    CHECK(small.heap_bytes() > 0);
}

TEST_CASE("id column: a decoded deck's consecutive ids kept as sequences read back alike") {
    const int n = 17000;
    std::string text = "*KEYWORD\n*NODE\n";
    for (int i = 0; i < n; ++i) text += fmt::format("{:8d}{:16.6f}{:16.6f}{:16.6f}\n", i + 1, 0.001 * i, 0.0, 0.5);
    text += "*ELEMENT_SPH\n";
    for (int i = 0; i < n; ++i) text += fmt::format("{:8d}{:8d}{:16.6f}\n", i + 1, 2, 1.0);
    text += "*END\n";
    const Decoded serial = decode(text, false), parallel = decode(text, true);
    for (const Decoded* d : {&serial, &parallel}) {
        CHECK(d->model.nodes.id.sequence());
        CHECK(d->model.particles.node.sequence());
        CHECK(d->model.particles.part.sequence());
        CHECK(d->model.nodes.id[n - 1] == n);
        CHECK(d->model.particles.node[123] == 124);
        CHECK(d->model.particles.part[n - 1] == 2);
    }
}

TEST_CASE("particle lines: runs read back each particle's line") {
    model::ParticleLines l;
    const std::vector<std::uint32_t> lines = {5, 6, 7, 7, 7, 7, 8, 20, 21, 3, 3};
    for (std::uint32_t v : lines) l.push_back(v);
    CHECK(l.size() == lines.size());
    CHECK(l.all() == lines);
    for (std::size_t i = 0; i < lines.size(); ++i) CHECK(l[i] == lines[i]);
    CHECK(l.runs() < lines.size());
    CHECK_THROWS(l.at(lines.size()));

    model::ParticleLines block;
    block.append_run(1000, 40, 1);   // a block decoded one particle a line
    block.append_run(500, 1040, 1);  // the next block, right after: still one run
    CHECK(block.runs() == 1);
    CHECK(block[1499] == 1539);
    block.resize(10);
    block.resize(12);  // new particles on line 0
    CHECK(block.all() == std::vector<std::uint32_t>{40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 0, 0});
    block.insert(1, 99);
    block.erase(0);
    CHECK(block[0] == 99);
    CHECK(block[1] == 41);
    model::ParticleLines same;
    for (std::uint32_t v : block.all()) same.push_back(v);
    CHECK(same == block);
}

TEST_CASE("id column: a big block of 10-digit ids decodes alike on threads, lines included") {
    // I10 cards (the '%' suffix): ids past 2^31 every 7th line, an NEND range, a part past 2^31.
    const int n = 9000;
    const long long base = 2'147'483'000LL;
    std::string text = "*KEYWORD\n*NODE %\n";
    for (int i = 0; i < n; ++i)
        text += fmt::format("{:10d}{:16.6f}{:16.6f}{:16.6f}\n", i % 7 == 0 ? base + i : i + 1, 0.001 * i, 0.0, 0.5);
    text += "*ELEMENT_SPH %\n$ a comment line inside the block\n";
    for (int i = 0; i < n; ++i) {
        const long long id = i % 7 == 0 ? base + i : i + 1;
        if (i == 8)
            text += fmt::format("{:10d}{:10d}{:16.6f}{:10d}\n", id, 4'000'000'000LL, 0.25, id + 2);  // a range of 3
        else
            text += fmt::format("{:10d}{:10d}{:16.6f}\n", id, 1, 1.0);
    }
    text += "*END\n";
    const Decoded serial = decode(text, false), parallel = decode(text, true);
    const model::Particles &a = serial.model.particles, &b = parallel.model.particles;
    CHECK(serial.model.nodes.id == parallel.model.nodes.id);
    CHECK(a.node == b.node);
    CHECK(a.part == b.part);
    CHECK(a.line == b.line);
    REQUIRE(b.size() == static_cast<std::size_t>(n + 2));
    CHECK(parallel.model.nodes.id[7] == base + 7);
    CHECK(parallel.model.nodes.id[8] == 9);
    CHECK(b.node[7] == base + 7);
    CHECK(b.part[8] == 4'000'000'000LL);
    CHECK(b.part[10] == 4'000'000'000LL);  // the range's last particle
    CHECK(b.part[11] == 1);
    // Each particle's line is its card's: a line of the file after the comment.
    const std::uint32_t first_card_line = static_cast<std::uint32_t>(n) + 5;  // *KEYWORD, *NODE, nodes, *ELEMENT_SPH, $
    CHECK(parallel.deck.lines[b.line[0]].line == first_card_line);
    CHECK(parallel.deck.lines[b.line[10]].line == first_card_line + 8);  // NEND range: the card's line
    CHECK(parallel.deck.lines[b.line[11]].line == first_card_line + 9);
    CHECK(parallel.deck.lines[b.line[n + 1]].line == first_card_line + static_cast<std::uint32_t>(n) - 1);
}

}  // namespace test_id_column_cpp
