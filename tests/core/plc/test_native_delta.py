"""Delta DVP rows made native (native/delta_timers.py, delta_words.py) equal their Python
implementations exactly, as test_native_functions.py proves the others (its helpers): a small
program of each row on a Python and a native engine, fast and monitored, operand bytes and
inputs drawn by hypothesis before every scan; after every scan all memory, the call sites'
states and the power flow are equal and no op calls back. The timers run over many scans of
several periods, their T values now and then written too, and once with the skipper."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.test_native_functions import (
    DATA,
    _byte,
    _delta,
    _gated,
    _run,
    _scans,
)
from tests.core.plc.test_native_functions import (
    disk_cache_in_tmp as disk_cache_in_tmp,  # the autouse fixture: the disk cache in tmp
)
from tests.hypothesis_profiles import examples

_T = DEVICES.word("T0")[0]

# TMR: a D preset (any value), constants, a 10 ms timer (M1028 on X3), the 1 ms one, a 32-bit
# C200 preset, and a subroutine's timer run twice a scan (counted once)
TIMERS = ("LD X0\nTMR T0 D0\nLD X1\nTMR T1 K5\nLD X3\nOUT M1028\nLD X2\nTMR T64 K20\n"
          "LD X4\nTMR T127 K50\nLD X5\nTMR T2 C200\nLD X6\nCALL P1\nLD X7\nCALL P1\n"
          "LD X10\nRST T1\nLD X11\nRST C0\nLD X12\nRST D3\nLD X13\nRST C200\nFEND\n"
          "P1\nLD X14\nTMR T3 K4\nOUT Y0\nSRET\n")
# CNT: D and constant presets, a 32-bit C200 preset; DCNT up/down (M1200 on X3)
COUNTERS = ("LD X0\nCNT C0 D0\nLD X1\nCNT C1 K3\nLD X2\nCNT C2 C201\nLD X3\nOUT M1200\n"
            "LD X3\nOUT M1201\nLD X4\nDCNT C200 D2\nLD X5\nDCNT C201 K-2\nLD X6\nRST C1\n"
            "LD X7\nRST C200\nLD X10\nCNT C1 K32767\n")

_timed = st.lists(st.tuples(st.lists(_byte, min_size=DATA, max_size=DATA),
                            st.integers(0, 255), st.integers(0, 255), st.booleans()),
                  min_size=1, max_size=40)


def _pair(binary: BinaryProgram, monitored: bool, period: int,
          every_scan: bool = True) -> tuple[ScanEngine, ScanEngine]:
    python = ScanEngine(binary, monitored=monitored, period_ms=period)
    native = ScanEngine(binary, monitored=monitored, period_ms=period, backend="native")
    assert native.backend_used == "native", native.backend_reason
    assert native._current.callbacks == [], native._current.callbacks
    python.every_scan, native.every_scan = True, every_scan
    return python, native


def _load(engine: ScanEngine, data: list[int], low: int, high: int, timers: bool) -> None:
    memory = engine.memory.areas
    memory[Area.D][0:DATA] = bytes(data)
    memory[Area.C][800:808] = bytes(data[:8])
    if timers:  # T0-T3 and C0-C2 from the data too
        memory[_T.area][_T.byte:_T.byte + 8] = bytes(data[8:16])
        memory[Area.C][0:6] = bytes(data[16:22])
    memory[Area.X][0], memory[Area.X][1] = low, high


def _run_timed(program: str, tmp: Path, monitored: bool, period: int, scans: list) -> None:
    python, native = _pair(_delta(program, tmp), monitored, period)
    for data, low, high, timers in scans:
        for engine in (python, native):
            _load(engine, data, low, high, timers)
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        assert native._ctx.wake_ms == python._ctx.wake_ms
        if monitored:
            assert native.power_flow == python.power_flow


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("program", ["timers", "counters"])
@settings(max_examples=examples(12), deadline=None)
@given(scans=_timed, period=st.sampled_from((1, 8, 30, 130)))
def test_delta_timers_and_counters_run_natively_as_in_python(
        program: str, monitored: bool, scans: list, period: int,
        tmp_path_factory: pytest.TempPathFactory) -> None:
    text = TIMERS if program == "timers" else COUNTERS
    _run_timed(text, tmp_path_factory.mktemp("timers"), monitored, period, scans)


def test_a_running_tmr_is_skipped_natively_as_python_runs_it(tmp_path: Path) -> None:
    """The native skipper moves TMR's "ms" and "at" on (time values) as every scan would."""
    binary = _delta("LD X0\nTMR T0 K30\nLD X1\nTMR T64 K25\nLD T0\nOUT Y0\n", tmp_path)
    python, native = _pair(binary, False, 8, every_scan=False)
    for low, ms in ((1, 500), (3, 2000), (0, 300), (2, 4000)):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = low
            engine.step(ms)
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
    assert native.skipped > 0


ROWS = {
    "RST": _gated("RST T0", "RST C0", "RST C200", "RST D20", "RST T5"),
}


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(ROWS))
@settings(max_examples=examples(10), deadline=None)
@given(scans=_scans)
def test_a_delta_word_row_runs_natively_as_in_python(row: str, monitored: bool, scans: list,
                                                     tmp_path_factory: pytest.TempPathFactory
                                                     ) -> None:
    _run(_delta(ROWS[row], tmp_path_factory.mktemp("rows")), monitored, scans, counters=True)
