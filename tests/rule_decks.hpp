// The test decks and the rules they belong to (decks/README.md): a deck under decks/tests/ whose file
// name starts with a rule code ("SPH030_fires.k", "DK029_straddle_silent.k") is one of that rule's decks;
// one named *fires* must report the rule, one named *silent* must not. Read by the deck runner
// (tests/test_decks.cpp) and the registry's row test (tests/test_rule_rows.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sphdeck::test {

// A file the deck runner checks on its own: a *.k or starter *.rad deck, not a Radioss engine deck
// (<run>_0001.rad, read with its starter deck) and nothing under a folder named `include`.
bool is_main_deck(const std::filesystem::path& path);

// Every main deck under decks/tests/ and decks/demo/, sorted.
std::vector<std::filesystem::path> all_test_decks();

// "SPH030" for ".../SPH030_fires.k": the code its file name starts with (capitals, three digits, '_'),
// or "" for a deck named after no rule.
std::string rule_of_deck(const std::filesystem::path& deck);

enum class DeckKind { Fires, Silent, Other };
// From the file name after the code: "fires" or "silent" in it; Other for neither (or no code).
DeckKind kind_of_deck(const std::filesystem::path& deck);

// The near misses named *silent* that still report their rule, lower than the firing case does: the
// rule's info (or warning) where the firing deck has its error (or warning). Each says so in its comments.
bool reports_its_rule_lower(const std::filesystem::path& deck);

// "DK001 DK002 ...": the codes CMakeLists.txt gave a ctest entry rule-CODE (read from the registry's rows
// at configure time; generated into the build tree).
std::string_view rule_ctest_codes();

}  // namespace sphdeck::test
