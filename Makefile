# rime — every check CI runs is `make test`; it installs what it needs on a fresh machine and prints
# each step's duration (target/bench/make-test-steps.tsv). The smaller targets run one part of it.
SHELL := /bin/bash
.PHONY: test setup check fmt clippy doc nostd unit www serve bench

test:
	@scripts/test-all.sh

# What a fresh machine needs: Rust targets and components, Debian packages (as root), the e2e
# test's npm packages, wasm-bindgen-cli, and the Python peers' virtual environment.
setup:
	@scripts/setup.sh
	@scripts/setup-apt.sh
	@scripts/setup-npm.sh
	@scripts/setup-wasm-bindgen.sh
	@if [ -x scripts/setup-python.sh ]; then scripts/setup-python.sh; fi

# The static checks: formatting, lints, docs and the no_std builds (no test runs).
check: clippy doc nostd
	cargo fmt --all -- --check

fmt:
	cargo fmt --all

clippy:
	cargo clippy --locked --workspace --all-targets -- -D warnings

doc:
	RUSTDOCFLAGS="-D warnings" cargo doc --locked --workspace --no-deps

nostd:
	cargo build --locked -p rime-core --no-default-features --target thumbv7em-none-eabihf
	cargo build --locked -p rime-core --no-default-features --features alloc --target thumbv7em-none-eabihf
	cargo build --locked -p rime-core --no-default-features --features explorer --target thumbv7em-none-eabihf

# Every Rust test (unit, integration, snapshot, doctests) in the release profile make test uses.
unit:
	cargo test --locked --workspace --release

bench:
	cargo run --release -- bench

www:
	@scripts/build-www.sh

serve: www
	@echo "serving www/ on http://127.0.0.1:8080"
	cd www && python3 -m http.server 8080 --bind 127.0.0.1
