// The test decks and their rules: see rule_decks.hpp.
#include "rule_decks.hpp"

#include <algorithm>

#include "grammar/radioss/reader.hpp"

namespace fs = std::filesystem;

namespace sphdeck::test {

bool is_main_deck(const fs::path& path) {
    const bool engine = grammar::radioss::is_engine_file_name(path.filename().string());
    if (path.extension() != ".k" && (path.extension() != ".rad" || engine)) return false;
    for (const auto& part : path)
        if (part == "include") return false;
    return true;
}

std::vector<fs::path> all_test_decks() {
    // decks/demo too: the demo's mistakes deck declares what `make demo` shows, the dam break none.
    std::vector<fs::path> decks;
    for (const char* folder : {"tests", "demo"}) {
        const fs::path root = fs::path(SPHDECK_SOURCE_DIR) / "decks" / folder;
        if (!fs::is_directory(root)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root))
            if (e.is_regular_file() && is_main_deck(e.path())) decks.push_back(e.path());
    }
    std::sort(decks.begin(), decks.end());
    return decks;
}

std::string rule_of_deck(const fs::path& deck) {
    const std::string name = deck.filename().string();
    std::size_t letters = 0;
    while (letters < name.size() && name[letters] >= 'A' && name[letters] <= 'Z') ++letters;
    if (letters < 2 || letters > 3 || name.size() < letters + 4) return {};
    for (std::size_t i = letters; i < letters + 3; ++i)
        if (name[i] < '0' || name[i] > '9') return {};
    return name[letters + 3] == '_' ? name.substr(0, letters + 3) : std::string();
}

DeckKind kind_of_deck(const fs::path& deck) {
    const std::string code = rule_of_deck(deck);
    if (code.empty()) return DeckKind::Other;
    const std::string rest = deck.stem().string().substr(code.size());
    if (rest.find("fires") != std::string::npos) return DeckKind::Fires;
    if (rest.find("silent") != std::string::npos) return DeckKind::Silent;
    return DeckKind::Other;
}

bool reports_its_rule_lower(const fs::path& deck) {
    const std::string name = deck.filename().string();
    return name == "DK001_silent_spellings.k"             // infos and warnings for names LS-DYNA may read
           || name == "DK017_silent_hypermesh_0000.rad";  // the info, not the warning: no starter block follows
}

}  // namespace sphdeck::test
