#!/bin/sh
# Runs a libFuzzer harness reproducibly: with address-space layout
# randomisation off for this process (setarch -R), where the system allows it.
# libFuzzer's comparison tracing keys its tables on code addresses, so with
# ASLR on the same seed explores different inputs from run to run; with it off
# a fixed seed and a fixed binary give the same run every time, and CI checks
# exactly what a local run of the same command checked.  Where personality()
# is refused (some containers), the harness runs as is and says so.
if setarch "$(uname -m)" -R true 2>/dev/null; then
  exec setarch "$(uname -m)" -R "$@"
fi
echo "run_fixed.sh: cannot turn ASLR off here; this fuzz run is not reproducible" >&2
exec "$@"
