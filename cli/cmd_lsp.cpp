// sphdeck lsp: the language server on stdin/stdout (lsp/server.hpp). `--stdio` is accepted because
// editors pass it; there is no other transport. Problems with messages are logged on stderr, which
// editors show in their server log.
#include <cerrno>
#include <csignal>
#include <iostream>
#include <memory>
#include <poll.h>
#include <streambuf>
#include <unistd.h>

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

int run_lsp() {
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
