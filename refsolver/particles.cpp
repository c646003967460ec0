#include "refsolver/particles.hpp"

#include <algorithm>

namespace sphdeck::refsolver {

namespace {

// The real-only arrays that carry state across a rebuild (the rates and the positions at the
// build do not: they are recomputed right after it; but d rho/dt, which FORM 0's Omega reads from
// the last evaluation: grad_h.hpp).
template <typename F>
void for_each_state_array(Particles& s, F&& f) {
    f(s.e), f(s.h_low), f(s.h_high), f(s.drho);
    f(s.vx_half), f(s.vy_half), f(s.vz_half), f(s.rho_half), f(s.e_half), f(s.h_half);
}

template <typename F>
void for_each_real_array(Particles& s, F&& f) {
    for_each_state_array(s, f);
    f(s.ax), f(s.ay), f(s.az), f(s.de), f(s.dh);
    f(s.x_built), f(s.y_built), f(s.z_built);
}

template <typename F>
void for_each_pair_array(Particles& s, F&& f) {
    f(s.x), f(s.y), f(s.z), f(s.vx), f(s.vy), f(s.vz), f(s.rho), f(s.p), f(s.c), f(s.h), f(s.m);
}

// spare[k] = v[order[k]] for k < order.size(), then the entries beyond (the ghosts) as they are.
// Called inside a parallel region: the threads share the loop and do not wait at its end.
template <typename T>
void gather_into(std::vector<T>& spare, const std::vector<T>& v, const std::vector<std::uint32_t>& order) {
    const std::size_t n = order.size(), total = v.size();
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < total; ++k) spare[k] = k < n ? v[order[k]] : v[k];
}

}  // namespace

void Particles::resize_real(std::size_t n) {
    real = n;
    ghost_source.clear(), ghost_planes.clear();
    for_each_real_array(*this, [n](std::vector<double>& v) { v.assign(n, 0.0); });
    part.assign(n, 0), model_index.assign(n, 0), active.assign(n, 1);
    if (solid) dstress.assign(n, SymmetricTensor{}), stress_half.assign(n, SymmetricTensor{});
    resize_pair_arrays();
}

void Particles::resize_pair_arrays() {
    const std::size_t n = total();
    for_each_pair_array(*this, [n](std::vector<double>& v) { v.resize(n, 0.0); });
    interacting.resize(n, 0);
    correction.resize(n, {1, 1, 1, 0, 0, 0});
    omega.resize(n, 1.0);
    if (solid) stress.resize(n, SymmetricTensor{});
}

void Particles::permute(const std::vector<std::uint32_t>& order, int threads) {
    // Every array is gathered into its spare in one parallel region (one fork and join, which
    // matters on a loaded machine), then the two are swapped.
    std::vector<std::vector<double>*> arrays;
    for_each_pair_array(*this, [&](std::vector<double>& v) { arrays.push_back(&v); });
    for_each_state_array(*this, [&](std::vector<double>& v) { arrays.push_back(&v); });
    spares.doubles.resize(arrays.size());
    for (std::size_t a = 0; a < arrays.size(); ++a) spares.doubles[a].resize(arrays[a]->size());
    spares.interacting.resize(interacting.size()), spares.active.resize(active.size());
    spares.correction.resize(correction.size());
    spares.stress.resize(stress.size()), spares.stress_half.resize(stress_half.size());  // empty for fluids
    spares.part.resize(part.size()), spares.model_index.resize(model_index.size()),
        spares.renumber.resize(order.size());
#pragma omp parallel num_threads(threads)
    {
        for (std::size_t a = 0; a < arrays.size(); ++a) gather_into(spares.doubles[a], *arrays[a], order);
        gather_into(spares.interacting, interacting, order), gather_into(spares.active, active, order);
        gather_into(spares.correction, correction, order);
        gather_into(spares.stress, stress, order), gather_into(spares.stress_half, stress_half, order);
        gather_into(spares.part, part, order), gather_into(spares.model_index, model_index, order);
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < order.size(); ++k) spares.renumber[order[k]] = static_cast<std::uint32_t>(k);
    }
    for (std::size_t a = 0; a < arrays.size(); ++a) arrays[a]->swap(spares.doubles[a]);
    interacting.swap(spares.interacting), active.swap(spares.active), correction.swap(spares.correction);
    stress.swap(spares.stress), stress_half.swap(spares.stress_half);
    part.swap(spares.part), model_index.swap(spares.model_index);
    for (std::uint32_t& source : ghost_source) source = spares.renumber[source];
}

}  // namespace sphdeck::refsolver
