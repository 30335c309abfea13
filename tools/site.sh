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
# Both cores are used by tools/site-build.R, which builds two pages
# (articles, halves of the reference) at a time; inside each, the future
# plan is sequential. A multicore plan there put four processes on two
# cores and forked the R session for every future_lapply() call: side by
# side at load 6-8, fit_grasp_models() on 20 subjects took 14.1 s of CPU
# (4.8 s of it system time, the forks) with it and 8.5 s sequential; the
# whole build's jobs took 790 s of CPU with it (load 10-25) and 267 s
# without (load 3-15), together with the cuts in the articles. (Results are
# the same under any plan.)
export R_FUTURE_PLAN="${R_FUTURE_PLAN:-sequential}"
start=$(date +%s)
# a fresh site each time: pages are all rebuilt anyway (lazy = FALSE), and a
# file an article writes itself (the GIF of looking-at-hands) refuses to
# overwrite the last build's
rm -rf site
# (pkgdown::build_site()'s steps, the reference, the articles, the home
# page and the changelog on both cores, and the search index as a script
# for pages opened from file://: tools/site-build.R)
Rscript tools/site-build.R
echo "site: built in $(( $(date +%s) - start )) s"
Rscript tools/check-site.R site
# CPU seconds beside the elapsed ones: on a shared machine the elapsed time
# says how busy it was, the CPU time how much work the site is
echo "site: built and checked in $(( $(date +%s) - start )) s; CPU seconds (user, system) of the builds and the browser:"
times
