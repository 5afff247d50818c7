# grainlab: the two commands a user needs are `make demo` and `make test`.
BUILD ?= build
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all setup build test demo bench clean

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
