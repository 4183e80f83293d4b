"""Shared test set-up: GUI tests run offscreen; Hypothesis profiles ("quick" here, "ci" in CI)."""

import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import tests.hypothesis_profiles  # noqa: F401  (registers and loads the profile)
