# handmotion: the two README commands are `make demo` and `make test`.
# Every target installs what is missing first (tools/setup.sh is idempotent).
SHELL := /bin/bash
R ?= Rscript
PY ?= /usr/bin/python3
OUT ?= output
# The real GraspDB14 samples and thesis tables live beside the repository, never in it.
export HANDMOTION_SHARED ?= $(abspath ../shared)
# snapshot tests run outside CRAN
export NOT_CRAN ?= true

.PHONY: setup demo test test-r test-python test-calibration check bench bench-quick docs site clean

setup:
	bash tools/setup.sh

## Main job: fit every model on the embedded default data and render the thesis reproduction into $(OUT)/
demo: setup
	$(R) tools/demo.R $(OUT)

## The whole test suite: R (testthat) then Python (pytest)
test: setup test-r test-python

test-r:
	HANDMOTION_SLOW_TESTS=$${HANDMOTION_SLOW_TESTS:-true} $(R) tools/run-tests.R

## The calibration of the default data over seeds 1-5 (several minutes; not part of make test)
test-calibration: setup
	HANDMOTION_CALIBRATION_SEEDS=true $(R) -e 'testthat::test_local(".", filter = "calibration")'

test-python:
	cd inst/python && $(PY) -m pytest -q tests

## R CMD build + R CMD check --no-manual, failing on errors or warnings
check: setup
	bash tools/check.sh

## The documentation site (pkgdown) into site/, then opened in headless chromium
site: setup
	bash tools/site.sh

## Benchmarks (bench/README.md): figures and ratios printed and appended to bench/results/*.csv
bench: setup
	bash tools/bench.sh

## The same benchmarks at small sizes (seconds each); CI runs these so a broken benchmark fails CI
bench-quick: setup
	BENCH_QUICK=1 bash tools/bench.sh

docs:
	$(R) -e 'roxygen2::roxygenise()'

clean:
	rm -rf handmotion.Rcheck handmotion_*.tar.gz $(OUT) src/*.o src/*.so
