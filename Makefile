# Quick start: `make serve` builds the wasm package and the book and serves both; `make test` runs every
# test. `make test` asserts behaviour only; budgets (ms per step, per frame, per drag) are
# checked by `make bench`, which is not part of `make test` or `.ci/run`.
PORT ?= 8080
export PATH := $(CURDIR)/node_modules/.bin:$(HOME)/.cargo/bin:$(PATH)

.PHONY: package docs serve build-wasm test lint lint-comments lint-rust lint-js test-native test-node test-browser test-e2e test-python wheel tools bench bench-native bench-wasm bench-browser bench-peer picture compare-table

tools:
	bash .ci/install

# The registry's sources, whose paths the module's panic messages name, are shortened to each
# crate's own folder (`serde_json-1.0.154/src/de.rs`): the module carries no path of the machine
# that built it, and shorter strings. Found once the crates are fetched, for the wasm target
# only, so that the native build and the build scripts keep their cache.
REMAP_REGISTRY = for d in "$${CARGO_HOME:-$$HOME/.cargo}"/registry/src/*/; do \
	  [ -d "$$d" ] && printf -- '--remap-path-prefix=%s= ' "$$d"; done

# Release build of the wasm package into www/pkg (wasm-opt from npm's binaryen, see .ci/install),
# with its TypeScript declarations (www/pkg/dvf.d.ts). The module is what the page downloads, so
# it is built for size: the crate at opt-level 2 for wasm (3 natively), its dependencies at "z"
# ("s" natively, Cargo.toml), none of which is in the step's loop; `make bench` checks the
# step's speed. With WebAssembly's 128-bit SIMD (every current browser: Chrome 91, Firefox 89,
# Safari 16.4, Node 16.4 on), which LLVM uses for pairs of f64 and for the step's selects
# without a branch, in fewer instructions: the same IEEE operations lane by lane, so the same
# bits as the native build.
build-wasm: tools
	cargo fetch --quiet
	CARGO_PROFILE_RELEASE_OPT_LEVEL=2 \
	  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-Ctarget-feature=+simd128 $$($(REMAP_REGISTRY))" \
	  wasm-pack build --release --target web --out-dir www/pkg \
	  -- --config 'profile.release.package."*".opt-level="z"'

# The npm package dvf-playground from the release build (package/build.mjs, its README the
# embedding guide): target/package/dvf-playground/ and its `npm pack` tarball beside it.
package: build-wasm
	node package/build.mjs

# The paper as a live book (docs/book/, mdBook) in target/book/: built from a copy in
# target/docs/ with the package's files in its src/dvf-playground/, so that the tree stays as
# it is.
docs: package
	rm -rf target/docs target/book
	mkdir -p target/docs
	cp -r docs/book docs/notes-on-the-paper.md target/docs/
	cp -r target/package/dvf-playground target/docs/book/src/dvf-playground
	mdbook build target/docs/book --dest-dir $(CURDIR)/target/book

# The playground and the book at /book/, which the page's header links: the book is built
# first (docs), so that the link works on a fresh clone.
serve: docs
	ln -sfn ../target/book www/book
	@echo "dvf playground: http://127.0.0.1:$(PORT)/"
	@echo "the book: http://127.0.0.1:$(PORT)/book/"
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory www

lint: lint-comments lint-rust lint-js

# Comments and docs say what the code does and why, in the present tense: no measurement deltas
# and no history (.ci/comments.mjs lists its rules).
lint-comments:
	node .ci/comments.mjs

# The crate's docs are checked with and without the `cli` feature (the library alone).
lint-rust:
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	cargo clippy --target wasm32-unknown-unknown --lib --tests -- -D warnings
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --no-default-features
	cargo clippy --lib --no-default-features --features python -- -D warnings

# The JavaScript of www/ and tests/e2e/: one linter and formatter, and the declarations
# type-checked against the code (and against the package's own, hence the build).
lint-js: build-wasm
	biome ci
	tsc --noEmit -p www/tsconfig.json

test-native:
	cargo test

# The math suite under wasm, in Node and in headless Chromium.
test-node: tools
	wasm-pack test --node

test-browser: tools
	WASM_BINDGEN_USE_BROWSER=1 wasm-pack test --headless --chrome

# The pages as users load them: the release package, served, driven in Chromium (screenshots and
# figures in test-results/).
test-e2e: package docs
	node tests/e2e/smoke.mjs
	node tests/e2e/forms.mjs
	node tests/e2e/embed.mjs
	node tests/e2e/figures.mjs
	node tests/e2e/recipes.mjs
	node tests/e2e/book.mjs
	node tests/e2e/reader.mjs
	node tests/e2e/crowd.mjs
	node tests/e2e/instrument.mjs
	node tests/e2e/planners.mjs

# The Python wheel (python/pyproject.toml, built by maturin; docs/book/src/python.md) in
# target/wheels/: the library with its Python module (the `python` feature, without the command
# line) and the playground's single-file build of `make package`, for the notebook widget. It
# builds in its own target folder, so that the native builds keep their caches.
PYENV := target/pyenv
wheel: package
	mkdir -p python/dvf/static
	cp target/package/dvf-playground/dvf-playground.inline.js python/dvf/static/
	rm -rf target/wheels
	cd python && ../$(PYENV)/bin/maturin build --release --out ../target/wheels --target-dir ../target/python

# The Python tests (python/tests/): the wheel installed into the virtual environment
# target/pyenv/ (.ci/install), checked against the command line (target/debug/dvf), on a Dask
# LocalCluster, in a JupyterLab driven by Chromium and in an exported notebook (screenshots in
# test-results/python/); and the wheel alone in a clean virtual environment.
test-python: wheel
	cargo build --bin dvf
	$(PYENV)/bin/pip install --quiet --force-reinstall --no-deps target/wheels/dvf-*.whl
	DVF_BIN=$(CURDIR)/target/debug/dvf DVF_WHEEL=$$(ls $(CURDIR)/target/wheels/dvf-*.whl) \
	  $(PYENV)/bin/python -m pytest -p no:cacheprovider python/tests

test: tools lint test-native test-node test-browser test-e2e test-python

# The book's comparison of planners (docs/book/src/command-line.md): the paper's examples and
# 50 scenes of each sweep family, with and without limits, for every planner, as Markdown on
# standard output (examples/compare.rs). Slow, and not part of `make test`.
compare-table:
	cargo run --release --example compare -- 25

# The README's picture (docs/playground.png), from the release build: a separate target, so that
# `make test` leaves the tree as it found it.
picture: build-wasm
	node tests/e2e/picture.mjs

# Benchmarks and their budgets, not part of `make test`: native and wasm (Node and Chromium) ms per
# step of the crowd at 1,000 and 10,000 robots (alternating, so that all see the same machine load), the drag of
# one robot in the 10,000-robot crowd, and the browser's frames. `cargo bench --bench crowd` runs
# the criterion benchmarks.
BENCH_STEPS ?= 200
bench: bench-native bench-wasm bench-browser bench-peer

# Each figure is a JSON line, printed and appended to test-results/bench-steps.jsonl. Native on one
# thread, as the wasm build runs (benches/peer.rs measures the threads).
bench-native: build-wasm
	cargo build --release
	mkdir -p test-results
	for n in 1000 10000 1000 10000 1000 10000; do \
		RAYON_NUM_THREADS=1 ./target/release/dvf bench --robots $$n --steps $(BENCH_STEPS) | tee -a test-results/bench-steps.jsonl; \
		node benches/wasm.mjs --robots $$n --steps $(BENCH_STEPS) | tee -a test-results/bench-steps.jsonl; \
		node benches/wasm-chromium.mjs --robots $$n --steps $(BENCH_STEPS) | grep '^{' | tee -a test-results/bench-steps.jsonl; \
	done

bench-wasm: build-wasm
	node benches/drag.mjs --robots 10000 --moves 200 --budget 5

bench-browser: build-wasm
	node tests/e2e/bench-browser.mjs

# DVF against ORCA (dodgy_2d) on the crowd of 1,000, alternating in one process: open space,
# the jam, the whole run (docs/book/src/performance.md); figures in test-results/bench-peer.jsonl.
bench-peer:
	cargo bench --bench peer
