#include "lsp/deck_settings.hpp"

#include <algorithm>
#include <cctype>
#include <string>

#include "engine/config_file.hpp"
#include "grammar/deck_files.hpp"

namespace sphdeck::lsp {
namespace fs = std::filesystem;

DeckSettings settings_for(const fs::path& deck, const std::vector<fs::path>& roots) {
    DeckSettings out;
    std::optional<fs::path> config = engine::find_config(deck);
    for (std::size_t i = 0; !config && i < roots.size(); ++i) {
        std::error_code ec;
        for (std::string_view name : engine::config_names)
            if (fs::is_regular_file(roots[i] / name, ec)) {
                config = roots[i] / name;
                break;
            }
    }
    lint::Config settings;
    if (config) {
        if (auto error = engine::load_config(config->string(), settings)) {
            out.error = std::move(error);
            settings = lint::Config{};
        }
    }
    out.options = engine::options_for(std::move(settings));  // as `sphdeck check`, without command-line overrides
    return out;
}

bool is_deck(const fs::path& path, std::string_view text) {
    if (grammar::has_deck_extension(path)) return true;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.remove_suffix(1);
        if (line.empty() || line.front() == '$') continue;
        if (line.rfind("#RADIOSS", 0) == 0) return true;
        if (line.front() == '#') continue;  // a Radioss comment
        return line.front() == '*' || line.front() == '/';
    }
    return false;
}

}  // namespace sphdeck::lsp
