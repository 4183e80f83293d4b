# LadderWorks: the two entry points of the README, and the helpers they use. Each runs in the
# project-local .venv that tools/dev.py creates and keeps installed (make is optional:
# `python3 tools/dev.py run` does the same, e.g. `py tools\dev.py test` in PowerShell).
PYTHON ?= python3
DEV = $(PYTHON) tools/dev.py

.PHONY: run test lint bench product

run:
	$(DEV) run

test:
	$(DEV) test

lint:
	$(DEV) lint

bench:
	$(DEV) bench

# What .ci/run checks after the tests: the wheel, installed into a fresh environment.
product:
	$(DEV) product
