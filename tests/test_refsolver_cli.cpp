// `sphdeck run` end to end: the small example deck with --out writes history.csv and snapshots.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "run_sphdeck.hpp"

namespace test_refsolver_cli_cpp {  // each test file's names stay its own in a unity batch

using namespace sphdeck::test;

TEST_CASE("refsolver cli: sphdeck run writes history.csv and .vtp snapshots") {
    TempDir dir;
    const std::string deck = std::string(SPHDECK_SOURCE_DIR) + "/decks/run/water_column_2d.k";
    const Run r = run_sphdeck(dir, "run '" + deck + "' --end-time 0.004 --every 10 --out out --quiet");
    CHECK_MESSAGE(r.exit_code == 0, r.err);
    std::ifstream history(dir.path() / "out" / "history.csv");
    std::string header;
    std::getline(history, header);
    if (!header.empty() && header.back() == '\r') header.pop_back();
    CHECK(header == "step,time,dt,kinetic,internal,total,external_work,momentum_x,momentum_y,momentum_z,mass,active");
    std::size_t rows = 0;
    for (std::string line; std::getline(history, line);) ++rows;
    CHECK(rows >= 10);
    CHECK(std::filesystem::exists(dir.path() / "out" / "particles_000000.vtp"));
    CHECK(std::filesystem::exists(dir.path() / "out" / "particles_000010.vtp"));
    CHECK(r.out.find("mass: start") != std::string::npos);
    CHECK(r.out.find("(unchanged") != std::string::npos);
}

TEST_CASE("refsolver cli: sphdeck run refuses an unsupported FORM with exit 2") {
    TempDir dir;
    const std::string deck = std::string(SPHDECK_SOURCE_DIR) + "/decks/demo/dam_break_2d.k";
    const Run r = run_sphdeck(dir, "run '" + deck + "' --quiet");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("FORM 15") != std::string::npos);
    CHECK(r.err.find("--ignore-unsupported") != std::string::npos);
}

TEST_CASE("refsolver cli: progress lines off a terminal, and an OpenRadioss deck without particles not run") {
    TempDir dir;
    const std::string deck = std::string(SPHDECK_SOURCE_DIR) + "/decks/run/water_column_2d.k";
    const Run r = run_sphdeck(dir, "run '" + deck + "' --end-time 0.004 --progress-every 0");
    CHECK_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("run: step 1, t = ") != std::string::npos);  // stderr is a file here
    CHECK(r.err.find("particles, about") != std::string::npos);
    const std::string radioss = std::string(SPHDECK_SOURCE_DIR) + "/decks/tests/rad/DK012_parameter_silent.rad";
    const Run refused = run_sphdeck(dir, "run '" + radioss + "'");
    CHECK(refused.exit_code == 2);
    CHECK(refused.err.find("the deck has no SPH particles") != std::string::npos);
    CHECK(refused.err.find("not run") != std::string::npos);
}
}  // namespace test_refsolver_cli_cpp
