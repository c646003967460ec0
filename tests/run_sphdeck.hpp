// Runs the built `sphdeck` binary (SPHDECK_BINARY) for end-to-end tests of exit codes and streams.
#pragma once

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "test_support.hpp"

namespace sphdeck::test {

struct Run {
    std::string out, err;  // stdout and stderr, kept apart: machine formats own stdout
    int exit_code = -1;
};

// Runs `sphdeck ARGS` in folder `dir`; the caller single-quotes arguments that need it. `prefix` goes
// before the binary ("timeout 20 ").
inline Run run_sphdeck(const TempDir& dir, const std::string& args, const std::string& prefix = "") {
    const std::string out = (dir.path() / "stdout.txt").string(), err = (dir.path() / "stderr.txt").string();
    const std::string command = "cd '" + dir.path().string() + "' && " + prefix + "'" + SPHDECK_BINARY + "' " + args +
                                " > '" + out + "' 2> '" + err + "'";
    const int status = std::system(command.c_str());
    auto slurp = [](const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    Run r{slurp(out), slurp(err), WIFEXITED(status) ? WEXITSTATUS(status) : -1};
    return r;
}

}  // namespace sphdeck::test
