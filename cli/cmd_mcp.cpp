// sphdeck mcp: the Model Context Protocol server on stdin/stdout (mcp/server.hpp), for coding agents
// (Claude Code, Claude Desktop, VS Code). Problems with messages are logged on stderr, which clients
// keep in their server log.
#include <csignal>
#include <iostream>

#include "cli/commands.hpp"
#include "mcp/server.hpp"

namespace sphdeck::cli {

std::function<int()> setup_mcp(CLI::App&) {
    return [] {
        std::signal(SIGPIPE, SIG_IGN);  // a client that goes away ends the loop through the input instead
        std::ios::sync_with_stdio(false);
        mcp::ServerOptions options;
        options.log = &std::cerr;
        mcp::Server server(std::cin, std::cout, options);
        return server.run();
    };
}

}  // namespace sphdeck::cli
