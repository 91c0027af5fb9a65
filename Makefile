# Columba: `make demo` renders the default scene, `make test` runs the test suite,
# `make install [PREFIX=/usr/local]` installs the `columba` binary with its scenes and documentation.
# All of them install missing Debian packages and build Release first.
BUILD ?= build
JOBS ?= $(shell nproc)
PREFIX ?= /usr/local
COLUMBA := $(BUILD)/columba
FUZZ_BUILD ?= build-fuzz
SANITIZE_BUILD ?= build-asan
FUZZ_SECONDS ?= 300
FUZZ_TARGETS ?= scene ply_mesh feather_ply obj_mesh serialized_mesh sdf_grid exr_envmap hdr_envmap bitmap merge_piece manifest spectra_csv layer_text observer_table observer_definition medium_grid number_list

.PHONY: deps configure build demo test slurm-test install bench figures clean fuzz fuzz-build sanitize format docs

deps:
	@./scripts/install-deps.sh

# CMAKE_FLAGS: further CMake options, e.g. -DCOLUMBA_WARNINGS_AS_ERRORS=ON (as CI builds).
configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@mkdir -p out
	$(COLUMBA) render -o out/default.exr

# After the run, each skipped test is listed with the reason it gave (from CTest's log).
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS); status=$$?; \
	awk '/: Skipped$$/ { getline reason; next } \
	     /^\[  SKIPPED \] [^ ]+ \(/ && reason != "" { if (!n++) print "Skipped tests:"; print "  " $$4 ": " reason; reason = "" }' \
	    Testing/Temporary/LastTest.log; exit $$status

# `make slurm-test`: renders a sweep in pieces through Slurm and checks the merged frames against
# local renders (scripts/slurm-render-test.sh), on a one-node cluster started for it and stopped
# afterwards (scripts/slurm-test-cluster.sh: root on Debian 12). Where this machine cannot run the
# cluster's daemons, the test is reported as skipped, with the reason.
slurm-test: build
	@status=0; ./scripts/slurm-test-cluster.sh ./scripts/slurm-render-test.sh $(COLUMBA) || status=$$?; \
	if [ $$status -eq 77 ]; then echo "SKIPPED: the Slurm cluster test: this machine cannot run a Slurm cluster (why: above)"; \
	else exit $$status; fi

# Installs as the current user where PREFIX is writable, through sudo otherwise (the build itself
# stays the user's).
install: build
	@mkdir -p "$(PREFIX)" 2>/dev/null || true
	@if [ -w "$(PREFIX)" ]; then cmake --install $(BUILD) --prefix "$(PREFIX)"; \
	else sudo cmake --install $(BUILD) --prefix "$(PREFIX)"; fi

# `make format`: lays out every C++ file as .clang-format says (the `formatting` test checks it).
format:
	@./scripts/check-format.sh . --fix

# `make docs`: the HTML site of docs/ (mkdocs.yml) in $(BUILD)/site, after checking that the plug-in
# reference in docs/reference/ is what the sources' documentation blocks give; --strict fails on
# broken links.
docs: deps
	@/usr/bin/python3 scripts/plugin-docs.py --check src docs/reference
	@mkdocs build --strict --quiet --site-dir $(BUILD)/site
	@echo "Documentation: $(BUILD)/site/index.html"

bench: build
	@./scripts/bench.sh $(BUILD)

figures: build
	@./scripts/figures.sh $(BUILD)

# `make fuzz`: libFuzzer targets (clang, ASan + UBSan) built in $(FUZZ_BUILD), then each of
# FUZZ_TARGETS run for FUZZ_SECONDS (fuzz/run.sh says where corpora, findings and logs go).
fuzz: fuzz-build
	@./fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

fuzz-build: deps
	@./scripts/install-fuzz-deps.sh
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_CXX_COMPILER=clang++ -DCOLUMBA_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -fno-math-errno" > /dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))

# `make sanitize`: the whole unit suite (GoogleTest) once under ASan + UBSan, built in $(SANITIZE_BUILD);
# the Python tests are left out (the interpreter is not instrumented).
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCOLUMBA_SANITIZE=address,undefined -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_FLAGS) \
	    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG -fno-math-errno" > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target columba_tests
	@cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1 \
	    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS) -E '^python_tests$$'

clean:
	rm -rf $(BUILD) out
