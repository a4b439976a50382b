# Quick start: `make serve` builds the wasm package and serves the page; `make test` runs every test.
PORT ?= 8080
export PATH := $(CURDIR)/node_modules/.bin:$(HOME)/.cargo/bin:$(PATH)

.PHONY: serve build-wasm test lint test-native test-browser test-e2e tools bench

tools:
	bash .ci/install

# Release build of the wasm package into www/pkg (wasm-opt from npm's binaryen, see .ci/install).
# The crate at opt-level 2 for wasm (3 natively): 6 KB smaller, as fast in Node and Chromium
# (README, Performance), and within the 250 KB budget.
build-wasm: tools
	CARGO_PROFILE_RELEASE_OPT_LEVEL=2 wasm-pack build --release --target web --out-dir www/pkg --no-typescript

serve: build-wasm
	@echo "dvf playground: http://127.0.0.1:$(PORT)/"
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory www

lint:
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps

test-native:
	cargo test

test-browser: tools
	wasm-pack test --headless --chrome

# The pages as users load them: the release package, served, driven in Chromium (screenshots in
# test-results/, the README picture in docs/playground.png).
test-e2e: build-wasm
	node tests/e2e/smoke.mjs
	node tests/e2e/embed.mjs
	node tests/e2e/frames.mjs

test: tools lint test-native test-browser test-e2e

# Benchmarks, not part of `make test`: ms per step of the crowd natively and in wasm (Node), at
# 1,000 and 10,000 robots, alternating so that both see the same machine load (README,
# Performance). `cargo bench --bench crowd` runs the criterion benchmarks.
BENCH_STEPS ?= 200
bench: build-wasm
	cargo build --release
	for n in 1000 10000 1000 10000 1000 10000; do \
		./target/release/dvf bench --robots $$n --steps $(BENCH_STEPS); \
		node www/bench.mjs --robots $$n --steps $(BENCH_STEPS); \
	done
