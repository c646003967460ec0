// Reference results of another SPH code for the dam break of Marrone et al. (2011, CMAME 200, 1526), the
// numerical cross-check of docs/verification.md §3: TrixiParticles.jl (trixi-framework/TrixiParticles.jl,
// MIT license; files validation/dam_break_2d/validation_reference_{wcsph,edac}_{40,80}.json, unchanged
// since commit 62ac80f987a990fd96521fd2584df70d1974bb1a, read at a720b1d54cf390538e87b2ab5631718f79283b92;
// written by TrixiParticles v0.4.1-51-g8d099b7ff), series "max_x_coord_fluid_1": the largest x over all
// fluid particles (validation/dam_break_2d/sensors.jl), in metres, every 0.01 in T = t sqrt(g / H).
// Sampled here every 0.2 in T (exact samples, no interpolation), to T = 2.4: the front reaches the far
// wall (x = 3.21 m at H/40, 3.2175 m at H/80) at T = 2.4-2.45, after which the series only shows the wall.
//
// Their set-up (the reference files' "meta" block, with examples/fluid/dam_break_2d.jl and
// validation/dam_break_2d/setup_marrone_2011.jl): column H = 0.6 m high, W = 2H wide, tank
// floor(5.366 H / dx) dx long, free-slip walls (4 layers of dummy particles, Adami pressure extrapolation, no
// wall viscosity), rho0 = 1000 kg/m^3, g = 9.81 m/s^2, hydrostatic start, Wendland C2 kernel with h = 2 dx,
// continuity density, Monaghan alpha = 0.01, beta = 0, Runge-Kutta CarpenterKennedy2N54. WCSPH: Cole EOS
// with exponent 1 (p = c0^2 (rho - rho0), tension kept), c0 = 20 sqrt(g H) = 48.52 m/s, density diffusion
// of Molteni & Colagrossi, delta = 0.1. EDAC (entropically damped artificial compressibility): c0 =
// 50 sqrt(g H) = 121.3 m/s. Resolutions H/40 (3,200 fluid particles) and H/80 (12,800); the particles start
// dx/2 from the walls, so max x = W - dx/2 at T = 0.
#pragma once

#include <array>

namespace sphdeck::verify {

inline constexpr double trixi_H = 0.6;  // m, the column height of their runs
inline constexpr double trixi_g = 9.81;

struct TrixiFrontRow {
    double T;                   // t sqrt(g / H)
    double wcsph_40, wcsph_80;  // max x of the fluid [m], WCSPH at H/40 and H/80
    double edac_40, edac_80;    // the same, EDAC
};

inline constexpr std::array<TrixiFrontRow, 13> trixi_dam_break_front = {{
    {0.0, 1.19250, 1.19625, 1.19250, 1.19625},
    {0.2, 1.22102, 1.22892, 1.22023, 1.22821},
    {0.4, 1.30146, 1.31744, 1.29977, 1.31551},
    {0.6, 1.42436, 1.44104, 1.42043, 1.43824},
    {0.8, 1.57291, 1.58830, 1.56702, 1.58522},
    {1.0, 1.73876, 1.75509, 1.73211, 1.75151},
    {1.2, 1.91877, 1.93780, 1.91237, 1.93390},
    {1.4, 2.11086, 2.13336, 2.10536, 2.12912},
    {1.6, 2.31298, 2.33947, 2.30863, 2.33456},
    {1.8, 2.52327, 2.55422, 2.52009, 2.54836},
    {2.0, 2.74027, 2.77479, 2.73772, 2.76828},
    {2.2, 2.96273, 2.99988, 2.95882, 2.99333},
    {2.4, 3.18945, 3.21643, 3.18171, 3.21610},
}};

}  // namespace sphdeck::verify
