// The table from LSP method names to the feature functions of lsp/features.hpp, and the
// capabilities they announce. A feature joins by adding its row here.
#include "lsp/features.hpp"

#include <array>

namespace sphdeck::lsp {
namespace {
using Handler = nlohmann::json (*)(const CheckedDeck&, grammar::FileId, const nlohmann::json& params);

struct FeatureRow {
    std::string_view method;      // "textDocument/hover"
    std::string_view capability;  // its key in ServerCapabilities
    Handler handler;
};

// One row a feature (filled in as the features land).
constexpr std::array<FeatureRow, 0> kFeatures{};
}  // namespace

FeatureAnswer answer_feature(std::string_view method, const CheckedDeck& deck, grammar::FileId file,
                             const nlohmann::json& params) {
    for (const auto& row : kFeatures)
        if (row.method == method) return {true, row.handler(deck, file, params)};
    return {};
}

nlohmann::json feature_capabilities() {
    nlohmann::json capabilities = nlohmann::json::object();
    for (const auto& row : kFeatures) capabilities[std::string(row.capability)] = true;
    return capabilities;
}

}  // namespace sphdeck::lsp
