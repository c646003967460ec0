// The OpenRadioss engine's listing of its QA case qa-tests/miniqa/SPH/WavesCompression
// (public OpenRadioss/OpenRadioss repository, file reference/CUBC_0001.out, run 11 Jan 2024, one
// domain, one thread; the repository is AGPL-3.0, its figures are used here as verification data
// with the source named): per cycle the time, the time step and the internal and kinetic energy,
// as printed (4 significant digits). Its data/ref.extract (the QA gate) holds cycle 44, time 29.52.
// The deck behind it: decks/verification/make_radioss_waves.py.
#pragma once

#include <array>

// A table laid out by hand, one row per line:
// clang-format off

namespace sphdeck::verify::radioss_waves {

struct ListingRow {
    int cycle;
    double time, dt, internal, kinetic;
};

inline constexpr double total_mass = 597.9;  // the listing's TOTAL MASS (4 digits), unchanged over the run
inline constexpr int final_cycle = 44;       // data/ref.extract: CYCLE 44, TIME 29.52
inline constexpr double final_time = 29.52;

inline constexpr std::array<ListingRow, 45> listing = {{
    {0, 0.0, 0.8008, 0.004994, 0.4276},
    {1, 0.8008, 0.7222, 0.01964, 0.4134},
    {2, 1.523, 0.7222, 0.03401, 0.3989},
    {3, 2.245, 0.7114, 0.04787, 0.3853},
    {4, 2.957, 0.697, 0.06119, 0.3723},
    {5, 3.654, 0.6946, 0.07426, 0.3596},
    {6, 4.348, 0.6909, 0.08741, 0.3468},
    {7, 5.039, 0.6689, 0.1004, 0.334},
    {8, 5.708, 0.6757, 0.1128, 0.3218},
    {9, 6.384, 0.6666, 0.1253, 0.3096},
    {10, 7.05, 0.6662, 0.1375, 0.2976},
    {11, 7.716, 0.6674, 0.1498, 0.2855},
    {12, 8.384, 0.6512, 0.162, 0.2735},
    {13, 9.035, 0.6457, 0.1738, 0.2618},
    {14, 9.681, 0.6452, 0.1856, 0.2503},
    {15, 10.33, 0.6617, 0.1974, 0.2387},
    {16, 10.99, 0.6479, 0.2094, 0.2268},
    {17, 11.64, 0.6473, 0.2211, 0.2153},
    {18, 12.28, 0.6502, 0.2328, 0.2038},
    {19, 12.93, 0.677, 0.2446, 0.1922},
    {20, 13.61, 0.6626, 0.2568, 0.1801},
    {21, 14.27, 0.6711, 0.2688, 0.1683},
    {22, 14.94, 0.6625, 0.2809, 0.1564},
    {23, 15.61, 0.6697, 0.2928, 0.1447},
    {24, 16.28, 0.6704, 0.3048, 0.1329},
    {25, 16.95, 0.6629, 0.3168, 0.1211},
    {26, 17.61, 0.6612, 0.3286, 0.1094},
    {27, 18.27, 0.655, 0.3403, 0.09791},
    {28, 18.93, 0.6483, 0.3516, 0.08664},
    {29, 19.57, 0.6539, 0.3641, 0.07498},
    {30, 20.23, 0.6631, 0.3763, 0.06291},
    {31, 20.89, 0.6641, 0.3882, 0.05112},
    {32, 21.55, 0.6714, 0.3997, 0.0398},
    {33, 22.23, 0.6676, 0.4107, 0.02903},
    {34, 22.89, 0.6611, 0.4206, 0.01935},
    {35, 23.56, 0.6717, 0.4288, 0.01128},
    {36, 24.23, 0.666, 0.4349, 0.005275},
    {37, 24.89, 0.6567, 0.4381, 0.002109},
    {38, 25.55, 0.654, 0.439, 0.001645},
    {39, 26.2, 0.6479, 0.4367, 0.003956},
    {40, 26.85, 0.6488, 0.4314, 0.009217},
    {41, 27.5, 0.6531, 0.4237, 0.01694},
    {42, 28.15, 0.6713, 0.4142, 0.02651},
    {43, 28.82, 0.6964, 0.4033, 0.03749},
    {44, 29.52, 0.7046, 0.3925, 0.04892},
}};

}  // namespace sphdeck::verify::radioss_waves
// clang-format on
