#!/usr/bin/env bash
# Installs everything handmotion needs on a fresh Debian machine, then the package itself.
# Idempotent: each step checks first, so a second run takes seconds.
#   Debian's prebuilt r-cran-* packages for whatever Debian has (far faster than compiling);
#   CRAN only for what Debian lacks (fda.usc with its fda chain, dtw).
set -euo pipefail
cd "$(dirname "$0")/.."

DEBIAN_PKGS=(
  r-base-dev pandoc
  # imports and suggests of handmotion
  r-cran-cli r-cran-rlang r-cran-ggplot2 r-cran-mixtools r-cran-future
  r-cran-future.apply r-cran-progressr r-cran-generics r-cran-xml2 r-cran-knitr
  r-cran-rmarkdown r-cran-roxygen2 r-cran-testthat r-cran-bench r-cran-withr
  r-cran-pkgbuild r-cran-pkgload r-cran-rcmdcheck
  # dependencies of the CRAN-only packages (fda.usc, fda, fds, rainbow, hdrcde, dtw)
  r-cran-proxy r-cran-ks r-cran-pcapp r-cran-desolve r-cran-rcurl r-cran-iterators
  r-cran-foreach r-cran-doparallel r-cran-mvtnorm r-cran-ksamples r-cran-suppdists
  r-cran-httr r-cran-colorspace r-cran-locfit r-cran-rcolorbrewer r-cran-fnn
  r-cran-multicool r-cran-pracma r-cran-kernlab
  # second wave: 3D viewer (and its Shiny bindings) and site, animation export,
  # fast reading, clusters, the shrinkage LDA's reference (MASS)
  r-cran-htmlwidgets r-cran-jsonlite r-cran-shiny r-cran-pkgdown r-cran-gganimate
  r-cran-magick r-cran-data.table r-cran-future.batchtools r-cran-batchtools r-cran-mass
  # the Python front end
  python3-rpy2 python3-numpy python3-pandas python3-pytest
)
# Optional tools: the browser tests and MP4 export skip with a clear message
# where these cannot be installed, so a failure here does not stop the set-up.
OPTIONAL_PKGS=(chromium ffmpeg)

# The given Debian packages that dpkg does not have installed, one a line.
missing_debian() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
# apt-get install of the given packages, as root or through sudo; fails if
# the update or the install fails (the caller decides whether that stops it).
apt_install() {
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "$@"
}

mapfile -t missing < <(missing_debian "${DEBIAN_PKGS[@]}")
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  apt_install "${missing[@]}"
else
  echo "setup: Debian packages already present"
fi
mapfile -t opt_missing < <(missing_debian "${OPTIONAL_PKGS[@]}")
if [ ${#opt_missing[@]} -gt 0 ]; then
  echo "setup: installing optional Debian packages: ${opt_missing[*]}"
  apt_install "${opt_missing[@]}" ||
    echo "setup: could not install ${opt_missing[*]}; browser tests and MP4 export will be skipped"
fi

# CRAN-only packages, in dependency order; installed only when absent.
Rscript -e '
  need <- c("ash", "hdrcde", "rainbow", "fds", "fda", "fda.usc", "dtw")
  have <- rownames(installed.packages())
  todo <- setdiff(need, have)
  if (length(todo)) {
    message("setup: installing from CRAN: ", paste(todo, collapse = ", "))
    lib <- .libPaths()[1]
    # uses the CRAN mirror configured on the machine (repos option, Rprofile.site)
    install.packages(todo, lib = lib,
                     Ncpus = 2, quiet = TRUE)
    bad <- setdiff(todo, rownames(installed.packages()))
    if (length(bad)) stop("setup: could not install from CRAN: ", paste(bad, collapse = ", "))
  } else message("setup: CRAN packages already present")
'

# The package itself, reinstalled only when its sources changed since the last
# install (a hash of the package files is kept in the installed package), so a
# second `make test` does not recompile the C code.
if [ "${HANDMOTION_SKIP_INSTALL:-0}" != "1" ]; then
  hash=$(bash tools/source-hash.sh)
  installed=$(Rscript -e 'd <- system.file(package = "handmotion"); f <- file.path(d, "source-hash"); if (nzchar(d) && file.exists(f)) cat(readLines(f))' 2>/dev/null || true)
  if [ "$hash" = "$installed" ]; then
    echo "setup: handmotion is installed and up to date"
  else
    R CMD INSTALL --preclean --no-multiarch . >/tmp/handmotion-install.log 2>&1 || {
      cat /tmp/handmotion-install.log; exit 1; }
    lib=$(Rscript -e 'cat(dirname(system.file(package = "handmotion")))')
    echo "$hash" > "$lib/handmotion/source-hash"
    echo "setup: handmotion $(Rscript -e 'cat(as.character(packageVersion("handmotion")))') installed"
  fi
fi
