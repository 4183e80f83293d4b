"""Where the benchmarks find the real FANUC programs (../shared/real-programs), and a timer."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NAMES = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036", "FANUC_STUDER_S41_F034")


def real_folder() -> Path | None:
    """The shared real-programs folder beside the repository (None when it is not there)."""
    for base in ROOT.parents:
        if (base / "shared" / "real-programs").is_dir():
            return base / "shared" / "real-programs"
    return None


def real_file(name: str) -> Path | None:
    """The real program `name` (None when it is not there)."""
    folder = real_folder()
    path = folder / f"{name}.txt" if folder is not None else None
    return path if path is not None and path.exists() else None


def median_ms(fn: Callable[[], object], repeat: int) -> float:
    """Median ms of `repeat` calls of `fn`."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times)
