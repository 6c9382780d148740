# The two commands of the README: `make demo` and `make test`. Both install missing
# Debian packages, configure and build (Release) first.
BUILD      ?= build
ASAN_BUILD ?= build-asan
TSAN_BUILD ?= build-tsan
LINT_BUILD ?= build-lint
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
# Unity builds (cmake/unity.cmake: up to 8 sources of a target in one unit, a pass folder's
# sources in one of their own): the headers (GoogleTest, Vulkan, GLM, JSON) are parsed once
# per batch instead of once per file, which is most of a cold build's time on the 2-core CI.
# `make lint` still compiles each source alone (clang-tidy), so a file that forgets an include
# is caught. UNITY=OFF builds file by file.
UNITY      ?= ON
DEMO_ARGS  ?= --size 1280x720 --out out/atrium.png

.PHONY: all deps configure build demo test test-asan test-tsan soak fuzz bench lint format-check reference docs-tables clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DANTUMBRA_UNITY_BUILD=$(UNITY) $(CMAKE_ARGS)

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

# Builds the program alone (no test suites, no benchmarks): the first image sooner.
demo: configure
	@cmake --build $(BUILD) -j$(JOBS) --target antumbra
	@mkdir -p out
	$(BUILD)/app/antumbra render $(DEMO_ARGS)

# Release tests (CPU-only suites and lavapipe GPU suites with validation), then the
# Vulkan-free suites (label asan: framegraph, scene, layering, watch, editor, the fuzz targets'
# replay) under ASan + UBSan.
test: build
	@ctest --test-dir $(BUILD) --output-on-failure --no-tests=error -j$(JOBS)
	@$(MAKE) --no-print-directory test-asan

# -O1 -g1 (line tables: sanitizer reports keep file:line) instead of RelWithDebInfo's -O2 -g:
# measured at a third of the compile time per file (a 2-core CI's cold run is bounded).
test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTUMBRA_SANITIZE=ON \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DANTUMBRA_BUILD_BENCHMARKS=OFF -DANTUMBRA_UNITY_BUILD=$(UNITY) $(CMAKE_ARGS)
	@cmake --build $(ASAN_BUILD) -j$(JOBS) --target antumbra_framegraph_tests antumbra_scene_tests antumbra_layering_tests antumbra_watch_tests \
	  antumbra_editor_model_tests antumbra_fuzz_replay_tests
	@ctest --test-dir $(ASAN_BUILD) --output-on-failure --no-tests=error -j$(JOBS) -L asan

# The watch and editor-model suites (reload, recovery, the editor's documents) under
# ThreadSanitizer. Today nothing in the project starts a thread (the watcher polls on its
# caller's), so this guards the first thread added there. Vulkan-free, so no
# uninstrumented driver thread reports false races. Not in CI: the 2-core cold run has no
# room for a third build.
test-tsan: deps
	@cmake -S . -B $(TSAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTUMBRA_TSAN=ON \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DANTUMBRA_BUILD_BENCHMARKS=OFF -DANTUMBRA_UNITY_BUILD=$(UNITY) $(CMAKE_ARGS)
	@cmake --build $(TSAN_BUILD) -j$(JOBS) --target antumbra_watch_tests antumbra_editor_model_tests
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" ctest --test-dir $(TSAN_BUILD) \
	  --output-on-failure --no-tests=error -j$(JOBS) -L asan

# The editor's soak (docs/robustness.md, "Soak"): the program under ASan + UBSan + LSan, a
# generated script of SOAK_EDITS edits and SOAK_RELOADS shader and graph reloads; no step
# may fail, no sanitizer report, and the device memory in use ends within 1 % of after the
# first reload. Without the validation layer: it leaks at each vkDestroyInstance and is
# unloaded before LeakSanitizer could name it. lavapipe is preloaded (SOAK_PRELOAD, after the
# ASan runtime, into the program alone) so that its global state stays reachable until exit
# instead of being unloaded with the device. CI runs the 300-edit version in Release with
# validation (cli.edit_soak): an ASan build of the Vulkan program does not fit its cold run.
SOAK_EDITS   ?= 10000
SOAK_RELOADS ?= 500
SOAK_PRELOAD ?= $(shell $(CXX) -print-file-name=libasan.so) $(firstword $(wildcard /usr/lib/*/libvulkan_lvp.so))
soak: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANTUMBRA_SANITIZE=ON \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DANTUMBRA_BUILD_BENCHMARKS=OFF -DANTUMBRA_UNITY_BUILD=$(UNITY) $(CMAKE_ARGS)
	@cmake --build $(ASAN_BUILD) -j$(JOBS) --target antumbra
	@SOAK_PRELOAD="$(SOAK_PRELOAD)" ASAN_OPTIONS="detect_leaks=1:halt_on_error=1" UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1" \
	  tests/cli/soak_test.sh $(ASAN_BUILD)/app/antumbra $(CURDIR) $(SOAK_EDITS) $(SOAK_RELOADS) no-validation

# libFuzzer over every parser of outside data (clang; docs/robustness.md, "Fuzzing"): each
# target in FUZZ_TARGETS runs FUZZ_SECONDS from its kept corpus (fuzz/corpus/<name>) and the
# inputs it found before (FUZZ_BUILD/corpus/<name>), with its dictionary; a crash stops the
# run and leaves its input in FUZZ_BUILD/crashes/<name>/ (keep it in fuzz/regressions/<name>/).
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= graph scene gltf edit-script pfm png
fuzz: deps
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
	  -DCMAKE_CXX_COMPILER=clang++ -DANTUMBRA_FUZZ=ON -DANTUMBRA_BUILD_TESTS=OFF \
	  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  -DANTUMBRA_BUILD_BENCHMARKS=OFF -DANTUMBRA_UNITY_BUILD=$(UNITY) $(CMAKE_ARGS)
	@cmake --build $(FUZZ_BUILD) -j$(JOBS) --target $(addprefix antumbra_fuzz_,$(FUZZ_TARGETS))
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t $(FUZZ_BUILD)/crashes/$$t || exit 1; \
	  echo "fuzz: $$t for $(FUZZ_SECONDS) s"; \
	  $(FUZZ_BUILD)/fuzz/antumbra_fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	    -rss_limit_mb=3072 -malloc_limit_mb=2048 -print_final_stats=1 -dict=fuzz/dict/$$t.dict \
	    -artifact_prefix=$(FUZZ_BUILD)/crashes/$$t/ $(FUZZ_BUILD)/corpus/$$t fuzz/corpus/$$t \
	    2> $(FUZZ_BUILD)/fuzz-$$t.log || { tail -60 $(FUZZ_BUILD)/fuzz-$$t.log; exit 1; }; \
	  grep -E "^stat::(number_of_executed_units|new_units_added|peak_rss_mb)|cov: " $(FUZZ_BUILD)/fuzz-$$t.log | tail -4; \
	done

# clang-format (no diff; C++ and GLSL), GLSL function lengths and clang-tidy (.clang-tidy,
# every warning an error) over the project's own sources; clean results are cached outside
# the clone (scripts/lint.py). clang-tidy reads its own configuration (LINT_BUILD: configured,
# never built), file by file: a unity build's compile_commands.json names its batches.
lint: deps
	@mkdir -p $(LINT_BUILD) && cmake -S . -B $(LINT_BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) \
	  -DANTUMBRA_UNITY_BUILD=OFF > $(LINT_BUILD)/configure.log 2>&1 || { tail -30 $(LINT_BUILD)/configure.log; exit 1; }
	@python3 scripts/lint.py --build $(LINT_BUILD) --jobs $(JOBS)

# The clang-format half of lint alone, GLSL function lengths included (seconds; no configure
# needed).
format-check:
	@python3 scripts/lint.py --format-only

# Copies the schemas and references the build generated from the registered passes and the
# scene format's table into data/schema/ and docs/ (tests fail while the committed copies
# differ).
reference: configure
	@cmake --build $(BUILD) -j$(JOBS) --target antumbra_update_reference

# Regenerates the measured tables of README.md and docs/*.md from the results files under
# docs/results/ (docs/measuring.md); a CPU test fails while a committed table differs.
docs-tables: configure
	@cmake --build $(BUILD) -j$(JOBS) --target antumbra
	$(BUILD)/app/antumbra docs-tables --root .

bench: build
	$(BUILD)/bench/antumbra_bench_graph
	$(BUILD)/bench/antumbra_bench_layering
	$(BUILD)/bench/antumbra_bench_atlas_planner

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD) out
