#!/usr/bin/env bash
# End-to-end test of the terminal explorer: drives the real `rime` binary in a detached tmux session.
#
#   tui/tests/e2e_tmux.sh [path/to/rime]
#
# Starts rime at 100×30, waits for the chart, selects the ice-frost preset (`p`), changes the layer
# viscosity (select the row, `l`), checks that the readout changed, exports (`x`) and checks the
# export folder and its CSVs, undoes and redoes the edit (`u`, `U`), scrolls the help, saves (`w`),
# edits again and quits (Ctrl-C, then `q`: each asks about the unsaved edit: `n` stays, `y` quits) and checks
# exit code 0. Exits non-zero with a message on
# any failure. Nothing sleeps for a fixed time: every wait polls the screen (or a file) for a condition,
# and its timeout is only a hang guard. GUARD = 30 s: the slowest wait takes under 1 s on an idle
# machine (the first frame; every other wait is one key's redraw), so the guard is over 30× that and
# a loaded machine still passes.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BIN="${1:-$ROOT/target/release/rime}"
if [[ ! -x "$BIN" ]]; then
    (cd "$ROOT" && cargo build --locked --release --workspace >&2)
fi
BIN="$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")"
command -v tmux >/dev/null || { echo "e2e_tmux: tmux is not installed" >&2; exit 1; }

WORK="$(mktemp -d "${TMPDIR:-/tmp}/rime-e2e.XXXXXX")"
SESSION="rime-e2e-$$"
cleanup() {
    tmux kill-session -t "$SESSION" 2>/dev/null || true
    rm -rf "$WORK"
}
trap cleanup EXIT

fail() {
    echo "e2e_tmux: FAIL: $*" >&2
    echo "---- last screen ----" >&2
    tmux capture-pane -p -t "$SESSION" >&2 2>/dev/null || true
    exit 1
}

screen() { tmux capture-pane -p -t "$SESSION"; }

# wait_for TEXT [TIMEOUT]: polls the screen until it contains TEXT.
GUARD=30
SLOWEST=0 SLOWEST_WHAT=""
# noted T0 WHAT: remembers the slowest wait (reported at the end, so the guard's margin is visible).
noted() {
    local dt
    dt=$(awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
    if awk -v a="$dt" -v b="$SLOWEST" 'BEGIN { exit !(a > b) }'; then SLOWEST=$dt SLOWEST_WHAT=$2; fi
}
wait_for() {
    local text="$1" timeout="${2:-$GUARD}" start=$SECONDS t0
    t0=$(date +%s.%N)
    while (( SECONDS - start < timeout )); do
        if screen | grep -qF -- "$text"; then noted "$t0" "$text"; return 0; fi
        sleep 0.05
    done
    fail "timed out after ${timeout}s waiting for '$text'"
}

# readout: the chart cursor readout line (▸ g … ε_N …).
# (The panel's right border is ┃ while it has the focus, │ otherwise.)
readout() { screen | grep -F "ε_N" | grep -E "[│┃] ▸" | head -1 | sed -E 's/^.*[│┃] ▸//'; }

tmux new-session -d -s "$SESSION" -x 100 -y 30 -c "$WORK" \
    "'$BIN' --accuracy fast; echo EXIT:\$? > '$WORK/exit'; sleep 60"

wait_for "ε_N(g_N)"
wait_for "t_c"
wait_for "sliding law"
before_preset="$(readout)"
[[ -n "$before_preset" ]] || fail "no chart readout on the first screen"

# Preset ice-frost (layer on), then select the layer-viscosity row and increase it.
tmux send-keys -t "$SESSION" p
wait_for "ice-frost"
wait_for "g_s(layer)"
# Move the cursor to where the layer matters (≈ 20 µm/s, just above g_s), from the default 1 cm/s;
# each { is 1/3 decade.
for _ in 1 2 3 4 5 6 7 8; do tmux send-keys -t "$SESSION" '{'; done
# (No sleep: keys are handled in order, so once the row selected below shows, the cursor has moved.)
# The panel starts on row 0; layer.viscosity is row 12 (0-based) of the parameter list.
for _ in $(seq 12); do tmux send-keys -t "$SESSION" j; done
wait_for "▸η* layer viscosity"
before="$(readout)"
[[ "$before" == *"ε_N"* ]] || fail "no readout before the change"
tmux send-keys -t "$SESSION" l
wait_for "1.25 kPa s"
# Wait for the recomputed frame: the readout must change.
start=$SECONDS
after="$(readout)"
while [[ "$after" == "$before" ]] && (( SECONDS - start < GUARD )); do
    sleep 0.2
    after="$(readout)"
done
[[ "$after" != "$before" ]] || fail "readout did not change after raising η* ('$before')"
echo "e2e_tmux: readout before: $before"
echo "e2e_tmux: readout after:  $after"

# Export.
tmux send-keys -t "$SESSION" x
wait_for "exported"
start=$SECONDS
dir=""
while [[ -z "$dir" ]] && (( SECONDS - start < GUARD )); do
    dir="$(find "$WORK" -maxdepth 1 -type d -name 'rime-export-*' | head -1)"
    [[ -n "$dir" ]] || sleep 0.2
done
[[ -n "$dir" ]] || fail "no rime-export-* folder in $WORK"
for f in scene.json eps_curve.csv eps_family.csv stick_map.csv eps_n.svg stick_map.svg; do
    [[ -s "$dir/$f" ]] || fail "export is missing $f"
done
grep -q '"viscosity": 1250' "$dir/scene.json" || fail "scene.json does not hold the changed viscosity"
# What the terminal exports is byte for byte what the command line prints for the same scene,
# speeds, grid and level (issue 11); the export adds only its `# ` context lines.
grep -v '^#' "$dir/eps_curve.csv" > "$WORK/terminal-curve.csv"
first="$(sed -n 2p "$WORK/terminal-curve.csv" | cut -d, -f1)"
last="$(tail -1 "$WORK/terminal-curve.csv" | cut -d, -f1)"
points=$(( $(wc -l < "$WORK/terminal-curve.csv") - 1 ))
"$BIN" curve --scene "$dir/scene.json" --accuracy fast --from "$first" --to "$last" \
    --points "$points" --format csv > "$WORK/cli-curve.csv"
cmp -s "$WORK/terminal-curve.csv" "$WORK/cli-curve.csv" \
    || fail "eps_curve.csv differs from rime curve: $(diff "$WORK/terminal-curve.csv" "$WORK/cli-curve.csv" | head -4)"
grep -v '^#' "$dir/stick_map.csv" > "$WORK/terminal-map.csv"
n="$(tail -n +2 "$WORK/terminal-map.csv" | cut -d, -f1 | sort -u | wc -l)"
max="$(tail -n +2 "$WORK/terminal-map.csv" | cut -d, -f1 | sort -g | tail -1)"
"$BIN" map --scene "$dir/scene.json" --accuracy fast --max "$max" --n "$n" --format csv \
    > "$WORK/cli-map.csv"
cmp -s "$WORK/terminal-map.csv" "$WORK/cli-map.csv" \
    || fail "stick_map.csv differs from rime map: $(diff "$WORK/terminal-map.csv" "$WORK/cli-map.csv" | head -4)"
echo "e2e_tmux: the export's curve ($points speeds) and map (${n}×${n}) equal rime curve / rime map byte for byte"

# Undo the edit (u), redo it (U): the readout follows.
tmux send-keys -t "$SESSION" u
wait_for "undone"
start=$SECONDS
while [[ "$(readout)" != "$before" ]] && (( SECONDS - start < GUARD )); do sleep 0.2; done
[[ "$(readout)" == "$before" ]] || fail "u did not restore the readout ('$before')"
tmux send-keys -t "$SESSION" U
wait_for "redone"
wait_for "1.25 kPa s"

# The help scrolls (PgDn) and says how; Esc closes it.
tmux send-keys -t "$SESSION" '?'
wait_for "scroll"
tmux send-keys -t "$SESSION" NPage
wait_for "Glossary"
tmux send-keys -t "$SESSION" Escape
start=$SECONDS
while screen | grep -qF "Glossary" && (( SECONDS - start < GUARD )); do sleep 0.2; done
screen | grep -qF "Glossary" && fail "Esc did not close the help"

# w writes the scene file; a second session's w would ask before overwriting it.
tmux send-keys -t "$SESSION" w
wait_for "saved scene"
[[ -s "$WORK/rime-scene.json" ]] || fail "w did not write rime-scene.json"

# Edit again, then Ctrl-C asks like q (unsaved edits, issue 22 item 8); n stays, q y quits with
# exit code 0.
tmux send-keys -t "$SESSION" l
wait_for "1.56"
tmux send-keys -t "$SESSION" C-c
wait_for "quit anyway?"
tmux send-keys -t "$SESSION" n
wait_for "not quitting"
tmux send-keys -t "$SESSION" q
wait_for "quit anyway?"
tmux send-keys -t "$SESSION" y
start=$SECONDS
while [[ ! -s "$WORK/exit" ]] && (( SECONDS - start < GUARD )); do sleep 0.2; done
[[ -s "$WORK/exit" ]] || fail "rime did not exit after q"
code="$(cat "$WORK/exit")"
[[ "$code" == "EXIT:0" ]] || fail "rime exited with '$code', expected EXIT:0"
echo "e2e_tmux: ok (changed a parameter, exported to $(basename "$dir"), undo/redo, help scroll, save, asked before quitting, quit with 0)"
echo "report: tmux e2e: slowest wait ${SLOWEST} s (for '${SLOWEST_WHAT}'); hang guard ${GUARD} s"
