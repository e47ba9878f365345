# Two commands matter: `make demo` and `make test`. Both set up everything they need.
JOBS ?= $(shell nproc)
RELEASE_DIR := build/release
TEST_DIR := build/test
FUZZ_DIR := build/fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= svg_reader path_reader animation_script config packing_reader

.PHONY: all deps release python demo test fuzz bench install install-inkscape clean
PREFIX ?= /usr/local

all: release

deps:
	@./scripts/install-deps.sh

# Built with clang: the same results bit for bit as g++ (the tests run on g++), and AnimationPak
# runs 16–22 % faster (docs/animationpak.md, fifteenth round). RELEASE_CXX=g++ for g++.
# A cache made by another compiler is set aside first: CMake would drop the options below with it.
RELEASE_CXX ?= clang++
release: deps
	@if [ -f $(RELEASE_DIR)/CMakeCache.txt ] && \
	  ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*$(RELEASE_CXX)$$' $(RELEASE_DIR)/CMakeCache.txt; then \
	  rm -rf $(RELEASE_DIR)/CMakeCache.txt $(RELEASE_DIR)/CMakeFiles; fi
	@cmake -S . -B $(RELEASE_DIR) -DCMAKE_CXX_COMPILER=$(RELEASE_CXX) -DCMAKE_BUILD_TYPE=Release -DPAK_BUILD_TESTS=OFF > /dev/null
	@cmake --build $(RELEASE_DIR) -j $(JOBS)

# The `pak` Python module, in the release build: build/release/python/pak.*.so
# (PYTHONPATH=build/release/python /usr/bin/python3 -c 'import pak').
python: release

# Packs the bundled example scene: out/demo.svg and out/demo.png.
demo: release
	@mkdir -p out
	./$(RELEASE_DIR)/pak pack --container examples/scene.svg --elements examples/elements \
	  -o out/demo.svg --png out/demo.png --report out/demo-report.json
	@echo "demo: wrote out/demo.svg, out/demo.png and out/demo-report.json"

# Assertions on, AddressSanitizer + UndefinedBehaviorSanitizer, then every test. python3
# cannot load a sanitized module, so the Python tests run on the release build's module.
test: deps python
	@cmake -S . -B $(TEST_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPAK_SANITIZE=ON \
	  -DPAK_ASSERTIONS=ON -DPAK_BUILD_BENCH=OFF -DPAK_PYTHON_TEST_BUILD=$(abspath $(RELEASE_DIR)) > /dev/null
	@cmake --build $(TEST_DIR) -j $(JOBS)
	@cd $(TEST_DIR) && ASAN_OPTIONS=detect_leaks=1 ctest --output-on-failure -j $(JOBS)

# The readers' libFuzzer targets (clang, ASan+UBSan, in $(FUZZ_DIR)), each run FUZZ_SECONDS
# (docs/reliability.md#fuzzing). Findings land in $(FUZZ_DIR)/findings/TARGET/ and fail the run.
fuzz:
	@./scripts/install-deps.sh --fuzz
	@cmake -S . -B $(FUZZ_DIR) -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPAK_FUZZ=ON \
	  -DPAK_SANITIZE=ON -DPAK_ASSERTIONS=ON -DPAK_BUILD_TESTS=OFF -DPAK_BUILD_APP=OFF -DPAK_BUILD_BENCH=OFF > /dev/null
	@cmake --build $(FUZZ_DIR) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	@./scripts/run-fuzzers.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# pak, its man pages and bash completion under PREFIX (bin/, share/man/man1/,
# share/bash-completion/completions/), and the Python module into python3's site-packages
# for PREFIX (/usr/local: its dist-packages; ~/.local: the user site; PYTHON_SITE=DIR: there):
# `make install PREFIX=$$HOME/.local` needs no root.
PYTHON_SITE ?= $(shell /usr/bin/python3 -c "import sys, sysconfig; p = sys.argv[1]; \
  print(sysconfig.get_path('platlib') if p == '/usr/local' else \
  sysconfig.get_path('platlib', 'posix_prefix', vars={'platbase': p, 'base': p}))" $(PREFIX) 2> /dev/null)
install: release
	@$(if $(PYTHON_SITE),cmake -S . -B $(RELEASE_DIR) -DPAK_PYTHON_INSTALL_DIR=$(PYTHON_SITE) > /dev/null)
	@cmake --install $(RELEASE_DIR) --prefix $(PREFIX)

# The Inkscape extension (Extensions > Pak > Pack and Flow) into the user's extensions folder,
# the one `inkscape --user-data-directory` names (else ~/.config/inkscape); override with
# `make install-inkscape INKSCAPE_EXTENSIONS=DIR`. The extension runs `pak` from the PATH.
INKSCAPE_EXTENSIONS ?= $(shell inkscape --user-data-directory 2> /dev/null | tail -n 1 | grep . || echo $$HOME/.config/inkscape)/extensions
install-inkscape:
	@mkdir -p "$(INKSCAPE_EXTENSIONS)/pak"
	@cp inkscape/*.inx inkscape/*.py "$(INKSCAPE_EXTENSIONS)/pak/"
	@echo "install-inkscape: installed in $(INKSCAPE_EXTENSIONS)/pak; restart Inkscape, then Extensions > Pak"
	@command -v pak > /dev/null || echo "install-inkscape: note: pak is not on the PATH; run make install" \
	  "(PREFIX=$$HOME/.local needs no root), or give the extension its path (PAK, or its Advanced tab)"

# Whole-run benchmark scenes; appends rows to bench/results.csv.
bench: release
	@./bench/run.sh $(RELEASE_DIR)

clean:
	rm -rf build out
