#!/usr/bin/env bash
# Installs what the VS Code extension test (run_vscode_test.sh) runs in, from the npm registry only:
# code-server (a real VS Code: its server and web workbench, the version package-lock.json pins), the
# modules of its VS Code (lib/vscode, pinned by vscode-modules-lock.json), and the extension's own
# (editors/vscode/package-lock.json). Chromium comes from Debian (scripts/install-deps.sh --vscode-test).
#   bash tests/editor/vscode/install.sh      (again after a failure: it redoes what is not finished)
# Install scripts are not run: code-server's postinstall and some of VS Code's modules download from
# GitHub. The native modules the server loads at start are built here from source instead, against
# NodeSource's headers (/usr/include/node): argon2 (code-server's password hashing, loaded even with
# --auth none), @vscode/spdlog (the server's logs), native-watchdog (the extension host's). Not built,
# not needed by the test: node-pty (terminals), kerberos (proxy auth). @vscode/ripgrep's binary (file
# search, the extension's workspaceContains activation) is Debian's rg; @parcel/watcher ships its
# prebuilt linux-x64 binary as a package.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source_dir="$(cd "$here/../../.." && pwd)"
ready="$here/node_modules/.sphdeck-vscode-test-ready"
fail() {
  echo "vscode-test install: FAILED: $*" >&2
  exit 1
}
command -v node > /dev/null && command -v npm > /dev/null || fail "node and npm are needed (scripts/install-deps.sh)"
# code-server 4.99 runs on Node 20 only (its engines field), and the native modules build for the node
# that runs them.
node_major=$(node -p 'process.versions.node.split(".")[0]')
[ "$node_major" = 20 ] || fail "code-server 4.99 needs Node 20, this is $(node --version)"
command -v rg > /dev/null || fail "rg is missing (Debian package ripgrep: scripts/install-deps.sh --vscode-test)"
[ -f /usr/include/node/node_api.h ] || fail "Node's headers are missing (/usr/include/node: NodeSource's nodejs package has them)"
# Done once for these locks: the marker holds their hash.
locks_hash() {
  cat "$here/package-lock.json" "$here/vscode-modules-lock.json" "$source_dir/editors/vscode/package-lock.json" | sha256sum
}
if [ -f "$ready" ] && [ "$(cat "$ready")" = "$(locks_hash)" ]; then
  exit 0
fi
rm -f "$ready"
# node-gyp takes the headers from there rather than downloading them from nodejs.org.
export npm_config_nodedir=/usr JOBS=2
npm_quiet=(--no-audit --no-fund --loglevel=error)

echo "vscode-test install: code-server (npm ci in tests/editor/vscode)"
(cd "$here" && npm ci --ignore-scripts "${npm_quiet[@]}")
code_server="$here/node_modules/code-server"
[ -f "$code_server/lib/vscode/npm-shrinkwrap.json" ] || fail "code-server's VS Code is missing: $code_server/lib/vscode"
echo "vscode-test install: argon2 built from source"
(cd "$here" && npm_config_build_from_source=true npm rebuild argon2 "${npm_quiet[@]}")

# The shrinkwrap code-server ships misses a module its package.json asks for (tslib: npm ci refuses it,
# npm install as in code-server's postinstall takes its newest); vscode-modules-lock.json is that
# shrinkwrap completed by npm install on 2026-11-30, so npm ci installs the same modules every time.
echo "vscode-test install: VS Code's modules (npm ci in code-server's lib/vscode, by vscode-modules-lock.json)"
cp "$here/vscode-modules-lock.json" "$code_server/lib/vscode/npm-shrinkwrap.json"
(cd "$code_server/lib/vscode" && npm ci --ignore-scripts --omit=dev "${npm_quiet[@]}")
echo "vscode-test install: @vscode/spdlog and native-watchdog built from source"
(cd "$code_server/lib/vscode" && npm rebuild @vscode/spdlog native-watchdog "${npm_quiet[@]}")
# What code-server's postinstall does besides: VS Code looks for its modules in node_modules.asar.
ln -sfn node_modules "$code_server/lib/vscode/node_modules.asar"
# In place of the binary @vscode/ripgrep's install script downloads from GitHub.
mkdir -p "$code_server/lib/vscode/node_modules/@vscode/ripgrep/bin"
ln -sfn "$(command -v rg)" "$code_server/lib/vscode/node_modules/@vscode/ripgrep/bin/rg"

echo "vscode-test install: the extension's modules (npm ci in editors/vscode)"
(cd "$source_dir/editors/vscode" && npm ci "${npm_quiet[@]}")

locks_hash > "$ready"
echo "vscode-test install: done"
