"""Where the real FANUC programs are: `shared/real-programs` beside the repository."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def real_programs_dir() -> Path | None:
    """The repository root's parent's `shared/real-programs` (or the nearest ancestor's)."""
    for base in ROOT.parents:
        candidate = base / "shared" / "real-programs"
        if candidate.is_dir():
            return candidate
    return None


WHOLE = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036", "FANUC_STUDER_S41_F034")


def real_bytes(name: str) -> bytes:
    """The bytes of a real program (a fragment wrapped in `%@3` ... `%`); skips without them."""
    folder = real_programs_dir()
    if folder is None or not (folder / f"{name}.txt").exists():
        pytest.skip("../shared/real-programs is not here")
    data = (folder / f"{name}.txt").read_bytes()
    return b"%@3\n" + data + b"%\n" if "_FRAG_" in name else data


def fragment_names() -> list[str]:
    """The fragment files' names (empty when the folder is missing)."""
    folder = real_programs_dir()
    return sorted(p.stem for p in folder.glob("FANUC_*_FRAG_*.txt")) if folder else []
