// The initial smoothing length h0 of an SPH part (sph-algorithms.md §2), by INI mode:
// - SPHINI > 0 on the section: h0 = SPHINI (CSLH does not apply), whatever the mode;
// - INI 0 (bucket sort) and INI 1 (global): h0 = CSLH * max_i d_i, d_i the distance from particle i
//   to its nearest particle of the same part (a maximum of minima). The two modes differ only in
//   how d_i is searched (grid or all pairs, nearest_neighbours.hpp), not in the rule;
// - INI 2 (from the mass): h0 = CSLH * max_i V_i^(1/d), V_i = m_i / rho0 (or the volume a negative
//   mass or *ELEMENT_SPH_VOLUME gives). Per part maximum, as for INI 0/1: whether LS-DYNA takes the
//   maximum or each particle's own value is not known; on a uniform fill they agree.
// During the run h stays within [HMIN * h0, HMAX * h0].
#pragma once

#include <span>
#include <string>

#include "model/model.hpp"

namespace sphdeck::preproc {

// Kernel support radius over h: 2 for the cubic spline, 3 for the quintic (Morris 1997). LS-DYNA's
// quadratic and quartic kernels are known by name only; 2 is assumed for them.
double kernel_support_factor(model::Kernel kernel);

// The volume a particle stands for: |mass| when the value is a volume (*ELEMENT_SPH_VOLUME or a
// negative mass), else mass / density; 0 when unknown (density <= 0).
double particle_volume(double mass, bool volume_flag, double density);
// The mass a particle carries: the deck's mass, or density * volume for a volume.
double particle_mass(double mass, bool volume_flag, double density);

struct SmoothingLength {
    double h0 = 0;
    model::IniMode mode = model::IniMode::BucketSort;  // the mode that produced h0
    bool from_sphini = false;
    std::string note;  // why h0 could not follow the mode, in words
};

struct SmoothingInputs {
    const model::Section* section = nullptr;  // nullptr: the *SECTION_SPH defaults
    model::IniMode mode = model::IniMode::BucketSort;
    std::span<const double> nn_distance;  // per particle of the part
    std::span<const double> volume;       // per particle of the part (particle_volume)
    int dimension = 3;
};

SmoothingLength initial_smoothing_length(const SmoothingInputs& in);

}  // namespace sphdeck::preproc
