// Replays the inputs the fuzzers found (fuzz/corpus/<target>/) through the same target bodies,
// so every crash fixed stays fixed in the ordinary test run, with or without the sanitizers.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/targets.hpp"

namespace test_fuzz_corpus_cpp {  // each test file's names stay its own in a unity batch

namespace fs = std::filesystem;

TEST_CASE("fuzz corpus: every saved input runs through its target") {
    const fs::path corpus = fs::path(SPHDECK_SOURCE_DIR) / "fuzz" / "corpus";
    REQUIRE(fs::is_directory(corpus));
    std::size_t replayed = 0;
    for (const auto& dir : fs::directory_iterator(corpus)) {
        if (!dir.is_directory()) continue;
        const auto target = sphdeck::fuzz::find_target(dir.path().filename().string());
        INFO("corpus folder " << dir.path().filename().string());
        const bool known_target = target != nullptr;
        REQUIRE(known_target);
        for (const auto& file : fs::directory_iterator(dir.path())) {
            if (!file.is_regular_file()) continue;
            std::ifstream in(file.path(), std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            INFO("input " << file.path().string());
            target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
            ++replayed;
        }
    }
    CHECK(replayed > 0);
}
}  // namespace test_fuzz_corpus_cpp
