#!/usr/bin/env bash
# Installs the Debian 12 packages sphdeck builds and tests with, only those missing
# (neovim: the editor test tests/editor/, ctest entry editor-neovim; nodejs and npm: the MCP client
# test tests/mcp-client/, ctest entry mcp-client-sdk, whose pinned SDK `npm ci` then installs from the
# npm registry).
# Runs as root (CI, fresh machines) or through sudo when available.
#   --fuzz  also Clang 14, its sanitizer and libFuzzer runtimes and its OpenMP library, for the
#           Clang build and the fuzz targets (fuzz/README.md); the default install stays GCC only.
#   --vscode-test  also what the VS Code extension's test runs in (tests/editor/vscode/README.md): Debian's
#           Chromium and ripgrep, then code-server and the modules from the npm registry
#           (tests/editor/vscode/install.sh, about 300 MB in all); .ci/run uses it, make test does not.
set -euo pipefail
#   --build only what building sphdeck needs (make demo, make build-cli, the GitHub Action).
build_packages=(
  build-essential cmake
  ninja-build    # the build tool make demo and make test use when it is there (Makefile)
  tao-pegtl-dev libeigen3-dev libfmt-dev libcli11-dev doctest-dev nlohmann-json3-dev
  libtomlplusplus-dev
  python3        # forms the unity batches at configure time (cmake/speed_up.cmake)
)
test_packages=(
  python3 python3-jsonschema python3-yaml
  python3-vtk9   # VTK's own reader checks the .vtp/.pvd files we write (tests/test_io_writers.cpp)
  neovim
  man-db         # `man sphdeck-check` on the installed pages (tests/ci/test_install.py)
  # The Python module (python/, ctest python-module): pybind11's headers, Python's, pytest.
  pybind11-dev python3-pybind11 python3-dev python3-pytest
  clang-format-14  # the sources keep .clang-format's layout (ctest sources-formatted)
)
# node and npm from Debian, unless another install already provides the commands (NodeSource's nodejs
# carries npm and conflicts with Debian's npm package).
command -v node > /dev/null || test_packages+=(nodejs)
command -v npm > /dev/null || test_packages+=(npm)
packages=("${build_packages[@]}" "${test_packages[@]}")
with_tests=1
with_vscode_test=0
for arg in "$@"; do
  case $arg in
    --fuzz) packages+=(clang-14 libclang-rt-14-dev libomp-14-dev) ;;
    --build) packages=("${build_packages[@]}"); with_tests=0 ;;
    --vscode-test) packages+=(chromium ripgrep); with_vscode_test=1 ;;
    *) echo "usage: scripts/install-deps.sh [--build] [--fuzz] [--vscode-test]" >&2; exit 2 ;;
  esac
done
# One dpkg-query for all of them (it runs before every `make demo` and `make test`). It exits 1 when a
# package was never installed (a fresh machine), and grep 1 when none is: neither is an error here.
installed=" $( (dpkg-query -W -f='${Package}:${Status} ' "${packages[@]}" 2>/dev/null || true) | (grep -o '[^ ]*:install ok installed' || true) | sed 's/:install ok installed//' | tr '\n' ' ') "
missing=()
for p in "${packages[@]}"; do
  [[ "$installed" == *" $p "* ]] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The MCP client test's SDK, at the version package-lock.json pins (tests/mcp-client/README.md).
client_dir="$(cd "$(dirname "$0")/.." && pwd)/tests/mcp-client"
if [ $with_tests -eq 1 ] && [ ! -f "$client_dir/node_modules/@modelcontextprotocol/sdk/package.json" ]; then
  (cd "$client_dir" && npm ci --no-audit --no-fund --loglevel=error)
fi
if [ $with_vscode_test -eq 1 ]; then
  bash "$(cd "$(dirname "$0")/.." && pwd)/tests/editor/vscode/install.sh"
fi
