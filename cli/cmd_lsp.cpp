// sphdeck lsp: the language server on stdin/stdout (lsp/server.hpp). `--stdio` is accepted because
// editors pass it; there is no other transport. Problems with messages are logged on stderr, which
// editors show in their server log.
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <poll.h>
#include <streambuf>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli/commands.hpp"
#include "lsp/server.hpp"

namespace sphdeck::cli {
namespace {

// Standard input as a stream buffer that says how much can be read without blocking (poll), so
// the server reads every message already sent before it handles them, and that hands over what
// one read() returns instead of waiting to fill its buffer.
class StdinBuffer final : public std::streambuf {
protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        ssize_t got;
        do got = ::read(STDIN_FILENO, buffer_, sizeof buffer_);
        while (got < 0 && errno == EINTR);
        if (got <= 0) return traits_type::eof();
        setg(buffer_, buffer_, buffer_ + got);
        return traits_type::to_int_type(*gptr());
    }
    std::streamsize showmanyc() override {
        pollfd fd{STDIN_FILENO, POLLIN, 0};
        if (::poll(&fd, 1, 0) > 0 && (fd.revents & (POLLIN | POLLHUP))) return 1;  // read() will not block
        return 0;
    }

private:
    char buffer_[65536];
};

// Between the parallel regions of a check, libgomp's idle workers spin (its default wait policy): on
// the busy 2-core VM that took about 200 ms of CPU from an open of a 1M-particle deck, and wall time
// from the check's own thread (bench/README.md, issue 45). The server waits for the editor most of its
// life and its checks have few parallel regions, so its workers sleep instead. libgomp reads the
// policy once, when it loads: the server starts itself again with OMP_WAIT_POLICY=passive unless the
// user chose a policy. Where that cannot be done (no /proc), it runs as it is.
void wait_passively_between_parallel_regions() {
    if (std::getenv("OMP_WAIT_POLICY")) return;
    std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(cmdline)), std::istreambuf_iterator<char>());
    std::vector<std::string> words;
    for (std::size_t start = 0; start < all.size();) {
        const std::size_t end = all.find('\0', start);
        words.push_back(all.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (words.empty() || setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    std::cout.flush();
    execv("/proc/self/exe", argv.data());
    unsetenv("OMP_WAIT_POLICY");  // not started again: as it was
}

int run_lsp() {
    wait_passively_between_parallel_regions();
    std::signal(SIGPIPE, SIG_IGN);  // an editor that goes away ends the loop through the input instead
    std::ios::sync_with_stdio(false);
    auto input = std::make_unique<StdinBuffer>();
    std::istream in(input.get());
    lsp::ServerOptions options;
    options.log = &std::cerr;
    lsp::Server server(in, std::cout, options);
    return server.run();
}

}  // namespace

std::function<int()> setup_lsp(CLI::App& app) {
    auto stdio = std::make_shared<bool>(false);  // accepted and ignored
    app.add_flag("--stdio", *stdio,
                 "talk over standard input and output (the default and only transport; editors pass it)");
    return [stdio] { return run_lsp(); };
}

}  // namespace sphdeck::cli
