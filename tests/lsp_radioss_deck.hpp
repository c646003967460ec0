// The small OpenRadioss deck the editor tests ask about: a /PART naming its /PROP/SPH and /MAT/LAW6, one
// node and its particle.
#pragma once

#include <string_view>

namespace sphdeck::test {

inline constexpr std::string_view lsp_radioss_deck = R"(#RADIOSS STARTER
/BEGIN
LSP
      2026
                  kg                  mm                  ms
                  kg                  mm                  ms
/PART/2
water
#  prop_ID    mat_ID subset_ID
         2         3         0
/PROP/SPH/2
water particles
#                 mp                  qa                  qb            alpha_cs   skew_ID      h_1D
              8.0E-6                 2.0                 1.0                 0.0         0         0
#    Order                   h             Xi_Stab                          hmin                hmax
         0                 2.4                 0.0
/MAT/LAW6/3
water
#              RHO_I
              1.0E-6
#                 Nu                Pmin
                 0.0                 0.0
/NODE
#  node_ID                   X                   Y                   Z
      1001                 1.0                 1.0                 1.0
/SPHCEL/2
#  node_ID      Type                MASS
      1001         0
/END
)";

}  // namespace sphdeck::test
