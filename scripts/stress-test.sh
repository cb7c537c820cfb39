#!/usr/bin/env bash
# The stress run (issue 34), outside `make test`: the browser checks (tests/e2e/e2e.mjs, the page;
# tests/e2e/ring.mjs, the ring card) and the terminal check (tui/tests/e2e_tmux.sh) run N times
# with K CPU burners (`yes > /dev/null`) beside them; prints each check's pass count, the load and
# the minutes each run took. Exits non-zero unless every check passed every run.
#
#   scripts/stress-test.sh [-n RUNS] [-k BURNERS]    (defaults: 5 runs, one burner per core)
#
# It builds what the web step of make test builds (www/, the release `rime`); the logs of every
# run are kept in target/stress/.
set -euo pipefail
cd "$(dirname "$0")/.."

runs=5
burners=$(nproc)
while getopts "n:k:h" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    k) burners=$OPTARG ;;
    *) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
  esac
done
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "stress-test: -n: runs must be a positive whole number, not '$runs'" >&2; exit 2; }
[[ $burners =~ ^[0-9]+$ ]] || { echo "stress-test: -k: burners must be a whole number, not '$burners'" >&2; exit 2; }

scripts/setup-web.sh >/dev/null
scripts/build-www.sh >/dev/null
rime_bin=$(scripts/rime-bin.sh)
source scripts/serve-www.sh # sets port and server
out=target/stress
rm -rf "$out"
mkdir -p "$out"

burner_pids=()
stop() {
  for p in "${burner_pids[@]}"; do kill "$p" 2>/dev/null || true; done
  kill "$server" 2>/dev/null || true
}
trap stop EXIT
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for _ in $(seq "$burners"); do
  yes > /dev/null &
  burner_pids+=($!)
done
echo "stress-test: $runs runs, $burners burners on $(nproc) cores (load before the burners: $load_before)"

t_all=$(date +%s)
for run in $(seq "$runs"); do
  t0=$(date +%s)
  log="$out/run-$run"
  RIME_BIN=$rime_bin node tests/e2e/e2e.mjs "http://127.0.0.1:$port/" >"$log-page.log" 2>&1 || true
  RIME_BIN=$rime_bin node tests/e2e/ring.mjs "http://127.0.0.1:$port/" >"$log-ring.log" 2>&1 || true
  if tui/tests/e2e_tmux.sh "$rime_bin" >"$log-tmux.log" 2>&1; then
    echo "PASS terminal: tui/tests/e2e_tmux.sh" >>"$log-tmux.log"
  else
    echo "FAIL terminal: tui/tests/e2e_tmux.sh" >>"$log-tmux.log"
  fi
  failed=$(cat "$log"-*.log | grep -c '^FAIL ' || true)
  echo "run $run: $(cat "$log"-*.log | grep -c '^PASS ' || true) passed, $failed failed, $(( ($(date +%s) - t0 + 30) / 60 )) min, load $(cut -d' ' -f1-3 /proc/loadavg)"
  cat "$log"-*.log | grep '^FAIL ' | cut -c1-300 | sed 's/^/  /' || true
done

# Pass counts per check (a check missing from a run, its script having stopped, counts as not passed).
echo "--- pass counts ($runs runs, $burners burners, $(( ($(date +%s) - t_all + 30) / 60 )) min)"
cat "$out"/run-*.log | grep -E '^(PASS|FAIL) ' | sed -E 's/^(PASS|FAIL) //; s/ — .*$//' | sort -u >"$out/checks.txt"
while IFS= read -r name; do
  n=$(cat "$out"/run-*.log | grep -E '^PASS ' | sed -E 's/^PASS //; s/ — .*$//' | grep -cxF -- "$name" || true)
  printf '%d/%d  %s\n' "$n" "$runs" "${name:0:150}"
done <"$out/checks.txt" | sort -n | tee "$out/pass-counts.txt"
checks=$(wc -l <"$out/checks.txt")
short=$(awk -v r="$runs" -F'[/ ]' '$1 != r' "$out/pass-counts.txt" | wc -l)
echo "stress-test: $((checks - short)) of $checks checks passed $runs of $runs runs (logs in $out/)"
[[ $short -eq 0 ]]
