#include "diag/rule_catalog.hpp"

#include <algorithm>
#include <cctype>

namespace sphdeck::diag {
namespace {
// Codes compare case-insensitively, as the registry's lookup does ("sph030" is SPH030).
bool same_code(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}
}  // namespace

std::optional<std::size_t> RuleCatalog::index_of(std::string_view code) const {
    for (std::size_t i = 0; i < rules.size(); ++i)
        if (same_code(rules[i].code, code)) return i;
    return std::nullopt;
}

const RuleMeta* RuleCatalog::find(std::string_view code) const {
    auto i = index_of(code);
    return i ? &rules[*i] : nullptr;
}

}  // namespace sphdeck::diag
