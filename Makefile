# SPDX-License-Identifier: MIT
# Two entry points for newcomers and CI:
#   make run   - install missing Debian packages, build (Release), run the flagship example
#   make test  - same set-up, then the whole test suite through ctest
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
EXAMPLE ?= confined_column
# unity build: each target compiled as a few large translation units, half the compile time of
# a fresh build (docs/development.md); UNITY=OFF for quicker rebuilds after editing one file
UNITY ?= ON

.PHONY: all deps configure build build-app run test clean format

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=$(UNITY) >/dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# only what an example needs: the trifem command (not the tests and benchmarks)
build-app: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target trifem

run: build-app
	@bash examples/run_example.sh $(EXAMPLE) $(BUILD_DIR)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

format:
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	@rm -rf $(BUILD_DIR) results
