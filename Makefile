# rime — every check CI runs is `make test`; it installs what it needs on a fresh machine.
SHELL := /bin/bash
.PHONY: test setup check fmt clippy doc nostd unit www serve bench

test:
	@scripts/test-all.sh

setup:
	@scripts/setup.sh

fmt:
	cargo fmt --all

bench:
	cargo run --release -- bench

www:
	@scripts/build-www.sh

serve: www
	@echo "serving www/ on http://127.0.0.1:8080"
	cd www && python3 -m http.server 8080 --bind 127.0.0.1
