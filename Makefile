# Columba: `make demo` renders the default scene, `make test` runs the test suite,
# `make install [PREFIX=/usr/local]` installs the `columba` binary with its scenes and documentation.
# All of them install missing Debian packages and build Release first.
BUILD ?= build
JOBS ?= $(shell nproc)
PREFIX ?= /usr/local
COLUMBA := $(BUILD)/columba

.PHONY: deps configure build demo test install bench figures clean

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null

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

# Installs as the current user where PREFIX is writable, through sudo otherwise (the build itself
# stays the user's).
install: build
	@mkdir -p "$(PREFIX)" 2>/dev/null || true
	@if [ -w "$(PREFIX)" ]; then cmake --install $(BUILD) --prefix "$(PREFIX)"; \
	else sudo cmake --install $(BUILD) --prefix "$(PREFIX)"; fi

bench: build
	@./scripts/bench.sh $(BUILD)

figures: build
	@./scripts/figures.sh $(BUILD)

clean:
	rm -rf $(BUILD) out
