#!/usr/bin/env bash
# The pair style's cost against LAMMPS' own pair_style granular with the
# same models (docs/performance.md, "LAMMPS"): the "Pair" time of LAMMPS'
# timing breakdown, serial, on
#   pour  in.pour_ab   (400 spheres poured onto a floor of frozen spheres, 5000 steps)
#   pile  in.pile_cost (2000 spheres settled on a wall, then 2000 steps timed)
# for the models stock, uncoupled (coupling no) and coupled (coupling yes),
# each run RUNS times (default 3), interleaved; prints every time, then per
# case and model the median and its ratio to stock's median.
#
#   engines/lammps/examples/pair_cost.sh LMP PLUGIN [RUNS] [pour|pile|both] [LAMMPS ARGS...]
#
# LMP: a LAMMPS built by engines/lammps/build_lammps.sh (PREFIX/bin/lmp);
# PLUGIN: spinslideplugin.so built against it (engines/lammps/README.md).
# LAMMPS ARGS go to every run (the test lammps.pair_cost_script shortens the
# runs with -var nsteps, -var nsettle and -var ntime).  Run it on an
# otherwise idle machine: the ratios move with the load.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 LMP PLUGIN [RUNS] [pour|pile|both] [LAMMPS ARGS...]" >&2
  exit 2
fi
lmp=$1 plugin=$2 runs=${3:-3} which=${4:-both}
shift $(($# < 4 ? $# : 4))
extra=("$@")
[ -x "$lmp" ] || { echo "$0: $lmp is not an executable LAMMPS" >&2; exit 2; }
[ -f "$plugin" ] || { echo "$0: no plugin at $plugin" >&2; exit 2; }
lmp=$(readlink -f "$lmp") plugin=$(readlink -f "$plugin")  # the runs cd to a scratch directory
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case $which in
  pour) cases=(pour) ;;
  pile) cases=(pile) ;;
  both) cases=(pour pile) ;;
  *) echo "$0: the case is pour, pile or both, not $which" >&2; exit 2 ;;
esac

# The last "Pair" row of a log: its average time over the ranks.
pair_time() { grep -E '^Pair +\|' "$1" | tail -n 1 | awk -F'|' '{gsub(/ /, "", $3); print $3}'; }

declare -A times
for c in "${cases[@]}"; do
  input=$here/in.pour_ab
  [ "$c" = pile ] && input=$here/in.pile_cost
  for ((r = 1; r <= runs; ++r)); do
    for m in stock uncoupled coupled; do
      log=$work/$c.$m.$r.log
      (cd "$work" && "$lmp" -in "$input" -var model "$m" -var plugin "$plugin" \
         -var out "$work/$c.$m" "${extra[@]}" -screen none -log "$log" > /dev/null) ||
        { echo "$0: LAMMPS failed on $c, $m (log: $log)" >&2; trap - EXIT; exit 1; }
      t=$(pair_time "$log")
      echo "$c $m run $r: Pair $t s"
      times[$c.$m]="${times[$c.$m]:-} $t"
    done
  done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
echo
printf '%-5s %-10s %12s %8s\n' case model "median [s]" "/ stock"
for c in "${cases[@]}"; do
  s=$(echo "${times[$c.stock]}" | median)
  for m in stock uncoupled coupled; do
    t=$(echo "${times[$c.$m]}" | median)
    printf '%-5s %-10s %12.4f %8.2f\n' "$c" "$m" "$t" "$(awk -v t="$t" -v s="$s" 'BEGIN {print t / s}')"
  done
done
