"""Tests on the public real programs in ../shared/real-programs (read in place, never copied)."""

from __future__ import annotations

from pathlib import Path

REAL_PROGRAMS = Path(__file__).resolve().parents[2].parent / "shared" / "real-programs"
PROGRAMS = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036", "FANUC_STUDER_S41_F034")


def real_program(name: str) -> Path:
    """The path of a real program by its name (without `.txt`)."""
    path = REAL_PROGRAMS / f"{name}.txt"
    assert path.exists(), f"{path} is missing: CI has ../shared beside the project"
    return path
