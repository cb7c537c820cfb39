# rime — every check CI runs is `make test`; it installs what it needs on a fresh machine.
SHELL := /bin/bash
.PHONY: test setup check fmt clippy doc nostd unit www serve bench

test:
	@scripts/test-all.sh

setup:
	@scripts/setup.sh

fmt:
	cargo fmt --all

# The quick checks, each runnable alone: formatting, lints, docs, the no_std core, unit tests.
check: clippy doc nostd unit
	cargo fmt --all --check

clippy:
	cargo clippy --workspace --all-targets -- -D warnings

doc:
	RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps

# The core on a bare-metal target: without features, and with `alloc` (ARCHITECTURE.md).
nostd:
	cargo build -p rime-core --target thumbv7em-none-eabihf --no-default-features
	cargo build -p rime-core --target thumbv7em-none-eabihf --no-default-features --features alloc

# The tests beside the code (core and terminal); the cross-crate tests are in `make test`.
unit:
	cargo test --release -p rime-core -p rime-tui

bench:
	cargo run --release -- bench

www:
	@scripts/build-www.sh

serve: www
	@echo "serving www/ on http://127.0.0.1:8080"
	cd www && python3 -m http.server 8080 --bind 127.0.0.1
