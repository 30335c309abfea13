#!/usr/bin/env bash
# R CMD build then R CMD check --no-manual; fails on any ERROR or WARNING and
# prints the NOTEs so they can be explained.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf handmotion.Rcheck handmotion_*.tar.gz
R CMD build --no-manual . >/tmp/handmotion-build.log 2>&1 || { cat /tmp/handmotion-build.log; exit 1; }
tarball=$(ls handmotion_*.tar.gz)
_R_CHECK_FORCE_SUGGESTS_=false R CMD check --no-manual "$tarball" | tee /tmp/handmotion-check.log
if grep -qE "^Status: .*(ERROR|WARNING)" /tmp/handmotion-check.log; then
  echo "check: R CMD check reported errors or warnings" >&2; exit 1
fi
grep -q "^Status:" /tmp/handmotion-check.log || { echo "check: no status line" >&2; exit 1; }
