"""Prints ms to parse each real FANUC program (../shared/real-programs), µs per line, and the
ms to write it back (faithful Save). Run from the repository root: python3 benchmarks/parse_real.py

`--compare REF` times the parse of this checkout's `ladderworks` and of git commit REF's, side
by side in one run: one process per tree, each program parsed by the old then the new, in
turn, `--rounds` times; the fastest and the median are printed with the change (the fastest is
the one a loaded machine disturbs least).
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))

from real_files import NAMES, median_ms, real_folder  # noqa: E402


def main() -> int:
    """One line per program: lines, parse ms, µs/line, save ms, diagnostics."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    sys.path.insert(0, str(ROOT))
    from ladderworks.core.il import parse_bytes
    from ladderworks.core.il.printer import encode_program

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


def worker(tree: str) -> int:
    """Parse with the `ladderworks` of `tree` each program named on stdin; print its ms."""
    sys.path.insert(0, tree)
    from ladderworks.core.il import parse_bytes

    folder = real_folder()
    assert folder is not None
    files = {name: (folder / f"{name}.txt").read_bytes() for name in NAMES}
    for name in files:
        parse_bytes(files[name])  # imports and caches warmed
    print("ready", flush=True)
    for line in sys.stdin:
        data = files[line.strip()]
        print(median_ms(lambda data=data: parse_bytes(data), 1), flush=True)
    return 0


def compare(ref: str, rounds: int) -> int:
    """This checkout's parse against commit `ref`'s: two processes, one per tree, parse each
    program in turn (old, new, old, new, ...) `rounds` times."""
    if real_folder() is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as old:
        archive = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "ladderworks"],
                                 check=True, capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", old], input=archive, check=True)
        workers = {label: subprocess.Popen(
            [sys.executable, __file__, "--worker", tree], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, text=True) for label, tree in (("old", old),
                                                                  ("new", str(ROOT)))}
        for process in workers.values():
            assert process.stdout is not None and process.stdout.readline() == "ready\n"
        found: dict[str, dict[str, list[float]]] = {k: {n: [] for n in NAMES} for k in workers}
        for _ in range(rounds):
            for name in NAMES:
                for label, process in workers.items():
                    assert process.stdin is not None and process.stdout is not None
                    process.stdin.write(name + "\n")
                    process.stdin.flush()
                    found[label][name].append(float(process.stdout.readline()))
        for process in workers.values():
            assert process.stdin is not None
            process.stdin.close()
            process.wait()
    print(f"parse ms, {rounds} parses each, old and new in turn: {ref} -> this checkout")
    for name in NAMES:
        for what, pick in (("fastest", min), ("median", statistics.median)):
            old_ms, new_ms = pick(found["old"][name]), pick(found["new"][name])
            print(f"{name:24s} {what:7s} old {old_ms:7.1f}  new {new_ms:7.1f}  "
                  f"{100 * (new_ms - old_ms) / old_ms:+5.1f} %")
    return 0


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--compare", metavar="REF", help="a git commit to compare with")
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--worker", metavar="TREE", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        sys.exit(worker(options.worker))
    sys.exit(compare(options.compare, options.rounds) if options.compare else main())
