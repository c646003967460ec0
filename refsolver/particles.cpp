#include "refsolver/particles.hpp"

namespace sphdeck::refsolver {

namespace {

template <typename T>
void reorder(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::vector<T>& scratch) {
    scratch.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) scratch[k] = v[order[k]];
    v.swap(scratch);
}

template <typename F>
void for_each_real_array(Particles& s, F&& f) {
    f(s.e), f(s.h_low), f(s.h_high), f(s.ax), f(s.ay), f(s.az), f(s.drho), f(s.de), f(s.dh);
    f(s.vx_half), f(s.vy_half), f(s.vz_half), f(s.rho_half), f(s.e_half), f(s.h_half);
    f(s.x_built), f(s.y_built), f(s.z_built);
}

template <typename F>
void for_each_pair_array(Particles& s, F&& f) {
    f(s.x), f(s.y), f(s.z), f(s.vx), f(s.vy), f(s.vz), f(s.rho), f(s.p), f(s.c), f(s.h), f(s.m);
}

}  // namespace

void Particles::resize_real(std::size_t n) {
    real = n;
    ghost_source.clear(), ghost_planes.clear();
    for_each_real_array(*this, [n](std::vector<double>& v) { v.assign(n, 0.0); });
    part.assign(n, 0), model_index.assign(n, 0), active.assign(n, 1);
    resize_pair_arrays();
}

void Particles::resize_pair_arrays() {
    const std::size_t n = total();
    for_each_pair_array(*this, [n](std::vector<double>& v) { v.resize(n, 0.0); });
    interacting.resize(n, 0);
    correction.resize(n, {1, 1, 1, 0, 0, 0});
}

void Particles::permute(const std::vector<std::uint32_t>& order) {
    std::vector<double> scratch;
    // Pair arrays: the real part reordered, the ghost part kept.
    const auto reorder_front = [&](auto& v, auto& buffer) {
        buffer.assign(v.begin(), v.end());
        for (std::size_t k = 0; k < order.size(); ++k) buffer[k] = v[order[k]];
        v.swap(buffer);
    };
    for_each_pair_array(*this, [&](std::vector<double>& v) { reorder_front(v, scratch); });
    std::vector<std::uint8_t> s8;
    reorder_front(interacting, s8);
    std::vector<std::array<double, 6>> s6;
    reorder_front(correction, s6);
    for_each_real_array(*this, [&](std::vector<double>& v) { reorder(v, order, scratch); });
    std::vector<std::uint32_t> s32;
    reorder(part, order, s32), reorder(model_index, order, s32);
    reorder(active, order, s8);
    std::vector<std::uint32_t> renumber(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) renumber[order[k]] = static_cast<std::uint32_t>(k);
    for (std::uint32_t& source : ghost_source) source = renumber[source];
}

}  // namespace sphdeck::refsolver
