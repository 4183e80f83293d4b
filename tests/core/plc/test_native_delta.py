"""Delta DVP rows made native (native/delta_timers.py, delta_words.py) equal their Python
implementations exactly, as test_native_functions.py proves the others (its helpers): a small
program of each row on a Python and a native engine, fast and monitored, operand bytes and
inputs drawn by hypothesis before every scan; after every scan all memory, the call sites'
states and the power flow are equal and no op calls back. The timers run over many scans of
several periods, their T values now and then written too, and once with the skipper."""

from __future__ import annotations

import random
from functools import cache

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.il import parse_file
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.test_native_functions import (
    DATA,
    _byte,
    _run,
    _scans,
)
from tests.core.plc.test_native_functions import (
    disk_cache_in_tmp as disk_cache_in_tmp,  # the autouse fixture: the disk cache in tmp
)
from tests.hypothesis_profiles import examples
from tests.real_programs import real_programs_dir

_T = DEVICES.word("T0")[0]


@cache
def _delta(body: str) -> BinaryProgram:
    """The program of Delta text `body` (compiled once: hypothesis runs it many times)."""
    result = parse_bytes((body + "END\n").encode("ascii"), "delta")
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.message() for d in compiled.diagnostics][:3]
    return decode(compiled.binary)

# TMR: a D preset (any value), constants, a 10 ms timer (M1028 on X3), the 1 ms one, a 32-bit
# C200 preset, and a subroutine's timer run twice a scan (counted once)
TIMERS = ("LD X0\nTMR T0 D0\nLD X1\nTMR T1 K5\nLD X3\nOUT M1028\nLD X2\nTMR T64 K20\n"
          "LD X4\nTMR T127 K50\nLD X5\nTMR T2 C200\nLD X6\nCALL P1\nLD X7\nCALL P1\n"
          "LD X10\nRST T1\nLD X11\nRST C0\nLD X12\nRST D3\nLD X13\nRST C200\nFEND\n"
          "P1\nLD X14\nTMR T3 K4\nOUT Y0\nSRET\n")
# CNT: D and constant presets, a 32-bit C200 preset; DCNT up/down (M1200 on X3)
COUNTERS = ("LD X0\nCNT C0 D0\nLD X1\nCNT C1 K3\nLD X2\nCNT C2 C201\nLD X3\nOUT M1200\n"
            "LD X3\nOUT M1201\nLD X4\nDCNT C200 D2\nLD X5\nDCNT C201 K-2\nLD X6\nRST C1\n"
            "LD X7\nRST C200\nLD X10\nCNT C1 K32767\n"
            # high-speed counters (their X inputs): one input, reset, start; U/D; A/B phases
            "LD X11\nOUT M1235\nLD X10\nDCNT C235 K5\nLD X11\nDCNT C241 D4\n"
            "LD X12\nDCNT C244 K-3\nLD X13\nDCNT C246 K2\nLD X14\nDCNT C247 D6\n"
            "LD X15\nDCNT C251 K1\nLD X16\nDCNT C254 K0\nLD X17\nDCNT C250 C201\n")

_timed = st.lists(st.tuples(st.lists(_byte, min_size=DATA, max_size=DATA),
                            st.integers(0, 255), st.integers(0, 255), st.booleans()),
                  min_size=1, max_size=30)


def _pair(binary: BinaryProgram, monitored: bool, period: int, every_scan: bool = True,
          callbacks: bool = False) -> tuple[ScanEngine, ScanEngine]:
    """A Python and a native engine (`callbacks`: some ops may call back)."""
    python = ScanEngine(binary, monitored=monitored, period_ms=period)
    native = ScanEngine(binary, monitored=monitored, period_ms=period, backend="native")
    assert native.backend_used == "native", native.backend_reason
    assert callbacks or native._current.callbacks == [], native._current.callbacks
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


def _run_timed(program: str, monitored: bool, period: int, scans: list) -> None:
    python, native = _pair(_delta(program), monitored, period)
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
        program: str, monitored: bool, scans: list, period: int) -> None:
    _run_timed(TIMERS if program == "timers" else COUNTERS, monitored, period, scans)


def test_a_running_tmr_is_skipped_natively_as_python_runs_it() -> None:
    """The native skipper moves TMR's "ms" and "at" on (time values) as every scan would."""
    binary = _delta("LD X0\nTMR T0 K30\nLD X1\nTMR T64 K25\nLD T0\nOUT Y0\n")
    python, native = _pair(binary, False, 8, every_scan=False)
    for low, ms in ((1, 500), (3, 2000), (0, 300), (2, 4000)):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = low
            engine.step(ms)
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
    assert native.skipped > 0


# each row's lines (one input each); packed into programs of up to 16 below
ROWS: dict[str, tuple[str, ...]] = {
    "RST": ("RST T0", "RST C0", "RST C200", "RST D20", "RST T5"),
    # word logic (16 and 32 bits: C200 is 32-bit, C0 16-bit in a D form)
    "WAND": ("WAND D0 D1 D20", "WAND K-1 C200 D21", "WAND D2 H0F0F C201"),
    "WOR": ("WOR D0 D1 D20", "WOR K-32768 C200 D21", "WOR D2 K5 C201"),
    "WXOR": ("WXOR D0 D1 D20", "WXOR K-1 C200 D21", "WXOR D2 D2 C201"),
    "DAND": ("DAND D0 D2 D20", "DAND K-1 C200 D22", "DAND D4 K65535 C0"),
    "DOR": ("DOR D0 D2 D20", "DOR K-2147483648 C200 D22", "DOR D4 D6 C201"),
    "DXOR": ("DXOR D0 D2 D20", "DXOR K-1 C200 D22", "DXOR D4 D4 C0"),
    "NEG": ("NEG D0", "NEG C200", "NEG D1", "NEG D2"),
    "DNEG": ("DNEG D0", "DNEG C200", "DNEG C0", "DNEG D2"),
    "CML": ("CML D0 D20", "CML C200 D21", "CML K5 C201"),
    "DCML": ("DCML D0 D20", "DCML C200 D22", "DCML K-1 C0"),
    "ABS": ("ABS D0", "ABS C200", "ABS D1", "ABS D2"),
    "DABS": ("DABS D0", "DABS C200", "DABS C0", "DABS D2"),
    "SWAP": ("SWAP D0", "SWAP C200", "SWAP D1"),
    "DSWAP": ("DSWAP D0", "DSWAP C200", "DSWAP C0"),
    # rotations: a count from data (mostly out of range: the operation error) or constants
    "ROR": ("ROR D0 D1", "ROR D2 K1", "ROR D3 K16", "ROR C200 K5"),
    "ROL": ("ROL D0 D1", "ROL D2 K1", "ROL D3 K16", "ROL C200 K5"),
    "DROR": ("DROR D0 D1", "DROR D2 K1", "DROR D4 K32", "DROR C200 K7", "DROR C0 K3"),
    "DROL": ("DROL D0 D1", "DROL D2 K1", "DROL D4 K32", "DROL C200 K7", "DROL C0 K3"),
    "RCR": ("RCR D0 D1", "RCR D2 K1", "RCR D3 K16", "RCR C200 K5"),
    "RCL": ("RCL D0 D1", "RCL D2 K1", "RCL D3 K16", "RCL C200 K5"),
    "DRCR": ("DRCR D0 D1", "DRCR D2 K1", "DRCR D4 K32", "DRCR C200 K9", "DRCR C0 K2"),
    "DRCL": ("DRCL D0 D1", "DRCL D2 K1", "DRCL D4 K32", "DRCL C200 K9"),
    # bits of words
    "BON": ("BON D0 M0 D1", "BON D2 M1 K15", "BON C200 Y0 K3",
                  "BON D4 M3 K0"),
    "DBON": ("DBON D0 M0 D1", "DBON D2 M1 K31", "DBON C200 Y0 K20",
                   "DBON C0 M3 K15"),
    "BSET": ("BSET D0 D1", "BSET D2 K15", "BSET C200 K3"),
    "BRST": ("BRST D0 D1", "BRST D2 K15", "BRST C200 K3"),
    "DBSET": ("DBSET D0 D1", "DBSET D2 K31", "DBSET C200 K20", "DBSET C0 K5"),
    "DBRST": ("DBRST D0 D1", "DBRST D2 K31", "DBRST C200 K20"),
    # Gray code and BCD
    "GRY": ("GRY D0 D20", "GRY C200 D21", "GRY K1234 D22", "GRY K-1 D23"),
    "GBIN": ("GBIN D0 D20", "GBIN C200 D21", "GBIN K1234 D22", "GBIN D1 C201"),
    "DGRY": ("DGRY D0 D20", "DGRY C200 D22", "DGRY K2147483647 D24", "DGRY D2 C0"),
    "DGBIN": ("DGBIN D0 D20", "DGBIN C200 D22", "DGBIN K-5 D24", "DGBIN D2 C0"),
    "BCD": ("BCD D0 D20", "BCD C200 D21", "BCD K9999 D22", "BCD K10000 D23",
                  "BCD K0 D24", "BCD D1 C201"),
    "BIN": ("BIN D0 D20", "BIN C200 D21", "BIN H9999 D22", "BIN H9A D23", "BIN D1 C201"),
    "DBCD": ("DBCD D0 D20", "DBCD C200 D22", "DBCD K99999999 D24",
                   "DBCD K100000000 D26", "DBCD D2 C0"),
    "DBIN": ("DBIN D0 D20", "DBIN C200 D22", "DBIN H99999999 D24", "DBIN D2 C0"),
    # blocks of words and bits (counts are constants: a count in a register calls back)
    "ZRST": ("ZRST M0 M20", "ZRST D20 D25", "ZRST T0 T3", "ZRST C0 C2", "ZRST C199 C201",
             "ZRST Y0 Y7", "ZRST D30 D28", "ZRST S0 S9", "ZRST M3 M1500"),
    "BMOV": ("BMOV D0 D20 K4", "BMOV D0 D2 K5", "BMOV D4 D1 K5", "BMOV C200 D30 K2"),
    "FMOV": ("FMOV D0 D20 K3", "FMOV K-5 D30 K2", "FMOV C200 D40 K2"),
    "DFMOV": ("DFMOV D0 D20 K3", "DFMOV K-7 C200 K2", "DFMOV C200 D30 K2"),
    "XCH": ("XCH D0 D1", "XCH C200 D2", "XCH D3 D3"),
    "DXCH": ("DXCH D0 D2", "DXCH C200 D4", "DXCH C0 D6"),
    "SFTR": ("SFTR X0 M0 K16 K4", "SFTR M100 M20 K8 K8", "SFTR M0 Y0 K8 K3"),
    "SFTL": ("SFTL X0 M0 K16 K4", "SFTL M100 M20 K8 K8", "SFTL M0 Y0 K8 K3"),
    "WSFR": ("WSFR D0 D20 K6 K2", "WSFR K-3 D30 K4 K1", "WSFR D2 D0 K5 K5"),
    "WSFL": ("WSFL D0 D20 K6 K2", "WSFL K-3 D30 K4 K1", "WSFL D2 D0 K5 K5"),
    "DECO": ("DECO D0 M0 K3", "DECO D1 D20 K4", "DECO C200 Y0 K2", "DECO D2 M10 K8"),
    "ENCO": ("ENCO D0 D20 K4", "ENCO M0 D21 K3", "ENCO X0 D22 K3", "ENCO D1 D23 K1"),
    "ALT": ("ALT M0", "ALT Y0"),
    "SUM": ("SUM D0 D20", "SUM C200 D21", "SUM K0 D22"),
    "DSUM": ("DSUM D0 D20", "DSUM C200 D22", "DSUM D2 C0"),
    "MEAN": ("MEAN D0 D20 K3", "MEAN C199 D21 K3", "MEAN D0 D22 K1", "MEAN K-7 D23 K4"),
    "DMEAN": ("DMEAN D0 D20 K3", "DMEAN C200 D22 K2"),
}
_PLAIN = ("RST", "BSET", "BRST", "DBSET", "DBRST", "BOUT", "DBOUT")  # no pulse form


# floating point: the singles every float row also reads (D30 ...): infinities, a
# signalling and a quiet NaN, -0, the smallest denormal, the largest single, 1.0
SINGLES = "".join(f"LD M1000\nDMOV H{bits} D{30 + 2 * k}\n" for k, bits in enumerate((
    "7F800000", "FF800000", "7F800001", "FFC00123", "80000000", "00000001", "7F7FFFFF",
    "3F800000")))
FLOATS: dict[str, tuple[str, ...]] = {
    "DECMP": ("DECMP D0 D2 M0", "DECMP D30 D32 M10", "DECMP K5 D4 M20", "DECMP D34 D34 M30",
              "DECMP D36 K0 Y0", "DECMP D38 D40 M40"),
    "DEZCP": ("DEZCP D0 D2 D4 M0", "DEZCP K-5 K5 D30 M10", "DEZCP D32 D30 D6 M20",
              "DEZCP D34 D36 D38 M30", "DEZCP D40 D42 D44 M40"),
    "FLT": ("FLT D0 D20", "FLT C200 D22", "FLT K-32768 D24", "FLT D1 C0"),
    "INT": ("INT D0 D20", "INT D30 D21", "INT D32 D22", "INT D34 D23", "INT D36 D24",
            "INT D42 D25", "INT D44 D26", "INT K-7 D27", "INT D2 C201", "INT K-32769 D28",
            "INT K32768 D29", "INT K32767 D52"),
    "DINT": ("DINT D0 D20", "DINT D30 D22", "DINT D34 D24", "DINT D42 D26", "DINT D44 D28",
             "DINT C200 D50", "DINT D2 C0"),
    "DFLT": ("DFLT D0 D20", "DFLT C200 D22", "DFLT K2147483647 D24", "DFLT K16777217 D26",
             "DFLT D2 C201"),
    # DEADD ... DEDIV: a constant operand, or one pair twice (two pairs call back)
    "DEADD": ("DEADD K5 D0 D20", "DEADD D30 K-1 D22", "DEADD D32 K0 D24", "DEADD D34 D34 D26",
              "DEADD D42 K2147483647 D28", "DEADD K-2147483648 D44 D50", "DEADD C200 K1 D52",
              "DEADD D38 D38 D54", "DEADD D2 D2 C201"),
    "DESUB": ("DESUB K5 D0 D20", "DESUB D30 K-1 D22", "DESUB D32 D32 D24", "DESUB D40 K0 D26",
              "DESUB D36 K1 D28", "DESUB D42 D42 D50", "DESUB D30 D30 D56"),
    "DEMUL": ("DEMUL K5 D0 D20", "DEMUL D30 K0 D22", "DEMUL D32 K-1 D24", "DEMUL D44 D44 D26",
              "DEMUL D40 D40 D28", "DEMUL D42 K1000 D50", "DEMUL D2 K3 D52"),
    "DEDIV": ("DEDIV K5 D0 D20", "DEDIV D30 D30 D22", "DEDIV D32 K0 D24", "DEDIV D36 K3 D26",
              "DEDIV D42 D42 D28", "DEDIV D40 K-7 D50", "DEDIV K1 D34 D52", "DEDIV D2 K10 D54"),
    "DESQR": ("DESQR D0 D20", "DESQR D30 D22", "DESQR D32 D24", "DESQR D34 D26",
              "DESQR D38 D28", "DESQR D40 D50", "DESQR K2 D52", "DESQR K-1 D54", "DESQR D44 D56",
              "DESQR D42 D58", "DESQR C200 C201"),
    "DRAD": ("DRAD D0 D20", "DRAD D30 D22", "DRAD D34 D24", "DRAD D42 D26", "DRAD K180 D28",
             "DRAD D40 D50", "DRAD C200 C201"),
    "DDEG": ("DDEG D0 D20", "DDEG D32 D22", "DDEG D36 D24", "DDEG D42 D26", "DDEG K3 D28",
             "DDEG D40 D50", "DDEG D38 D52"),
    "DEMOV": ("DEMOV D0 D20", "DEMOV D30 D22", "DEMOV D32 D24", "DEMOV D34 D26",
              "DEMOV D36 D28", "DEMOV K-7 D50", "DEMOV D38 D52", "DEMOV C200 D54",
              "DEMOV D40 D56", "DEMOV D42 D58", "DEMOV D44 D60"),
}
EXTRA: dict[str, tuple[str, ...]] = {
    "BOUT": ("BOUT D0 K3", "BOUT D1 D2", "BOUT C200 K15"),
    "DBOUT": ("DBOUT D0 K20", "DBOUT C200 D2", "DBOUT C0 K3"),
    "SCAL": ("SCAL D0 K500 K-3 D20", "SCAL D1 D2 D3 D21", "SCAL C200 K1000 K0 D22"),
    "SCLP": ("SCLP D0 D4 D20", "SCLP D1 D8 D21", "SCLP K5 D40 D22"),
    "SQR": ("SQR D0 D20", "SQR C200 D21", "SQR K0 D22", "SQR K32767 D23", "SQR K16 D24",
            "SQR K15 D25"),
    "DSQR": ("DSQR D0 D20", "DSQR C200 D22", "DSQR K2147483647 D24", "DSQR D2 C0",
             "DSQR K1073676289 D26", "DSQR K1073676288 D28"),
    "SMOV": ("SMOV D0 K4 K2 D20 K3", "SMOV K1234 K4 K4 D21 K4", "SMOV D1 K2 K1 D2 K1",
             "SMOV C200 K3 K2 D3 K2"),
    # special modules' CRs (TO writes them, FROM reads them; a CR past #99: the error)
    "TO": ("TO K0 K1 K0 K1", "TO K0 K5 D0 K4", "TO K7 K97 D1 K4"),
    "FROM": ("FROM K0 K5 D20 K2", "FROM K7 K98 D22 K3", "FROM K0 K1 D25 K1"),
    "DTO": ("DTO K0 K20 D0 K2", "DTO K2 K97 D2 K2", "DTO K3 K0 K-5 K1"),
    "DFROM": ("DFROM K0 K20 D30 K2", "DFROM K2 K97 D34 K2", "DFROM K3 K0 C200 K1"),
    # FIFO: SFWR's place found at run time (a count from the data: before D, past the end)
    "SFWR": ("SFWR D0 D20 K5", "SFWR D1 D2 K4", "SFWR K-3 D10 K300", "SFWR D3 D4999 K3",
             "SFWR D4 D5000 K3", "SFWR D5 T3 K3", "SFWR D6 C198 K4"),
    "SFRD": ("SFRD D20 D40 K5", "SFRD D0 D41 K4", "SFRD D8 D42 K2", "SFRD D9999 D43 K3"),
}
# NOP/WDT, shown-only rows (PID, a contact LD&), a step ladder's SET/OUT Sn, CJP and CALLP,
# nested FOR/NEXT
OTHERS = ("LD X0\nNOP\nOUT Y0\nLD X1\nWDT\nOUT Y1\nLD X2\nPID D0 D1 D2 D3\n"
          "LD& D0 D1\nOUT Y2\nLD X3\nAND& D2 D3\nOUT Y3\nLD X4\nOR& D4 D5\nOUT Y4\n"
          "LD X5\nCJP P1\nLD M1000\nINC D20\nP1\nLD X6\nCALLP P2\n"
          "LD M1002\nSET S0\nSTL S0\nOUT Y5\nLD X7\nSET S20\nSTL S20\nOUT Y6\n"
          "LD X10\nSET S21\nSTL S21\nLD X11\nOUT S0\nRET\n"
          "FOR K3\nLD X12\nINC D22\nFOR K2\nLD X13\nINC D23\nNEXT\nNEXT\n"
          "FEND\nP2\nLD M1000\nINC D21\n"
          "SRET\n")
_SIGNS = ("=", ">", "<", "<>", "<=", ">=")
FLOAT_CONTACTS = SINGLES + "".join(
    f"LD X{k}\nFAND{t} D{2 * k} D{30 + 2 * k}\nOUT Y{k}\n"
    f"FLD{t} D{2 * k} K{k - 2}\nOUT M{k}\n"
    f"LD X{k}\nFOR{t} D34 D{2 * k}\nOUT M1{k}\n"
    f"LD X{k}\nFLD{t} D{30 + 2 * k} D{32 + 2 * k}\nORB\nOUT M2{k}\n"
    f"FLD{t} D{2 * k} D{2 * k}\nOUT M3{k}\n" for k, t in enumerate(_SIGNS))


_INPUTS = [f"X{k}" for k in range(8)] + [f"X1{k}" for k in range(8)]


def _gated(*lines: str) -> str:
    """Each instruction under an input of its own: X0-X17, then their inverses (LDI)."""
    return "".join(f"{'LD' if k < 16 else 'LDI'} {_INPUTS[k % 16]}\n{line}\n"
                   for k, line in enumerate(lines))


def _packed(rows: dict[str, tuple[str, ...]], pulse: bool, prefix: str = "") -> dict[str, str]:
    """Programs of up to 32 gated lines (`_gated`), the rows in order (`pulse`: their P forms,
    for the rows that have one), by the names of the rows they hold; `prefix` before each."""
    programs: dict[str, str] = {}
    names: list[str] = []
    lines: list[str] = []
    for name, own in [*rows.items(), ("", ())]:
        if pulse and name in _PLAIN:
            continue
        if names and (not name or len(lines) + len(own) > 32):
            programs[",".join(names) + ("/P" if pulse else "")] = prefix + _gated(*lines)
            names, lines = [], []
        names.append(name)
        lines += [line.replace(f"{name} ", f"{name}P ", 1) if pulse else line for line in own]
    return programs


PROGRAMS = {**_packed(ROWS, False), **_packed(ROWS, True), **_packed(FLOATS, False, SINGLES),
            **_packed(FLOATS, True, SINGLES), "F contacts": FLOAT_CONTACTS,
            **_packed(EXTRA, False), **_packed(EXTRA, True), "others": OTHERS}


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("rows", sorted(PROGRAMS))
@settings(max_examples=examples(10), deadline=None)
@given(scans=_scans)
def test_delta_word_rows_run_natively_as_in_python(rows: str, monitored: bool, scans: list
                                                   ) -> None:
    _run(_delta(PROGRAMS[rows]), monitored, scans, counters=True)


REAL = ("METALURGICA_c91257f_atual_no_programa", "NIRMALKUMAR_timer1", "NIRMALKUMAR_counter1",
        "NIRMALKUMAR_booleangates", "NIRMALKUMAR_bcdbin", "NIRMALKUMAR_compliment")


@pytest.mark.parametrize("name", REAL)
def test_real_delta_programs_run_natively_as_in_python(name: str) -> None:
    """Real WPLSoft projects using these rows (read from ../shared): 200 scans with inputs
    changing every 7, fast and monitored, then the native skipper over 30 s."""
    path = real_programs_dir() / "delta" / f"{name}.dvp"
    compiled = compile_program(parse_file(path).program)
    assert compiled.binary is not None
    binary = decode(compiled.binary)
    rng = random.Random(name)
    for monitored in (False, True):
        python, native = _pair(binary, monitored, 10, callbacks=True)
        for k in range(200):
            if k % 7 == 0:
                inputs = bytes(rng.randrange(256) for _ in range(4))
                for engine in (python, native):
                    engine.memory.areas[Area.X][0:4] = inputs
            python.scan()
            native.scan()
            assert native.memory.areas == python.memory.areas, k
            assert native.call_states() == python.call_states(), k
            if monitored:
                assert native.power_flow == python.power_flow
    python, native = _pair(binary, False, 10, every_scan=False, callbacks=True)
    for _ in range(10):
        inputs, ms = bytes(rng.randrange(256) for _ in range(4)), rng.choice((50, 700, 3000))
        for engine in (python, native):
            engine.memory.areas[Area.X][0:4] = inputs
            engine.step(ms)
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()


@pytest.mark.parametrize("bits", ["7F800000", "FF800000", "7FC00000"])
def test_int_of_an_infinity_or_a_nan_is_an_operation_error(bits: str) -> None:
    """As any value out of range (it raised OverflowError in Python before): D kept."""
    for backend in ("python", "native"):
        engine = ScanEngine(_delta(f"LD M1000\nDMOV H{bits} D0\nMOV K7 D2\nLD X0\nINT D0 D2\n"
                                   f"DINT D0 D4\n"), backend=backend)
        engine.memory.areas[Area.X][0] = 1
        engine.scan()
        assert engine.memory.bit(DEVICES.bit("M1067")) == 1
        assert engine.memory.read(DEVICES.word("D2")[0], 2) == 7


def test_the_delta_states_go_through_the_dicts_both_ways() -> None:
    """TMR's running/ms, a high-speed counter's x/y and NEXT's left written into the dicts
    (export) and read back into another engine's state words (import) go on as in Python."""
    binary = _delta("LD X0\nTMR T0 K30\nLD X1\nDCNT C246 K5\nLD X2\nDCNT C251 K3\n"
                    "FOR K3\nLD X3\nINC D20\nNEXT\n")
    rng = random.Random(11)
    python, native = _pair(binary, False, 8)
    for k in range(60):
        inputs = rng.randrange(256) | 1  # the timer runs throughout
        if k == 30:  # the states through their dicts into fresh engines
            state = native.export_state()
            assert state == python.export_state()
            python, native = _pair(binary, False, 8)
            python.import_state(state)
            native.import_state(state)
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = inputs
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
