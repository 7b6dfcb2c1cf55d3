#!/usr/bin/env bash
# The pair style's cost against LAMMPS' own pair_style granular with the
# same models (docs/performance.md, "LAMMPS"): the "Pair" time of LAMMPS'
# timing breakdown, and beside it the "Modify" time (the fixes: the walls,
# with fix nve/sphere and fix gravity), serial, on
#   pour  in.pour_ab    (400 spheres poured onto a floor of frozen spheres, 5000 steps)
#   pile  in.pile_cost  (2000 spheres settled on a wall, then 2000 steps timed)
#   drum  in.drum_cost  (1060 spheres in a turning drum of region walls,
#                        rolling resistance on, 10 000 steps, then 4000 timed)
# for the models stock, uncoupled (coupling no) and coupled (coupling yes),
# each run RUNS times (default 3), interleaved; prints every time, then per
# case and model the medians and their ratios to stock's medians.  The
# times are CPU seconds: each section's wall time times its %CPU (the runs
# take -var timer full), which leaves out the time a run waited for a core
# on a shared machine; the per-run lines give the wall times too.
#
# Then one more run of uncoupled and of coupled per case, untimed, counts
# the plugin's contacts between spheres (-var stats yes: compute pair
# granular/spinslide, the mean over the timed steps), for the last table:
#   ns/contact  the model's median Pair time over its touching contacts
#               summed over the timed steps (stock: over uncoupled's, the
#               same law in the plugin);
#   ns/slide    (coupled - uncoupled median Pair time) over coupled's
#               contacts at the friction limit (sliding) summed over the
#               timed steps: what the coupled cap costs a sliding contact.
#
#   engines/lammps/examples/pair_cost.sh LMP PLUGIN [RUNS] [pour|pile|drum|both|all] [LAMMPS ARGS...]
#
# both: pour and pile; all: pour, pile and drum (default: both).
# LMP: a LAMMPS built by engines/lammps/build_lammps.sh (PREFIX/bin/lmp);
# PLUGIN: spinslideplugin.so built against it (engines/lammps/README.md).
# LAMMPS ARGS go to every run (the test lammps.pair_cost_script shortens the
# runs with -var nsteps, -var nsettle and -var ntime).  Run it on an
# otherwise idle machine: the ratios move with the load.
set -euo pipefail
usage="usage: $0 LMP PLUGIN [RUNS] [pour|pile|drum|both|all] [LAMMPS ARGS...]"
if [ $# -lt 2 ]; then
  echo "$usage" >&2
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
  pour | pile | drum) cases=("$which") ;;
  both) cases=(pour pile) ;;
  all) cases=(pour pile drum) ;;
  *) echo "$0: the case is pour, pile, drum, both or all, not $which" >&2; echo "$usage" >&2; exit 2 ;;
esac
models=(stock uncoupled coupled)

input_of() {
  case $1 in
    pour) echo "$here/in.pour_ab" ;;
    pile) echo "$here/in.pile_cost" ;;
    drum) echo "$here/in.drum_cost" ;;
  esac
}

# run CASE MODEL OUT [ARGS...]: one serial LAMMPS run in the scratch
# directory, its outputs named OUT (OUT.log the log).
run() {
  local c=$1 m=$2 out=$3 log=$3.log
  shift 3
  (cd "$work" && "$lmp" -in "$(input_of "$c")" -var model "$m" -var plugin "$plugin" \
     -var out "$out" -var timer full "${extra[@]}" "$@" -screen none -log "$log" > /dev/null) ||
    { echo "$0: LAMMPS failed on $c, $m (log: $log)" >&2; trap - EXIT; exit 1; }
}

# The last row NAME of a log's timing breakdown (timer full): its average
# wall time over the ranks, then that times its %CPU.
row_time() { grep -E "^$2 +\|" "$1" | tail -n 1 | awk -F'|' '{print $3 + 0, $3 * $6 / 100}'; }
# The steps of a log's last run (the timed one).
timed_steps() { sed -n 's/^Loop time of .* for \([0-9]*\) steps .*/\1/p' "$1" | tail -n 1; }

declare -A pair modify steps
for c in "${cases[@]}"; do
  for ((r = 1; r <= runs; ++r)); do
    for m in "${models[@]}"; do
      log=$work/$c.$m.$r.log
      run "$c" "$m" "$work/$c.$m.$r"
      read -r pw p < <(row_time "$log" Pair)
      read -r fw f < <(row_time "$log" Modify)
      echo "$c $m run $r: Pair $p s (wall $pw s), Modify $f s (wall $fw s)"
      pair[$c.$m]="${pair[$c.$m]:-} $p"
      modify[$c.$m]="${modify[$c.$m]:-} $f"
      steps[$c]=$(timed_steps "$log")
    done
  done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {print (b > 0) ? a / b : 0}'; }
echo
echo "medians, CPU seconds"
printf '%-5s %-10s %10s %8s %11s %8s\n' case model "Pair [s]" "/ stock" "Modify [s]" "/ stock"
declare -A pair_median
for c in "${cases[@]}"; do
  ps=$(echo "${pair[$c.stock]}" | median) fs=$(echo "${modify[$c.stock]}" | median)
  for m in "${models[@]}"; do
    p=$(echo "${pair[$c.$m]}" | median) f=$(echo "${modify[$c.$m]}" | median)
    pair_median[$c.$m]=$p
    printf '%-5s %-10s %10.4f %8.2f %11.4f %8.2f\n' "$c" "$m" "$p" "$(ratio "$p" "$ps")" "$f" "$(ratio "$f" "$fs")"
  done
done

# The counting runs: the first two columns of a stats file (after the step)
# are the mean contacts and sliding contacts per step.
declare -A contacts sliding
for c in "${cases[@]}"; do
  for m in uncoupled coupled; do
    run "$c" "$m" "$work/$c.$m.count" -var stats yes
    counts=$(awk '!/^#/ {print $2, $3}' "$work/$c.$m.count.stats")
    contacts[$c.$m]=${counts% *} sliding[$c.$m]=${counts#* }
  done
done
echo
echo "contacts between spheres per timed step (the plugin's count; stock: uncoupled's)"
printf '%-5s %-10s %6s %10s %10s %11s %9s\n' case model steps contacts sliding ns/contact ns/slide
for c in "${cases[@]}"; do
  for m in "${models[@]}"; do
    counted=$m
    [ "$m" = stock ] && counted=uncoupled
    n=${contacts[$c.$counted]} s=${sliding[$c.$counted]}
    ns=$(awk -v t="${pair_median[$c.$m]}" -v n="$n" -v k="${steps[$c]}" 'BEGIN {print (n > 0) ? 1e9 * t / (n * k) : 0}')
    slide=-
    if [ "$m" = coupled ]; then
      slide=$(awk -v a="${pair_median[$c.coupled]}" -v b="${pair_median[$c.uncoupled]}" -v s="$s" -v k="${steps[$c]}" \
        'BEGIN {printf "%.1f", (s > 0) ? 1e9 * (a - b) / (s * k) : 0}')
    fi
    printf '%-5s %-10s %6d %10.1f %10.1f %11.1f %9s\n' "$c" "$m" "${steps[$c]}" "$n" "$s" "$ns" "$slide"
  done
done
