# grainlab: the two commands a user needs are `make demo` and `make test`.
BUILD ?= build
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all setup build test demo bench clean fuzz test-sanitize

all: build

setup:
	@bash scripts/setup.sh

$(BUILD)/CMakeCache.txt: | setup
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: setup $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && OMP_WAIT_POLICY=PASSIVE ctest --output-on-failure -j $(JOBS) --timeout 600

demo: build
	$(BUILD)/grainlab run --default

bench: build
	$(BUILD)/bench_scenes
	$(BUILD)/bench_pair_paths
	$(BUILD)/bench_contact_energy
	$(BUILD)/bench_sphere_lab
	$(BUILD)/bench_paper_size
	$(BUILD)/bench_shear_presets

clean:
	rm -rf $(BUILD)

# Fuzzing (not part of `make test`, whose corpus tests replay the inputs):
# the harnesses of tests/fuzz built with clang and libFuzzer in their own
# folder, each run for FUZZ_SECONDS or FUZZ_RUNS executions, whichever comes
# first (scripts/run_fuzzers.sh; findings in $(FUZZ_BUILD)/fuzz-findings).
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
FUZZ_RUNS ?= 1000000
CLANG_FLAGS = -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14
fuzz: setup
	cmake -S . -B $(FUZZ_BUILD) $(CLANG_FLAGS) -DGRAINLAB_FUZZ=ON
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_harnesses
	scripts/run_fuzzers.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_RUNS)

# The fast tests under AddressSanitizer and UndefinedBehaviorSanitizer, in
# their own folder (not part of `make test`): every test but the long runs
# (SANITIZE_SKIP: the preset runs; the golden regression and the embedded
# index densities' grain fingerprints (the default inputs', the bench
# beads'), whose bits belong to the release build's compiler and flags).
SANITIZE_SKIP ?= PresetRun|Golden|EmbeddedIndices.BelongTo
SANITIZE_BUILD ?= build-sanitize
test-sanitize: setup
	cmake -S . -B $(SANITIZE_BUILD) $(CLANG_FLAGS) -DGRAINLAB_SANITIZE=ON
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && OMP_WAIT_POLICY=PASSIVE ASAN_OPTIONS=detect_leaks=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS) --timeout 1200 -E '$(SANITIZE_SKIP)'
