# LadderWorks: the two entry points of the README, and the helpers they use.
PYTHON ?= python3
PIP ?= $(PYTHON) -m pip

.PHONY: install run test lint bench translations

install:
	$(PIP) install --quiet --disable-pip-version-check -e '.[test]'

run: install
	$(PYTHON) -m ladderworks

test: install
	QT_QPA_PLATFORM=offscreen $(PYTHON) -m ruff check ladderworks tests benchmarks tools
	QT_QPA_PLATFORM=offscreen $(PYTHON) -m pytest -q

lint:
	$(PYTHON) -m ruff check ladderworks tests benchmarks tools

bench: install
	for script in benchmarks/*.py; do $(PYTHON) $$script || exit 1; done
