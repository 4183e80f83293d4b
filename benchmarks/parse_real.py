"""Prints ms to parse each real FANUC program (../shared/real-programs), µs per line, and the
ms to write it back (faithful Save). Run from the repository root: python3 benchmarks/parse_real.py
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import NAMES, median_ms, real_folder  # noqa: E402

from ladderworks.core.il import parse_bytes  # noqa: E402
from ladderworks.core.il.printer import encode_program  # noqa: E402


def main() -> int:
    """One line per program: lines, parse ms, µs/line, save ms, diagnostics."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    for name in NAMES:
        data = (folder / f"{name}.txt").read_bytes()
        lines = data.count(b"\n")
        result = parse_bytes(data)
        parse_ms = median_ms(lambda data=data: parse_bytes(data), 3)
        save_ms = median_ms(lambda r=result: encode_program(r.program), 3)
        print(f"{name:24s} {lines:6d} lines  parse {parse_ms:7.1f} ms "
              f"({1000 * parse_ms / lines:5.2f} µs/line)  save {save_ms:6.1f} ms  "
              f"{len(result.diagnostics)} diagnostics")
    return 0


if __name__ == "__main__":
    sys.exit(main())
