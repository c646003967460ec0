// gen_big_deck: write a large, valid LS-DYNA SPH deck for reader benchmarks.
//
//   gen_big_deck OUTPUT [NODES] [--clusters] [--coincident=M]        (NODES defaults to 1000000)
//
// The deck holds *KEYWORD, *CONTROL_SPH (IDIM 3, FORM 15), *SECTION_SPH, *PART, *MAT_NULL,
// *EOS_MURNAGHAN, then NODES *NODE lines (fixed I8,3E16,2I8) on a jittered cubic lattice centred on
// the origin, NODES *ELEMENT_SPH lines (fixed I8,I8,E16) and *END: about 106 bytes per particle,
// so ~106 MB for a million. The output depends only on NODES: the jitter comes from std::mt19937
// with a fixed seed, turned into reals by hand (std::uniform_real_distribution differs between
// standard libraries).
//
// --clusters adds the nearest-neighbour search's old worst case (bench/README.md, "Tight clusters"): three
// blobs of 800 particles 3 microns wide inside the lattice (at a quarter, half and three quarters of its
// diagonal, mid-height) and one stray particle 10 m away, after the lattice's NODES.
//
// --coincident=M adds M particles at one place (the lattice's centre, bit for bit the same coordinates), after
// the rest: the coincident pairs' worst case (M (M - 1) / 2 pairs, SPH114; bench/README.md).
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr double kSpacing = 1.0e-3;           // m
constexpr double kDensity = 1000.0;           // kg/m^3 (water)
constexpr double kJitter = 0.1;               // max displacement per axis, in spacings
constexpr long long kMaxNodes = 99'999'999;   // largest id an I8 field holds
constexpr int kBlobs = 3, kBlobPoints = 800;  // --clusters
constexpr double kBlobWidth = 3.0e-6;         // m

// Buffered writer: lines are formatted into one large buffer and flushed with fwrite.
class Out {
public:
    explicit Out(std::FILE* f) : f_(f), buf_(kSize) {}
    ~Out() { flush(); }
    void put(std::string_view s) {
        if (len_ + s.size() > buf_.size()) flush();
        std::memcpy(buf_.data() + len_, s.data(), s.size());
        len_ += s.size();
    }
    // Room for at least n more bytes, written directly by the caller, then commit(n).
    char* reserve(std::size_t n) {
        if (len_ + n > buf_.size()) flush();
        return buf_.data() + len_;
    }
    void commit(std::size_t n) { len_ += n; }
    bool flush() {
        if (len_ > 0 && std::fwrite(buf_.data(), 1, len_, f_) != len_) ok_ = false;
        len_ = 0;
        return ok_;
    }
    bool ok() const { return ok_; }

private:
    static constexpr std::size_t kSize = 8u << 20;
    std::FILE* f_;
    std::vector<char> buf_;
    std::size_t len_ = 0;
    bool ok_ = true;
};

// Right-justify an integer in `width` columns at p.
void put_int(char* p, int width, long long v) {
    char tmp[24];
    auto [end, ec] = std::to_chars(tmp, tmp + sizeof tmp, v);
    (void)ec;
    auto n = static_cast<int>(end - tmp);
    std::memset(p, ' ', static_cast<std::size_t>(width - n));
    std::memcpy(p + (width - n), tmp, static_cast<std::size_t>(n));
}

// Right-justify v as %16.8e (e.g. " 1.23456789e-02", "-1.23456789e-02") at p.
void put_e16(char* p, double v) {
    char tmp[32];
    auto [end, ec] = std::to_chars(tmp, tmp + sizeof tmp, v, std::chars_format::scientific, 8);
    (void)ec;
    auto n = static_cast<int>(end - tmp);
    std::memset(p, ' ', static_cast<std::size_t>(16 - n));
    std::memcpy(p + (16 - n), tmp, static_cast<std::size_t>(n));
}

// Uniform in [-1, 1) from 24 bits of one mt19937 draw: the same numbers on every platform.
double jitter(std::mt19937& rng) { return static_cast<double>(rng() >> 8) * (2.0 / 16777216.0) - 1.0; }

void write_header(Out& out, long long nodes) {
    const double gamma = 7.0;
    const double c0 = 50.0;  // m/s
    const double k0 = kDensity * c0 * c0 / gamma;
    char eos[96];
    std::snprintf(eos, sizeof eos, "%10d%10.1f%10.1f%10.1f\n", 1, gamma, k0, 1.0);
    out.put("$ Benchmark deck written by gen_big_deck: ");
    out.put(std::to_string(nodes));
    out.put(" SPH particles on a jittered cubic lattice.\n");
    out.put("*KEYWORD\n");
    out.put("*CONTROL_SPH\n");
    out.put("$#    ncbs     boxid        dt      idim    memory      form     start      maxv\n");
    out.put("         1         0   1.0e+20         3       150        15       0.0   1.0e+15\n");
    out.put("*SECTION_SPH\n");
    out.put("$#   secid      cslh      hmin      hmax    sphini     death     start\n");
    out.put("         1       1.2       0.2       2.0       0.0   1.0e+20       0.0\n");
    out.put("*PART\n");
    out.put("$#                                                               title\n");
    out.put("water block\n");
    out.put("$#     pid     secid       mid     eosid\n");
    out.put("         1         1         1         1\n");
    out.put("*MAT_NULL\n");
    out.put("$#     mid        ro\n");
    out.put("         1    1000.0\n");
    out.put("*EOS_MURNAGHAN\n");
    out.put("$#   eosid     gamma        k0        v0\n");
    out.put(eos);
}

bool write_deck(std::FILE* f, long long nodes, bool clusters, long long coincident) {
    const long long lattice_nodes = nodes;
    if (clusters) nodes += kBlobs * kBlobPoints + 1;
    const long long first_coincident = nodes;
    nodes += coincident;
    Out out(f);
    write_header(out, nodes);

    // Smallest cube holding `nodes` lattice points, centred on the origin; filled x fastest.
    auto side = static_cast<long long>(std::ceil(std::cbrt(static_cast<double>(lattice_nodes))));
    while (side * side * side < lattice_nodes) ++side;
    const double origin = -0.5 * static_cast<double>(side - 1) * kSpacing;

    out.put("*NODE\n");
    out.put("$#   nid               x               y               z      tc      rc\n");
    std::mt19937 rng(20240611u);
    constexpr std::size_t kNodeLine = 8 + 3 * 16 + 2 * 8 + 1;
    const double extent = static_cast<double>(side - 1) * kSpacing;
    for (long long id = 1; id <= nodes; ++id) {
        const long long k = id - 1;
        const long long lattice[3] = {k % side, (k / side) % side, k / (side * side)};
        char* p = out.reserve(kNodeLine);
        put_int(p, 8, id);
        for (int a = 0; a < 3; ++a) {
            double x = origin + (static_cast<double>(lattice[a]) + kJitter * jitter(rng)) * kSpacing;
            if (k >= first_coincident) {  // one place: the lattice's centre
                x = origin + 0.5 * extent;
            } else if (k >= lattice_nodes &&
                       k + 1 < first_coincident) {  // a blob: corner at (f, f, 1/2) of the lattice's box
                const double f = 0.25 * static_cast<double>(1 + (k - lattice_nodes) / kBlobPoints);
                x = origin + (a == 2 ? 0.5 : f) * extent + 0.5 * kBlobWidth * (1 + jitter(rng));
            } else if (k >= lattice_nodes) {  // the stray particle
                x = origin + extent + 10.0;
            }
            put_e16(p + 8 + 16 * a, x);
        }
        put_int(p + 56, 8, 0);
        put_int(p + 64, 8, 0);
        p[72] = '\n';
        out.commit(kNodeLine);
    }

    out.put("*ELEMENT_SPH\n");
    out.put("$#   nid     pid            mass\n");
    char mass[16];
    put_e16(mass, kDensity * kSpacing * kSpacing * kSpacing);
    constexpr std::size_t kElemLine = 8 + 8 + 16 + 1;
    for (long long id = 1; id <= nodes; ++id) {
        char* p = out.reserve(kElemLine);
        put_int(p, 8, id);
        put_int(p + 8, 8, 1);
        std::memcpy(p + 16, mass, 16);
        p[32] = '\n';
        out.commit(kElemLine);
    }
    out.put("*END\n");
    return out.flush();
}

}  // namespace

int main(int argc, char** argv) {
    long long coincident = 0;
    if (argc >= 3 && std::strncmp(argv[argc - 1], "--coincident=", 13) == 0) {
        const std::string_view s = argv[argc - 1] + 13;
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), coincident);
        if (ec != std::errc() || end != s.data() + s.size() || coincident < 0 || coincident > kMaxNodes / 2) {
            std::fprintf(stderr, "gen_big_deck: --coincident=M takes an integer from 0 to %lld, got '%s'\n",
                         kMaxNodes / 2, argv[argc - 1]);
            return 2;
        }
        --argc;
    }
    const bool clusters = argc >= 3 && std::strcmp(argv[argc - 1], "--clusters") == 0;
    if (clusters) --argc;
    if (argc < 2 || argc > 3 || std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0) {
        std::fprintf(stderr, "usage: %s OUTPUT [NODES] [--clusters] [--coincident=M]   (NODES defaults to 1000000)\n",
                     argv[0]);
        return 2;
    }
    long long nodes = 1'000'000;
    if (argc == 3) {
        const std::string_view s = argv[2];
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), nodes);
        if (ec != std::errc() || end != s.data() + s.size() || nodes < 1 ||
            nodes > kMaxNodes - (clusters ? kBlobs * kBlobPoints + 1 : 0) - coincident) {
            std::fprintf(stderr, "gen_big_deck: NODES must be an integer from 1 to %lld, got '%s'\n", kMaxNodes,
                         argv[2]);
            return 2;
        }
    }
    std::FILE* f = std::fopen(argv[1], "wb");
    if (!f) {
        std::fprintf(stderr, "gen_big_deck: cannot open '%s' for writing: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    const bool ok = write_deck(f, nodes, clusters, coincident);
    if (std::fclose(f) != 0 || !ok) {
        std::fprintf(stderr, "gen_big_deck: write to '%s' failed: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    return 0;
}
