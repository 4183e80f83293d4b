"""Hypothesis profiles: "quick" locally (fewer examples), "ci" when the CI variable is true."""

from __future__ import annotations

import os

from hypothesis import settings

CI = os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")
PROFILE = os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if CI else "quick")
QUICK_SHARE = 5  # the quick profile runs a fifth of the CI examples

settings.register_profile("ci", max_examples=200, deadline=None, print_blob=True)
settings.register_profile("quick", max_examples=20, deadline=None)
settings.load_profile(PROFILE)


def examples(ci: int) -> int:
    """Examples for a test that needs `ci` in CI: all of them there, a fifth (>= 10) locally."""
    return ci if PROFILE == "ci" else max(10, ci // QUICK_SHARE)
