# The two commands of the README: `make demo` and `make test`. Both install missing
# Debian packages, configure and build (Release) first.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
DEMO_ARGS  ?= --size 1280x720 --out out/atrium.png

.PHONY: all deps configure build demo test test-asan bench clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

demo: build
	@mkdir -p out
	$(BUILD)/app/antumbra render $(DEMO_ARGS)

# Release tests (CPU-only suites and lavapipe GPU suites with validation), then the
# CPU-only suites again under AddressSanitizer + UBSan.
test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)
	@$(MAKE) --no-print-directory test-asan

test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTUMBRA_SANITIZE=ON \
	  -DANTUMBRA_BUILD_BENCHMARKS=OFF $(CMAKE_ARGS) > /dev/null
	@cmake --build $(ASAN_BUILD) -j$(JOBS) --target antumbra_framegraph_tests antumbra_scene_tests
	@ctest --test-dir $(ASAN_BUILD) --output-on-failure -j$(JOBS) -L asan

bench: build
	$(BUILD)/bench/antumbra_bench_graph

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
