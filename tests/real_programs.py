"""Where the real FANUC programs are: `shared/real-programs` beside the repository."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def real_programs_dir() -> Path:
    """The repository root's parent's `shared/real-programs` (or the nearest ancestor's); a test
    that needs it fails when it is missing (CI has ../shared beside the project)."""
    for base in ROOT.parents:
        candidate = base / "shared" / "real-programs"
        if candidate.is_dir():
            return candidate
    pytest.fail(f"shared/real-programs is missing beside {ROOT}: the real-program tests need it")


WHOLE = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036", "FANUC_STUDER_S41_F034")


def real_bytes(name: str) -> bytes:
    """The bytes of a real program (a fragment wrapped in `%@3` ... `%`); skips without them."""
    data = (real_programs_dir() / f"{name}.txt").read_bytes()
    return b"%@3\n" + data + b"%\n" if "_FRAG_" in name else data


def fragment_names() -> list[str]:
    """The fragment files' names."""
    return sorted(p.stem for p in real_programs_dir().glob("FANUC_*_FRAG_*.txt"))
