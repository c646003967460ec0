#!/usr/bin/env bash
# ctest entry editor-neovim: drives Debian's Neovim headless against `sphdeck lsp`
# (tests/editor/neovim_lsp_test.lua).   bash tests/editor/run_neovim_test.sh path/to/sphdeck
# nvim is installed by scripts/install-deps.sh: a missing nvim fails the test, it is not skipped.
set -u
if [ $# -ne 1 ]; then
  echo "usage: $0 SPHDECK" >&2
  exit 2
fi
if ! command -v nvim > /dev/null; then
  echo "editor-neovim: FAILED: nvim not found; install it with scripts/install-deps.sh (Debian package neovim)" >&2
  exit 1
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
sphdeck=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
# A private home: no user configuration, state or log of the machine's user is read or written.
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
# timeout: a second bound behind the script's own (20 s), should nvim itself hang.
HOME=$home XDG_CONFIG_HOME=$home/config XDG_DATA_HOME=$home/data XDG_STATE_HOME=$home/state \
XDG_CACHE_HOME=$home/cache SPHDECK=$sphdeck \
  timeout -k 5 40 nvim --headless --clean -u "$root/tests/editor/neovim_lsp_test.lua" < /dev/null
status=$?
if [ $status -ne 0 ] && [ -s "$home/state/nvim/lsp.log" ]; then
  echo "--- Neovim's LSP log:" >&2
  tail -n 40 "$home/state/nvim/lsp.log" >&2
elif [ $status -ne 0 ] && [ -s "$home/cache/nvim/lsp.log" ]; then
  echo "--- Neovim's LSP log:" >&2
  tail -n 40 "$home/cache/nvim/lsp.log" >&2
fi
[ $status -eq 124 ] && echo "editor-neovim: FAILED: nvim did not end within 40 s" >&2
exit $status
