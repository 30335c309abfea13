#!/usr/bin/env bash
# One hash of the package's sources (what R CMD INSTALL builds from). setup.sh
# stores it in the installed package; bench/_common.R compares against it to
# know whether the installed build is the current one.
cd "$(dirname "$0")/.."
find DESCRIPTION NAMESPACE R src inst data vignettes -type f \
  ! -name '*.o' ! -name '*.so' ! -path '*__pycache__*' ! -path '*.pytest_cache*' -print0 \
  | sort -z | xargs -0 sha1sum | sha1sum | cut -d' ' -f1
