#!/usr/bin/env bash
# R CMD build then R CMD check --no-manual; fails on any ERROR or WARNING and
# prints the NOTEs so they can be explained.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -rf handmotion.Rcheck handmotion_*.tar.gz
# The reproduce-thesis vignette is the full report; R CMD build and check each knit it,
# so here it runs on a small design (the README's demo command renders the full one).
export HANDMOTION_REPORT_SUBJECTS="${HANDMOTION_REPORT_SUBJECTS:-6}"
export HANDMOTION_REPORT_GRASPS="${HANDMOTION_REPORT_GRASPS:-9,17,22,25,29}"
export HANDMOTION_REPORT_FOLDS="${HANDMOTION_REPORT_FOLDS:-3}"
export NOT_CRAN="${NOT_CRAN:-true}"
R CMD build --no-manual . >/tmp/handmotion-build.log 2>&1 || { cat /tmp/handmotion-build.log; exit 1; }
tarball=$(ls handmotion_*.tar.gz)
_R_CHECK_FORCE_SUGGESTS_=false R CMD check --no-manual "$tarball" | tee /tmp/handmotion-check.log
if grep -qE "^Status: .*(ERROR|WARNING)" /tmp/handmotion-check.log; then
  echo "check: R CMD check reported errors or warnings" >&2; exit 1
fi
grep -q "^Status:" /tmp/handmotion-check.log || { echo "check: no status line" >&2; exit 1; }
