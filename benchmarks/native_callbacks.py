"""What the native scan still calls back into Python for, by dialect: every functional row of
each dialect's instruction table (the PMC's and the seed's, Delta, Fatek, S7) that the
simulator runs, as native code (core/plc/native: builtins.py, stateful.py, tables.py; the
structural rows, JMP/CALL/COM and the like, are the generator's own) or as a call-back into
its Python implementation; counted, with the call-backs' names. A native row may still call
back at a call site whose parameters the native code does not take (data past its area, an
unknown width). Then the call sites that call back in the real programs: the FANUC ones, each
Delta WPLSoft project (shared/real-programs/delta/*.dvp) and the Fatek WinProladder one
(fatek/*.pdw), each with its call-back rows by count, and the totals. Prints; asserts
nothing.

    python benchmarks/native_callbacks.py
"""

from __future__ import annotations

import collections
from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.compiler.checks import implementation_of
from ladderworks.core.il import parse_file
from ladderworks.core.instructions import FUNCTIONS, Flow, InstructionSpec, Kind
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions import load_all
from ladderworks.core.plc.native import builtins, stateful

_ROOT = Path(__file__).resolve().parents[1]
SHARED = next((base / "shared" / "real-programs"
               for base in (_ROOT.parent, _ROOT.parent.parent, Path("/work"))
               if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
PROGRAMS = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036")


def native(spec: InstructionSpec, registry: dict) -> bool | None:
    """True: native code; False: a call-back; None: not a simulated functional row."""
    if spec.kind is not Kind.FUNCTION or not spec.simulated:
        return None
    if spec.flow is not Flow.NONE:
        return True  # structure: the generator's code
    impl = implementation_of(spec, registry)
    if impl is None:
        return None
    return impl in builtins.EMITTERS or impl in builtins.EDGES or \
        stateful.kind(spec, impl) is not None


def main() -> int:
    registry = load_all()
    tables = [("PMC and seed", FUNCTIONS)]
    tables += [(dialect.name, dialect.rows) for dialect in dialects.every()
               if dialect.rows]
    for name, rows in tables:
        found = {spec.name: native(spec, registry) for spec in rows}
        done = sorted(k for k, v in found.items() if v)
        back = sorted(k for k, v in found.items() if v is False)
        print(f"{name}: {len(done) + len(back)} functional rows simulated, {len(done)} native, "
              f"{len(back)} call back into Python")
        if back:
            print("  call back: " + ", ".join(back))
    paths = [SHARED / f"{program}.txt" for program in PROGRAMS]
    paths += sorted((SHARED / "delta").glob("*.dvp")) + sorted((SHARED / "fatek").glob("*.pdw"))
    totals: dict[str, collections.Counter[str]] = {}
    for path in paths:
        if not path.exists():
            continue
        sites = callbacks(path)
        totals.setdefault(path.suffix, collections.Counter()).update(sites)
        print(f"{path.name}: {sum(sites.values())} call sites call back: " +
              (", ".join(f"{k} {v}" for k, v in sites.most_common()) or "none"))
    for suffix, sites in totals.items():
        print(f"all {suffix} programs: {sum(sites.values())} call sites call back: " +
              (", ".join(f"{k} {v}" for k, v in sites.most_common()) or "none"))
    return 0


def callbacks(path: Path) -> collections.Counter[str]:
    """The call sites of the program in `path` that call back, by row (its own reader)."""
    compiled = compile_program(parse_file(path).program)
    assert compiled.binary is not None, path
    engine = ScanEngine(decode(compiled.binary), backend="native")
    return collections.Counter(getattr(engine._current, "callbacks", []))


if __name__ == "__main__":
    raise SystemExit(main())
