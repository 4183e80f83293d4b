"""The WPLSoft `.dvp` projects in ../shared/real-programs/delta: what decodes (files,
instructions, comments, unknown codes, empty programs), how many open as a Program the engine
runs, and the ms to read one; run from the repository root."""

from __future__ import annotations

import os
import sys
from collections import Counter
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import median_ms, real_folder  # noqa: E402

from ladderworks.core.dialects.delta.dvp_file import read_or_diagnostic  # noqa: E402
from ladderworks.core.il.reading import parse_bytes  # noqa: E402


def main() -> int:
    """Read every project; print the figures."""
    folder = real_folder()
    if folder is None:
        print("../shared/real-programs is not there")
        return 1
    paths = sorted((folder / "delta").glob("*.dvp"))
    errors, empty, opened, instructions, comments = 0, 0, 0, 0, 0
    unknown: Counter[str] = Counter()
    refused: Counter[str] = Counter()
    for path in paths:
        data = path.read_bytes()
        project, diagnostic = read_or_diagnostic(data)
        if project is None:
            errors += 1
            print(f"{path.name}: {diagnostic and diagnostic.message()}")
            continue
        instructions += len(project.instructions)
        comments += len(project.comments)
        empty += not project.instructions
        unknown.update(each.mnemonic for each in project.instructions if not each.known)
        result = parse_bytes(data)
        if result.ok:
            opened += 1
        else:  # the first error the Delta reader gives the decoded list
            first = next(d for d in result.diagnostics if d.is_error)
            refused[first.code] += 1
    print(f"files {len(paths)}, decode errors {errors}, empty programs {empty}")
    print(f"instructions {instructions}, device comments {comments}, unknown codes {dict(unknown)}")
    print(f"open as a Program without error: {opened} of {len(paths)}; the others' first error:"
          f" {dict(refused)}")
    largest = max(paths, key=lambda p: p.stat().st_size)
    data = largest.read_bytes()
    read = median_ms(lambda: read_or_diagnostic(data), 20)
    program = median_ms(lambda: parse_bytes(data), 10)
    print(f"read {largest.name} ({len(data)} bytes): {read:.1f} ms; as a Program: {program:.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
