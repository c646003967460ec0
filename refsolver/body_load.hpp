// *LOAD_BODY_X|Y|Z with its *DEFINE_CURVE: a uniform acceleration of every particle.
// Sign (LS-DYNA convention, stated in the task brief and in decks/demo/dam_break_2d.k; not in the
// reference files, so [unverified]): the card gives the acceleration of the *base*; the material
// feels the opposite, a_body = -SF * f(t) along the axis. Gravity along -Y is *LOAD_BODY_Y, SF = 9.81.
#pragma once

#include <array>
#include <vector>

namespace sphdeck::refsolver {

// A *DEFINE_CURVE: points (SFA * a_k + OFFA, SFO * o_k + OFFO), linear between them and held
// constant beyond the first and last points ([unverified] for LS-DYNA, which may extrapolate).
struct LoadCurve {
    std::vector<double> t, f;  // abscissae (increasing) and ordinates
    double at(double time) const;
};

struct BodyLoad {
    int axis = 1;      // 0 x, 1 y, 2 z
    double scale = 1;  // SF
    LoadCurve curve;
};

// The body acceleration at `time`, summed over the loads.
std::array<double, 3> body_acceleration(const std::vector<BodyLoad>& loads, double time);

}  // namespace sphdeck::refsolver
