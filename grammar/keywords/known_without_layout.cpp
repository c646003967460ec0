// LS-DYNA keywords that neither the hand-written tables nor pydyna's generated layouts describe.
// LS-DYNA accepts them, so they must never be reported as unknown (DK001 stays an info for them:
// their cards are not checked). Each entry names where the keyword is documented.
#include <algorithm>
#include <array>
#include <string_view>

#include "grammar/keywords/schema.hpp"

namespace sphdeck::keywords {

namespace {
using namespace std::string_view_literals;

// Sorted. Source: LS-DYNA Keyword User's Manual, Volume I (R13, R14): the *TERMINATION and
// *USER_INTERFACE / *USER_LOADING chapters (pydyna generates no class for them), and
// *ELEMENT_SOLID_{OPTION} (pydyna has *ELEMENT_SOLID_ORTHO_DOF but not the plain _ORTHO).
constexpr std::array kKnownWithoutLayout = {
    "*ELEMENT_SOLID_ORTHO"sv,
    "*TERMINATION_BODY"sv,
    "*TERMINATION_CONTACT"sv,
    "*TERMINATION_CURVE"sv,
    "*TERMINATION_DELETED_SHELLS"sv,
    "*TERMINATION_DELETED_SHELLS_SET"sv,
    "*TERMINATION_DELETED_SOLIDS"sv,
    "*TERMINATION_DELETED_SOLIDS_SET"sv,
    "*TERMINATION_NODE"sv,
    "*TERMINATION_SENSOR"sv,
    "*USER_INTERFACE_CONDUCTIVITY"sv,
    "*USER_INTERFACE_CONTROL"sv,
    "*USER_INTERFACE_FRICTION"sv,
    "*USER_LOADING"sv,
    "*USER_LOADING_SET"sv,
};
static_assert(std::is_sorted(kKnownWithoutLayout.begin(), kKnownWithoutLayout.end()));
}  // namespace

std::span<const std::string_view> known_without_layout() { return kKnownWithoutLayout; }

bool is_known_without_layout(std::string_view upper_name) {
    return std::binary_search(kKnownWithoutLayout.begin(), kKnownWithoutLayout.end(), upper_name);
}

}  // namespace sphdeck::keywords
