#include "preproc/smoothing_length.hpp"

#include <algorithm>
#include <cmath>

namespace sphdeck::preproc {

double kernel_support_factor(model::Kernel kernel) { return kernel == model::Kernel::QuinticSpline ? 3.0 : 2.0; }

double particle_volume(double mass, bool volume_flag, double density) {
    if (volume_flag || mass < 0) return std::abs(mass);
    return density > 0 ? mass / density : 0.0;
}

double particle_mass(double mass, bool volume_flag, double density) {
    if (volume_flag || mass < 0) return std::abs(mass) * std::max(density, 0.0);
    return mass;
}

SmoothingLength initial_smoothing_length(const SmoothingInputs& in) {
    static const model::Section defaults;
    const model::Section& s = in.section ? *in.section : defaults;
    SmoothingLength out;
    out.mode = in.mode;
    if (s.sphini.value > 0) {
        out.h0 = s.sphini.value, out.from_sphini = true;
        return out;
    }
    const double cslh = s.cslh.value;
    if (in.mode == model::IniMode::FromMass) {
        double largest = 0;
        for (double v : in.volume)
            if (v > 0) largest = std::max(largest, std::pow(v, 1.0 / in.dimension));
        if (largest > 0) {
            out.h0 = cslh * largest;
            return out;
        }
        out.note = "INI 2: no particle volume (mass / density) is known; h0 from the nearest-neighbour distances";
        out.mode = model::IniMode::BucketSort;
    }
    if (in.nn_distance.size() < 2) {
        out.note += std::string(out.note.empty() ? "" : "; ") + "a single particle has no nearest neighbour: no h0";
        return out;
    }
    out.h0 = cslh * *std::max_element(in.nn_distance.begin(), in.nn_distance.end());
    return out;
}

}  // namespace sphdeck::preproc
