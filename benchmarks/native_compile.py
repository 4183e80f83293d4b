"""The native scan's cold compile of X22 and S41_F036 (shared/real-programs): seconds of CPU (the
process's: LLVM works on a thread of its own) and of wall time for a new engine with nothing
cached (the in-memory cache cleared, the disk cache off), until the engine can scan the whole
program natively; with the IR made in Python and LLVM's part (parse, passes, code
generation, linking), which overlap; the best of `--rounds`. `--compare-passes` alternates
the rounds between the IR passes on every function (as before) and on the units' functions
only (jit.CHUNK_PASSES), printing both. Prints figures; asserts nothing.

    python benchmarks/native_compile.py [--rounds N] [--compare-passes] [PROGRAM ...]

To compare two versions in one run, run it alternately with each tree on PYTHONPATH.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import jit

_ROOT = Path(__file__).resolve().parents[1]
SHARED = next((base / "shared" / "real-programs"
               for base in (_ROOT.parent, _ROOT.parent.parent, Path("/work"))
               if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
PROGRAMS = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036")


def load(name: str) -> BinaryProgram:
    result = compile_program(parse_file(SHARED / f"{name}.txt").program)
    assert result.binary is not None
    return decode(result.binary)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--compare-passes", action="store_true")
    parser.add_argument("programs", nargs="*", default=PROGRAMS)
    args = parser.parse_args()
    os.environ["LADDERWORKS_NATIVE_CACHE"] = "off"
    settings = (False, True) if args.compare_passes else (jit.CHUNK_PASSES,)
    for name in args.programs:
        binary = load(name)
        rounds: dict[bool, list[tuple[float, float, float, float]]] = {k: [] for k in settings}
        for _ in range(args.rounds):
            for chunk_passes in settings:
                jit.CHUNK_PASSES = chunk_passes
                jit.clear_cache()
                cpu, wall = time.process_time(), time.perf_counter()
                engine = ScanEngine(binary, backend="native")
                cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
                if engine.backend_reason:
                    print(f"{name}: the native scan cannot run: {engine.backend_reason}")
                    return 1
                compiled = engine._current.compiled
                rounds[chunk_passes].append((cpu, wall, compiled.ir_seconds,
                                             compiled.llvm_seconds))
        for chunk_passes, found in rounds.items():
            cpu, wall, ir, llvm = (min(r[k] for r in found) for k in range(4))
            which = " (passes on every function)" if chunk_passes else ""
            print(f"{name}: {len(binary.ops)} steps, cold compile {cpu:.2f} s CPU, {wall:.2f} s "
                  f"wall (IR {ir:.2f} s, LLVM {llvm:.2f} s; best of {args.rounds}){which}",
                  flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
