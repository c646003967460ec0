#include "engine/check_named.hpp"

#include "engine/include_context.hpp"

namespace sphdeck::engine {

NamedCheck check_named_file(const std::string& path, const CheckOptions& options, bool in_context) {
    NamedCheck out;
    if (in_context) {
        IncludeContext context = check_in_context(path, Documents{}, options);
        for (std::size_t k = 0; k < context.decks.size(); ++k) {
            out.included_by.push_back(context.decks[k].deck.sources.file(0).display_name);
            context.decks[k].diagnostics = std::move(context.findings[k]);
        }
        out.checked = std::move(context.decks);
        if (!out.checked.empty()) return out;
    }
    out.checked.push_back(check_file(path, options));
    return out;
}

}  // namespace sphdeck::engine
