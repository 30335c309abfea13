#!/usr/bin/env bash
# The documentation site: pkgdown builds the README as home page, the
# reference grouped by task (_pkgdown.yml) and the vignettes as articles into
# site/; then tools/check-site.R opens it in headless chromium (the 3D widget
# must draw without script errors). The reproduce-thesis article runs on a
# small design here, as in R CMD check; `make demo` renders the full report.
set -euo pipefail
cd "$(dirname "$0")/.."
export HANDMOTION_REPORT_SUBJECTS="${HANDMOTION_REPORT_SUBJECTS:-6}"
export HANDMOTION_REPORT_GRASPS="${HANDMOTION_REPORT_GRASPS:-9,17,22,25,29}"
export HANDMOTION_REPORT_FOLDS="${HANDMOTION_REPORT_FOLDS:-3}"
export NOT_CRAN="${NOT_CRAN:-true}"
# Both cores: the articles' held-out evaluations and model fits run their
# folds and grasp types through future.apply, and the future package takes
# its plan from R_FUTURE_PLAN in every R process pkgdown starts (forked
# workers: no start-up cost; results are the same under any plan)
export R_FUTURE_PLAN="${R_FUTURE_PLAN:-multicore}"
start=$(date +%s)
# (pkgdown::build_site()'s steps, the reference and the articles on both
# cores: tools/site-build.R)
Rscript tools/site-build.R
# The search index as a script as well: a page opened from file:// may load
# a script but not fetch() a JSON file (pkgdown/assets/pkgdown.js loads it).
Rscript -e 'writeLines(c("window.pkgdownSearchIndex = ", readLines("site/search.json", warn = FALSE), ";"), "site/search-index.js")'
echo "site: built in $(( $(date +%s) - start )) s"
Rscript tools/check-site.R site
