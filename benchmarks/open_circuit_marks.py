"""Prints the µs per network to find the open-circuit marks (`open_ends`) over each real FANUC
program (../shared/real-programs), and how many networks read from text got a mark (should be
none). Run from the repository root: python3 benchmarks/open_circuit_marks.py"""

from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import NAMES, real_folder  # noqa: E402

from ladderworks.core.il import parse_bytes  # noqa: E402
from ladderworks.core.ladder import open_ends  # noqa: E402
from ladderworks.core.ladder.convert import program_to_ladder  # noqa: E402


def main() -> int:
    """One line per program: networks, µs per network, networks marked."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    for name in NAMES:
        networks = program_to_ladder(parse_bytes((folder / f"{name}.txt").read_bytes())
                                     .program).networks
        start = time.perf_counter()
        marked = sum(1 for network in networks if open_ends(network))
        elapsed = time.perf_counter() - start
        print(f"{name:24s} {len(networks):6d} networks  "
              f"{1e6 * elapsed / len(networks):6.1f} µs/network  {marked} marked")
    return 0


if __name__ == "__main__":
    sys.exit(main())
