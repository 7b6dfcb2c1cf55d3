#!/usr/bin/env bash
# Instructions per impulse_friction call (docs/performance.md, "The impulse
# law and the 3-D projection"), counted by callgrind: deterministic, where
# the timings of this project's machines move by ±20 % between runs.
#
#   tools/impulse_instructions.sh [INCLUDE_DIR] [START_TYPE] [handle]
#
# INCLUDE_DIR: the headers to measure (default: this checkout's include/;
# for another commit, `git archive <commit> include | tar -x -C DIR`);
# START_TYPE: the warm start's type (default curve_point<double>;
# starting_ratio<double> for headers before issue 26's second session).
# With a third argument `handle`, each count is also taken with the calls made
# through the run-time handle contact_profile (issue 40; its budget: within
# 5 % of the concrete type's).
# Prints, per profile and case, (count with 200 × 64 calls − count with
# none) / 12 800: the calls alone, without the set-up.  Needs valgrind.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
include=${1:-$here/../include}
start=${2:-curve_point<double>}
handle=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v valgrind > /dev/null || { echo "$0: needs valgrind" >&2; exit 2; }
count() {  # PROFILE MODE REPS [HANDLE]
  g++ -std=c++17 -O3 -DNDEBUG -DPROFILE="$1" -DMODE="$2" -DREPS="$3" -DSTART="$start" \
    -DHANDLE="${4:-0}" \
    -I"$include" "$here/impulse_instructions.cpp" -o "$work/driver"
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$work/driver" 2>&1 |
    sed -n 's/.*Collected : //p'
}
names=("uniform disk" "Hertz" "tabulated annulus")
modes=("sliding, warm" "sliding, cold" "sticking")
for p in 0 1 2; do
  for m in 0 1 2; do
    with=$(count "$p" "$m" 200)
    without=$(count "$p" "$m" 0)
    calls=$(((with - without) / 12800))
    if [ -n "$handle" ]; then
      through=$((($(count "$p" "$m" 200 1) - $(count "$p" "$m" 0 1)) / 12800))
      echo "${names[$p]}, ${modes[$m]}: $calls instructions per call," \
           "$through through contact_profile ($(( (through - calls) * 1000 / calls )) per mille)"
    else
      echo "${names[$p]}, ${modes[$m]}: $calls instructions per call"
    fi
  done
done
