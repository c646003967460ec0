// Martin & Moyce (1952) surge-front data, T = t sqrt(2 g / a) against Z/a, as tabulated in
// verification.md §3 (from pypr/pysph `pysph/examples/db_exp_data.py`).
#pragma once

#include <array>
#include <span>
#include <string_view>

namespace sphdeck::verify {

struct FrontPoint {
    double T, z_over_a;
};

struct FrontSeries {
    std::string_view column;  // the experiment's column width
    std::span<const FrontPoint> points;
};

inline constexpr std::array<FrontPoint, 10> martin_moyce_1125 = {{{0.849, 1.245},
                                                                  {1.212, 1.443},
                                                                  {1.602, 1.884},
                                                                  {2.283, 2.689},
                                                                  {2.950, 3.728},
                                                                  {3.598, 4.528},
                                                                  {3.905, 4.999},
                                                                  {4.592, 5.841},
                                                                  {4.961, 6.271},
                                                                  {5.316, 6.717}}};
inline constexpr std::array<FrontPoint, 15> martin_moyce_225 = {{{0.832, 1.217},
                                                                 {1.219, 1.474},
                                                                 {1.997, 2.292},
                                                                 {2.547, 2.995},
                                                                 {3.345, 4.134},
                                                                 {4.034, 4.944},
                                                                 {4.418, 5.881},
                                                                 {5.091, 6.980},
                                                                 {5.685, 7.945},
                                                                 {6.306, 8.966},
                                                                 {6.822, 9.986},
                                                                 {7.439, 10.963},
                                                                 {8.031, 11.977},
                                                                 {8.633, 13.005},
                                                                 {9.237, 13.970}}};

inline const std::array<FrontSeries, 2>& martin_moyce() {
    static const std::array<FrontSeries, 2> series = {
        {{"a = 1.125 in", martin_moyce_1125}, {"a = 2.25 in", martin_moyce_225}}};
    return series;
}

}  // namespace sphdeck::verify
