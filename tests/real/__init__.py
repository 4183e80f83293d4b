"""Tests on the public real programs in ../shared/real-programs (read in place, never copied)."""

from __future__ import annotations

from pathlib import Path

from tests.real_programs import WHOLE, real_programs_dir

PROGRAMS = WHOLE


def real_program(name: str) -> Path:
    """The path of a real program by its name (without `.txt`)."""
    return real_programs_dir() / f"{name}.txt"
