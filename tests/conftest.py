"""Shared test set-up: GUI tests run offscreen; Hypothesis profiles ("quick" here, "ci" in CI)."""

import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

# Imported before pytester's inline runs (tests/core/plc/test_pytest_plugin.py): a module they
# first import leaves sys.modules after each, and a process pool made later with a second copy
# of concurrent.futures.process cannot pickle its worker function.
import concurrent.futures.process  # noqa: F401

import tests.hypothesis_profiles  # noqa: F401  (registers and loads the profile)
