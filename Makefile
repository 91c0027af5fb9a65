# Columba: `make demo` renders the default scene, `make test` runs the test suite.
# Both install missing Debian packages and build Release first.
BUILD ?= build
JOBS ?= $(shell nproc)
COLUMBA := $(BUILD)/columba

.PHONY: deps configure build demo test bench figures clean

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@mkdir -p out
	$(COLUMBA) render -o out/default.exr

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	@./scripts/bench.sh $(BUILD)

figures: build
	@./scripts/figures.sh $(BUILD)

clean:
	rm -rf $(BUILD) out
