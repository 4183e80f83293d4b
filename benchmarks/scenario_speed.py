"""Scenario speed: a 10-minute scenario of the real X22 program on the virtual clock.

Builds a scenario that toggles machine inputs (X bytes and bits) once a second for ten minutes
and checks an output at the end, runs it from a cold start the way `ladderworks-cli test`
does, and prints virtual time / wall time (the speed-up over real time). Prints figures;
asserts nothing.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file
from ladderworks.core.plc.parameters import PmcParameters
from ladderworks.core.plc.scenario import parse_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun

_ROOT = Path(__file__).resolve().parents[1]
X22 = next((base / "shared" / "real-programs" / "FANUC_STUDER_X22_P036.txt"
            for base in (_ROOT.parent, _ROOT.parent.parent)
            if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
MINUTES = 10


def ten_minutes() -> str:
    """SET lines once a second for MINUTES minutes, then a WAITFOR that cannot fail quickly."""
    lines = ["PMC SIGNAL DATA", f"REMARK,{MINUTES} minutes of X22 inputs"]
    for second in range(MINUTES * 60):
        lines.append(f"SET,{0 if second == 0 else 1000},X8.4,{second % 2},,"
                     f"X10,{second * 37 % 256},BYTE")
    lines.append("EXPECT,1000,X8.4,1")  # the end of the tenth minute
    return "\n".join(lines) + "\n"


def main() -> int:
    """Print the speed-up of the 10-minute scenario."""
    if not X22.exists():
        print(f"{X22} is missing")
        return 1
    parsed = parse_file(X22)
    compiled = compile_program(parsed.program)
    assert compiled.binary is not None, compiled.diagnostics[:3]
    plc = PlcRun()
    plc.set_parameters(PmcParameters())
    assert plc.load(compiled.binary, parsed.program) == []
    scenario = parse_scenario(ten_minutes(), "x22-10min", parsed.program.symbols)
    assert scenario.ok, scenario.error_texts()
    result = run_scenario(plc, scenario)
    assert plc.engine is not None
    print(f"X22 ({len(plc.engine.program.ops)} ops), {result.virtual_ms / 1000:.0f} s of "
          f"virtual time ({plc.engine.scan_count} scans of {plc.engine.period_ms} ms) in "
          f"{result.seconds:.1f} s: {result.virtual_ms / 1000 / result.seconds:.1f}x real time"
          f" ({'passed' if result.passed else 'failed'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
