#!/bin/bash
# A fuzz campaign for one harness (docs/reliability.md, "The second campaign"):
# runs the libFuzzer binary from the sanitize preset for a fixed wall time,
# with ASLR on (unlike CTest's reproducible runs), restarting with the next
# seed after each report on the corpus gathered so far.  Reports
# (crash-*, timeout-*, oom-*) and one log per seed land in OUT/HARNESS, and
# one line per seed (exit code, inputs executed) in OUT/HARNESS/summary.
#
#   fuzz/campaign.sh HARNESS SECONDS [FIRST_SEED] [BUILD_DIR] [OUT]
#   e.g. fuzz/campaign.sh contact 420 101 build/sanitize fuzz-campaign
#
# Replay a report with BUILD_DIR/fuzz/fuzz_HARNESS OUT/HARNESS/crash-<hash>.
set -u
h=${1:?harness: disk profiles coupling terminal stop_time contact}
total=${2:?seconds}
seed=${3:-101}
build=${4:-build/sanitize}
[ -d "$build" ] && build=$(cd "$build" && pwd)
out=${5:-fuzz-campaign}
bin=$build/fuzz/fuzz_$h
[ -x "$bin" ] || { echo "campaign.sh: no $bin (cmake --preset sanitize && cmake --build --preset sanitize)" >&2; exit 2; }
d=$out/$h
mkdir -p "$d/corpus"
d=$(cd "$d" && pwd)
end=$(( $(date +%s) + total ))
while [ "$(date +%s)" -lt "$end" ]; do
  left=$(( end - $(date +%s) ))
  "$bin" "$d/corpus" -seed="$seed" -max_len=512 -timeout=30 -max_total_time="$left" \
    -artifact_prefix="$d/" -print_final_stats=1 > "$d/log.$seed" 2>&1
  rc=$?
  echo "seed $seed rc $rc $(grep -E 'stat::number_of_executed_units' "$d/log.$seed")" | tee -a "$d/summary"
  seed=$((seed + 1))
done
