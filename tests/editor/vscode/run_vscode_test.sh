#!/usr/bin/env bash
# The VS Code extension's test (tests/editor/vscode/README.md): editors/vscode in a real VS Code
# (code-server's server and web workbench, Debian's headless Chromium) against `sphdeck lsp`.
#   bash tests/editor/vscode/run_vscode_test.sh path/to/sphdeck
# Needs scripts/install-deps.sh --vscode-test (Chromium from Debian; code-server and the modules from
# the npm registry, by tests/editor/vscode/install.sh): without them the test fails, it is not skipped.
set -u
if [ $# -ne 1 ]; then
  echo "usage: $0 SPHDECK" >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
if [ ! -f "$here/node_modules/.sphdeck-vscode-test-ready" ]; then
  echo "vscode-test: FAILED: not installed; run scripts/install-deps.sh --vscode-test (or tests/editor/vscode/install.sh)" >&2
  exit 1
fi
# The extension as its sources are now (tsc, a few seconds).
if ! (cd "$root/editors/vscode" && npm run --silent compile); then
  echo "vscode-test: FAILED: the extension does not compile (npm run compile in editors/vscode)" >&2
  exit 1
fi
# timeout: a second bound behind the driver's own (150 s), should node itself hang.
timeout -k 5 180 node "$here/driver.mjs" "$1" "$root"
status=$?
[ $status -eq 124 ] && echo "vscode-test: FAILED: the driver did not end within 180 s" >&2
exit $status
