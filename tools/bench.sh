#!/usr/bin/env bash
# Runs every benchmark in bench/ (not the shared bench/_common.R), in turn,
# from the repository root; fails at the end if any of them failed, naming
# each. BENCH_QUICK=1 runs them at small sizes (make bench-quick).
set -uo pipefail
cd "$(dirname "$0")/.."
failed=()
start=$(date +%s)
for f in bench/*.R; do
  case "$(basename "$f")" in _*) continue ;; esac
  t0=$(date +%s)
  if ! Rscript "$f"; then failed+=("$f"); fi
  echo "-- $f: $(( $(date +%s) - t0 )) s"
done
echo "bench: $(( $(date +%s) - start )) s in all${BENCH_QUICK:+ (quick mode)}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "bench: FAILED: ${failed[*]}" >&2
  exit 1
fi
