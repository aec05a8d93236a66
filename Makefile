# The two commands of the README, and a few more for developers.
BUILD_DIR ?= build
ASAN_DIR  ?= build-asan
JOBS      ?= $(shell nproc)

.PHONY: all deps build test demo asan bench install clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD_DIR)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD_DIR)/CMakeCache.txt
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The program into PREFIX/bin and the Python module into the system's python3
# (/usr/local/lib/python3.X/dist-packages with the default prefix).
install: build
	cmake --install $(BUILD_DIR)

demo: build
	@bash scripts/demo.sh $(BUILD_DIR)

# The whole suite under AddressSanitizer and UndefinedBehaviorSanitizer.
asan: deps
	cmake -S . -B $(ASAN_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHYDRODDA_SANITIZE=ON \
	      -DHYDRODDA_BUILD_BENCHMARKS=OFF -DHYDRODDA_PYTHON=OFF
	cmake --build $(ASAN_DIR) -j $(JOBS)
	cd $(ASAN_DIR) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	    ctest --output-on-failure -j $(JOBS)

bench: build
	@ls $(BUILD_DIR)/bin/bench_* 2>/dev/null || echo "no benchmarks built"

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR)
