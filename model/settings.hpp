// Enumerated settings as named enums (design.md habit 6): bare integers stop at the schema.
#pragma once

#include <string_view>

namespace sphdeck::model {

// *CONTROL_SPH IDIM.
enum class Dimension : int { Unset = 0, PlaneStrain = 2, ThreeD = 3, Axisymmetric = -2 };

// *CONTROL_SPH FORM (lsdyna-sph-cards.md §1).
enum class Form : int {
    Default = 0,
    Renormalized = 1,
    Symmetric = 2,
    SymmetricRenormalized = 3,
    Tensor = 4,
    FluidParticle = 5,
    FluidRenormalized = 6,
    TotalLagrangian = 7,
    TotalLagrangianRenormalized = 8,
    Adaptive = 9,               // ASPH
    AdaptiveRenormalized = 10,  // renormalized ASPH
    MovingLeastSquares = 12,
    Incompressible = 13,
    EnhancedFluid = 15,
    EnhancedFluidRenormalized = 16,
};

// *CONTROL_SPH INI: how the initial smoothing length is computed.
enum class IniMode : int { BucketSort = 0, Global = 1, FromMass = 2 };

// *CONTROL_SPH IAVIS.
enum class ArtificialViscosity : int { Monaghan = 0, SolidBulk = 1 };

// *CONTROL_SPH IEROD.
enum class ErosionMode : int { StayActive = 0, PartlyDeactivated = 1, FullyDeactivated = 2, DeviatoricOnly = 3 };

// *SECTION_SPH SPHKERN.
enum class Kernel : int { CubicSpline = 0, QuinticSpline = 1, Quadratic = 2, QuarticBSpline = 3 };

std::string_view to_string(Form f);
std::string_view to_string(Dimension d);

inline bool is_asph(Form f) { return f == Form::Adaptive || f == Form::AdaptiveRenormalized; }
inline bool is_mpp_only(Form f) { return f == Form::MovingLeastSquares || f == Form::Incompressible; }
inline bool is_enhanced_fluid(Form f) { return f == Form::EnhancedFluid || f == Form::EnhancedFluidRenormalized; }
inline bool is_two_dimensional(Dimension d) { return d == Dimension::PlaneStrain || d == Dimension::Axisymmetric; }

}  // namespace sphdeck::model
