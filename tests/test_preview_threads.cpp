// The preview on several threads and without copies (issue 30): the grid, the nearest neighbours
// and the counts are the same on 1 thread as on 2, 4 and 16 (issue 40), bit for bit; the rules' preview (no
// per-particle arrays) and a model whose particles are not in node order give the same numbers.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "preproc/nearest_neighbours.hpp"
#include "preproc/neighbour_grid.hpp"
#include "preproc/particle_positions.hpp"
#include "preproc/preview.hpp"

namespace test_preview_threads_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck;

namespace {

// Runs f() with `threads` OpenMP threads, then puts the count back.
template <typename F>
auto with_threads(int threads, F&& f) {
#ifdef _OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    auto r = f();
    omp_set_num_threads(before);
    return r;
#else
    (void)threads;
    return f();
#endif
}

struct Points {
    std::vector<double> x, y, z;
};

// A jittered lattice of side^3 points (spacing 1), plus `clusters` tight blobs and a stray point:
// cells of very different fill, and empty runs of cells.
Points cloud(int side, int clusters, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    Points p;
    for (int k = 0; k < side; ++k)
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i)
                p.x.push_back(i + u(rng)), p.y.push_back(j + u(rng)), p.z.push_back(k + u(rng));
    for (int c = 0; c < clusters; ++c)
        for (int i = 0; i < 800; ++i)
            p.x.push_back(5 + 0.01 * u(rng)), p.y.push_back(7 + c), p.z.push_back(3 + 0.01 * u(rng));
    p.x.push_back(3 * side), p.y.push_back(0.5), p.z.push_back(0.5);
    return p;
}

struct GridPicture {
    std::vector<std::uint32_t> order;
    std::vector<double> x;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    bool operator==(const GridPicture&) const = default;
};

GridPicture picture(const Points& p, double cell) {
    const preproc::NeighbourGrid g(p.x, p.y, p.z, cell);
    GridPicture out{g.order(), {g.x().begin(), g.x().end()}, {}};
    for (std::size_t o = 0; o < g.occupied(); ++o) out.ranges.push_back(g.occupied_range(o));
    return out;
}

model::Model lattice_model(int side, bool shuffled_nodes) {
    model::Model m;
    m.controls.sph.idim = model::Dimension::ThreeD;
    model::Section s;
    s.id = "1", s.keyword = "*SECTION_SPH", s.sph = true;
    m.sections.push_back(s);
    for (const char* id : {"1", "2"}) {
        model::Part part;
        part.id = id, part.section = model::Id("1"), part.material = model::Id("1");
        m.parts.push_back(part);
    }
    model::Material mat;
    mat.id = "1", mat.keyword = "*MAT_NULL", mat.density = 1000.0;
    m.materials.push_back(mat);
    const Points p = cloud(side, 0, 7);
    const std::size_t n = p.x.size();
    std::vector<std::size_t> at(n);
    std::iota(at.begin(), at.end(), 0);
    if (shuffled_nodes) std::shuffle(at.begin(), at.end(), std::mt19937(3));
    m.nodes.id.resize(n), m.nodes.x.resize(n), m.nodes.y.resize(n), m.nodes.z.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        m.nodes.id.set(at[i], static_cast<long long>(i + 1));
        m.nodes.x[at[i]] = p.x[i], m.nodes.y[at[i]] = p.y[i], m.nodes.z[at[i]] = p.z[i];
        m.particles.node.push_back(static_cast<long long>(i + 1));
        m.particles.part.push_back(p.x[i] < side / 2.0 ? 1 : 2);
        m.particles.mass.push_back(1000.0), m.particles.volume.push_back(0), m.particles.line.push_back(0);
    }
    m.particles.node.push_back(static_cast<long long>(n + 100));  // a particle without a node
    m.particles.part.push_back(1), m.particles.mass.push_back(1000.0), m.particles.volume.push_back(0);
    m.particles.line.push_back(0);
    return m;
}

}  // namespace

TEST_CASE("preview threads: the grid bins the same on 1 and 4 threads") {
    const Points p = cloud(40, 3, 11);             // 64,000 lattice points and 2,400 clustered
    for (double cell : {0.9, 1.5, 2.5, 1000.0}) {  // hashed; dense: about a point per cell, several, one for all
        const GridPicture one = with_threads(1, [&] { return picture(p, cell); });
        const GridPicture four = with_threads(4, [&] { return picture(p, cell); });
        CHECK(one == four);
    }
}

TEST_CASE("preview threads: nearest neighbours and counts are the same on 1, 2, 4 and 16 threads") {
    const Points p = cloud(24, 2, 5);  // 13,824 lattice points and 1,600 clustered
    const auto nn = [&] { return preproc::nearest_neighbours_grid(p.x, p.y, p.z); };
    // Two groups of different supports (the mixed counting loop) and one for all (the uniform one).
    std::vector<std::uint32_t> one_group(p.x.size(), 0), two_groups(p.x.size(), 0);
    for (std::size_t i = 0; i < p.x.size(); ++i) two_groups[i] = p.x[i] < 12.0 ? 0 : 1;
    const double support[] = {2.4, 1.9}, tolerance[] = {1e-9, 1e-9};
    const auto counts = [&](const std::vector<std::uint32_t>& group) {
        return [&] {
            return preproc::count_neighbours(p.x, p.y, p.z, preproc::GroupedRadii{group, support, tolerance});
        };
    };
    const preproc::NearestNeighbours a = with_threads(1, nn);
    const preproc::NeighbourCounts c = with_threads(1, counts(one_group)), m = with_threads(1, counts(two_groups));
    for (int threads : {2, 4, 16}) {
        CAPTURE(threads);
        const preproc::NearestNeighbours b = with_threads(threads, nn);
        CHECK(a.distance == b.distance);
        CHECK(a.index == b.index);
        const preproc::NeighbourCounts d = with_threads(threads, counts(one_group));
        CHECK(c.count == d.count);
        CHECK(c.coincident == d.coincident);
        const preproc::NeighbourCounts e = with_threads(threads, counts(two_groups));
        CHECK(m.count == e.count);
        CHECK(m.coincident == e.coincident);
    }
}

TEST_CASE("preview threads: positions in place, in node order or not, and the rules' preview without arrays") {
    const model::Model in_order = lattice_model(34, false), shuffled = lattice_model(34, true);
    CHECK(!preproc::ParticlePositions(in_order).in_place());  // the last particle has no node
    const preproc::Preview full = preproc::compute_preview(in_order);
    preproc::PreviewOptions lean_options;
    lean_options.particle_arrays = false;
    for (const model::Model* m : {&in_order, &shuffled}) {
        const preproc::Preview lean = with_threads(4, [&] { return preproc::compute_preview(*m, lean_options); });
        const preproc::Preview arrays = preproc::compute_preview(*m);
        CHECK(lean.particles.x.empty());
        CHECK(lean.particles.mass.empty());
        CHECK(arrays.particles.x == full.particles.x);
        CHECK(arrays.particles.neighbours == full.particles.neighbours);
        for (const preproc::Preview* p : {&lean, &arrays}) {
            CHECK(p->particles.nn_distance == full.particles.nn_distance);
            CHECK(p->particles.located == full.particles.located);
            CHECK(p->particles.part == full.particles.part);
            CHECK(p->coincident == full.coincident);
            REQUIRE(p->parts.size() == full.parts.size());
            for (std::size_t q = 0; q < full.parts.size(); ++q) {
                CHECK(p->parts[q].spacing == full.parts[q].spacing);
                CHECK(p->parts[q].h0 == full.parts[q].h0);
                CHECK(p->parts[q].neighbours.median == full.parts[q].neighbours.median);
                CHECK(p->parts[q].neighbours.max == full.parts[q].neighbours.max);
                CHECK(p->parts[q].mass_median == full.parts[q].mass_median);
                CHECK(p->parts[q].notes == full.parts[q].notes);
            }
        }
    }
    // One part, every node in order: the positions are the model's own arrays.
    model::Model whole = lattice_model(10, false);
    whole.particles.node.pop_back(), whole.particles.part.pop_back(), whole.particles.mass.pop_back();
    whole.particles.volume.pop_back(), whole.particles.line.pop_back();
    const preproc::ParticlePositions at(whole);
    CHECK(at.in_place());
    CHECK(at.all().x.data() == whole.nodes.x.data());
}
}  // namespace test_preview_threads_cpp
