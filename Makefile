# Front door: `make demo` and `make test` are the whole set-up on a fresh Debian 12 machine.
BUILD ?= build
BUILD_ASAN ?= build-asan
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
PREFIX ?= /usr/local

.PHONY: all deps deps-build build build-cli python install-python demo test test-asan corpus mistakes bench verify install package clean

all: build

deps:
	bash scripts/install-deps.sh

deps-build:
	bash scripts/install-deps.sh --build

# Ninja when it is installed (scripts/install-deps.sh --build installs it): it starts the next compile the
# moment one ends, with none of the recursive make calls of CMake's Makefiles. Asked when the recipe runs,
# after deps-build, not when make reads this file.
$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $$(command -v ninja > /dev/null && echo -G Ninja) $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# Only the command-line program: what the demo runs (the test binary and benchmarks take most of a build).
build-cli: deps-build $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target sphdeck

# The Python module sphdeck (python/, README "From Python") into $(BUILD)/python/: import it with
# PYTHONPATH=$(BUILD)/python. The option is set here, since a tree configured before pybind11-dev was
# installed has it off.
python: deps $(BUILD)/CMakeCache.txt
	cmake -S . -B $(BUILD) -DSPHDECK_PYTHON=ON
	cmake --build $(BUILD) -j $(JOBS) --target sphdeck_python

# The module into Python's site-packages (SPHDECK_PYTHON_SITE, /usr/local/lib/python3.11/dist-packages on
# Debian 12; DESTDIR honoured): a copy of one file, no network.
install-python: python
	cmake --install $(BUILD) --component python

# check on a deck with typical mistakes (its findings are the point), then the smoothing-length preview.
demo: build-cli
	bash decks/demo/run_demo.sh $(BUILD)/sphdeck

# What ctest runs: the program, the test binary, the man pages (ctest install-tree installs them) and the
# Python module when it is configured; not the benchmarks (make bench builds them; CI builds the whole tree).
TEST_TARGETS = sphdeck sphdeck_tests sphdeck_man \
  $$(grep -q '^SPHDECK_PYTHON:BOOL=ON' $(BUILD)/CMakeCache.txt && echo sphdeck_python)

test: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target $(TEST_TARGETS)
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The corpus check: sphdeck on the real public decks of ../shared/corpus (or $$SPHDECK_CORPUS), every
# error and warning compared with the argued baseline tests/corpus/baseline.tsv.
corpus: build
	python3 tests/corpus/run_corpus.py --sphdeck $(BUILD)/sphdeck

# The seeded-mistakes test: typical mistakes planted into the shipped and corpus decks, the rate per kind
# (tests/mistakes/README.md); also a ctest entry.
mistakes: build
	python3 tests/mistakes/run_mistakes.py --sphdeck $(BUILD)/sphdeck --verbose

# The test suite again under AddressSanitizer and UndefinedBehaviorSanitizer (CI runs it too).
test-asan: deps
	cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=Debug -DSPHDECK_SANITIZE=ON -DSPHDECK_WERROR=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_ASAN) -j $(JOBS) --target sphdeck sphdeck_tests
	cd $(BUILD_ASAN) && ctest --output-on-failure

bench: build
	bash bench/run_reader_bench.sh $(BUILD)
	bash bench/bench_many_sets.sh $(BUILD)
	python3 bench/bench_lsp.py $(BUILD)
	$(BUILD)/bench_refsolver

# The full verification suite (docs/verification.md): reports in verification-out/.
verify: build
	./$(BUILD)/sphdeck verify all --out verification-out

# The binary, man pages, shell completions, rule pages, editor set-ups and decks under $(PREFIX) (DESTDIR
# honoured): builds only what it installs.
install: build-cli
	cmake --build $(BUILD) -j $(JOBS) --target sphdeck_man
	cmake --install $(BUILD) --prefix $(PREFIX)

# The Debian package build/sphdeck_VERSION_ARCH.deb (CPack): what make install puts under /usr.
package: build-cli
	cmake --build $(BUILD) -j $(JOBS) --target sphdeck_man
	cd $(BUILD) && cpack -G DEB

clean:
	rm -rf $(BUILD) $(BUILD_ASAN)
