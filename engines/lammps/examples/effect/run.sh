#!/bin/sh
# What coupling does to granular matter (issue 30; docs/lammps.md, "What
# coupling does to a heap and a drum"): an experiment run coupled and
# uncoupled, with rolling resistance off and on, fifteen seeds each (60
# runs, two at a time), then its analysis on each set.
#
#   run.sh repose|drum LMP PLUGIN OUTDIR [SEEDS] [LAMMPS ARGUMENTS]
#
# SEEDS: the seeds, in one argument (default: the fifteen of
# docs/lammps.md); LAMMPS ARGUMENTS: more -var settings for every run, in
# one argument (a test shortens the runs so).
# repose: in.repose (the heap on a plate), analysed by repose.py;
# drum: in.drum (the rotating drum), analysed by drum.py.  Each run writes
# OUTDIR/<experiment>_<coupling>_<rolling>_<seed>.{xyz|dump} and its log;
# the analyses' output goes to OUTDIR/<experiment>_results.txt.
set -eu
experiment=$1
lmp=$2
plugin=$3
out=$4
seeds=${5:-"4767548 1234567 7654321 2468024 1357913 1111 2222 3333 4444 5555 6666 7777 8888 9999 1010"}
extra=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
case "$experiment" in
  repose) suffix=xyz ;;
  drum) suffix=dump ;;
  *) echo "run.sh: the experiment is repose or drum, not $experiment" >&2; exit 2 ;;
esac
mkdir -p "$out"
pids=""
count=0
for rolling in no yes; do
  for coupling in no yes; do
    for seed in $seeds; do
      name=${experiment}_${coupling}_${rolling}_${seed}
      (cd "$out" && "$lmp" -in "$here/in.$experiment" -var plugin "$plugin" \
         -var coupling "$coupling" -var rolling "$rolling" -var seed "$seed" -var out "$name" \
         -log "log.$name" -screen none $extra) &
      pids="$pids $!"
      count=$((count + 1))
      if [ $((count % 2)) -eq 0 ]; then
        for p in $pids; do wait "$p"; done
        pids=""
        echo "run.sh: $count runs done" >&2
      fi
    done
  done
done
for p in $pids; do wait "$p"; done
results="$out/${experiment}_results.txt"
: > "$results"
for rolling in no yes; do
  for coupling in no yes; do
    echo "coupling $coupling, rolling $rolling:" >> "$results"
    /usr/bin/python3 "$here/$experiment.py" "$out"/${experiment}_${coupling}_${rolling}_*.$suffix >> "$results"
  done
done
cat "$results"
