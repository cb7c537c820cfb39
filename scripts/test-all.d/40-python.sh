#!/usr/bin/env bash
# rime from Python (issue 23): builds the abi3 wheel with maturin (in the workspace's target
# directory), installs it into target/venv and runs the pytest suite there: python/tests (against
# the `rime` binary, REBOUND 5.2.2 and DustPy 1.0.9), the doctests of the installed package and the
# README's Python examples. Ends with pytest's summary line.
set -euo pipefail
cd "$(dirname "$0")/../.."
scripts/setup-python.sh
venv=target/venv
# The CLI is the tests' independent path to the core: make test's build step built it; run alone,
# build it the same way (nothing is built twice).
RIME_BIN=$(scripts/rime-bin.sh)
export RIME_BIN
wheels="${CARGO_TARGET_DIR:-target}/wheels"
rm -f "$wheels"/rime_grains-*.whl
start=$(date +%s.%N)
(cd python && "../$venv/bin/maturin" build --release --quiet 2>&1 | grep -v '^📦 Including' || true)
wheel=$(ls "$wheels"/rime_grains-*-cp39-abi3-*.whl)
build=$(python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$start" "$(date +%s.%N)")
echo "wheel: $(basename "$wheel"), $(du -k "$wheel" | cut -f1) KiB, built in ${build} s"
"$venv/bin/python" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel"
# The benchmark reports (never asserts): 1e6 speeds at `fast` against the Rust batch path, and the
# cost per collision against REBOUND's hard-sphere resolve with a compiled C Bridges law.
("$venv/bin/python" python/bench/bench.py --quick || echo "benchmark failed (not a test)") |
  sed 's/^/report: /'
# rime_grains.dustpy's update cost on DustPy's default disk (100 cells × 120² pairs; issue 39).
("$venv/bin/python" python/bench/dustpy_bench.py --quick || echo "DustPy benchmark failed (not a test)") |
  sed 's/^/report: /'
# From the repository root: `python/` is not on sys.path, so the tests import the installed wheel.
out=$(mktemp)
rc=0
"$venv/bin/python" -m pytest -c python/pytest.ini --rootdir python python/tests \
  --doctest-modules --pyargs rime_grains 2>&1 | tee "$out" || rc=$?
# Each pytest test counts as one test of make test: "count: N passed, M failed" from its summary.
summary=$(grep -E '^=+ .*(passed|failed|error).* in [0-9.]+s' "$out" | tail -1 || true)
p=$(echo "$summary" | { grep -oE '[0-9]+ passed' || true; } | awk '{ s += $1 } END { print s + 0 }')
f=$(echo "$summary" | { grep -oE '[0-9]+ (failed|errors?)' || true; } | awk '{ s += $1 } END { print s + 0 }')
echo "count: ${p:-0} passed, ${f:-0} failed"
rm -f "$out"
exit "$rc"
