#!/usr/bin/env bash
# ctest mcp-client-sdk: runs client_test.mjs (the official MCP TypeScript SDK as a client of `sphdeck
# mcp`). Skipped (exit 77) only when node is not installed (scripts/install-deps.sh installs it, with
# the SDK: `npm ci` here, from the npm registry, the version package-lock.json pins).
#   run_client_test.sh SPHDECK_BINARY
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source_dir="$(cd "$here/../.." && pwd)"
if ! command -v node > /dev/null; then
  echo "SKIP: node is not installed (scripts/install-deps.sh installs nodejs and npm)"
  exit 77
fi
if [ ! -f "$here/node_modules/@modelcontextprotocol/sdk/package.json" ]; then
  if ! command -v npm > /dev/null; then
    echo "error: the MCP SDK is not installed in $here/node_modules and npm is missing (scripts/install-deps.sh)" >&2
    exit 1
  fi
  echo "installing the pinned MCP SDK (npm ci in tests/mcp-client)"
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi
exec node "$here/client_test.mjs" "$1" "$source_dir"
