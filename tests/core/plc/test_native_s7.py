"""The S7-1200 rows and the PMC's DCNV, DSCH, DSCHB and XMOV as native code equal their Python
implementations exactly: small programs of each row (typed operands at addresses, bits and
constants of every type; timer and counter instances) run on a Python engine and a native one,
fast and monitored, with the operand bytes and inputs drawn by hypothesis before every scan
(edge bytes weighted in: NaNs, infinities, denormals and the integer limits come from 00, FF,
7F, 80, 01); after every scan all memory, the call sites' states and W1 are equal and no op
calls back into Python (test_native_functions.py's helpers)."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, Op, SourcePosition, decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc import typed
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import disk_cache
from tests.core.plc.test_native_functions import DATA, _byte, _engines, _pmc, _run
from tests.core.plc.test_skipping import Driver, bytes_of, program_inputs
from tests.hypothesis_profiles import examples

VT = typed.ValueType
INTEGERS = (VT.INT, VT.DINT, VT.SINT, VT.USINT, VT.UINT, VT.UDINT, VT.TIME, VT.BYTE,
            VT.WORD, VT.DWORD, VT.BOOL, VT.CHAR)
_HERE = SourcePosition(0, 0, 1, 1)


@pytest.fixture(autouse=True)
def disk_cache_in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(disk_cache.ENV, str(tmp_path / "native-cache"))


def at(text: str) -> Address:
    """`D4` or `D4.1`."""
    byte, _, bit = text[1:].partition(".")
    return Address(Area(text[0]), int(byte), int(bit) if bit else None)


class Program:
    """An S7 program of ops made one by one; each box's W1 to the next output bit."""

    def __init__(self) -> None:
        self.ops: list[Op] = []
        self.outputs = 0

    def read(self, *bits: str) -> Program:
        for k, text in enumerate(bits):
            self.ops.append(Op("RD.STK" if k else "RD", at(text), (), _HERE))
        return self

    def box(self, name: str, *params: object, inputs: tuple[str, ...] = ("X0.0",),
            out: bool = True) -> Program:
        self.read(*inputs)
        self.ops.append(Op(name, None, tuple(at(p) if isinstance(p, str) else int(p)
                                             for p in params), _HERE))
        if out:
            self.ops.append(Op("WRT", Address(Area.R, 100 + self.outputs // 8,
                                              self.outputs % 8), (), _HERE))
            self.outputs += 1
        return self

    def binary(self) -> BinaryProgram:
        return BinaryProgram(tuple(self.ops), dialect="s7")


def _inputs(k: int) -> str:
    return f"X{k // 8}.{k % 8}"


def _typed_boxes(names: tuple[str, ...], operands: tuple[tuple[object, ...], ...],
                 types: tuple[VT, ...] = (*INTEGERS, VT.REAL, VT.LREAL)) -> BinaryProgram:
    """Each of `names` of every type with each operand tuple, each under its own input bit,
    with targets (D32 and on) of its own."""
    program, k = Program(), 0
    for n, name in enumerate(names):
        for t, vtype in enumerate(types):
            for params in operands:
                program.box(name, int(vtype), *(_own(p, 100 * t + 1500 * n) for p in params),
                            inputs=(_inputs(k % 16),))
                k += 1
    return program.binary()


def _own(param: object, shift: int) -> object:
    """A target (D32 and on) moved by `shift`; the data (D0-D23) shared."""
    if isinstance(param, str) and at(param).byte >= 32:
        place = at(param)
        return f"D{place.byte + shift}" + (f".{place.bit}" if place.bit is not None else "")
    return param


COMPARES = ("S7.EQ", "S7.NE", "S7.GT", "S7.LT", "S7.GE", "S7.LE")
_PAIRS = (("D0", "D8"), ("D4", "D4"), ("D12", 0), ("D2", -1), ("D0.3", "D16"),
          (5, "D20"), ("D16", 2139095040))  # 2139095040: a Real's +infinity

ROWS: dict[str, object] = {
    "compares": lambda: _typed_boxes(COMPARES, _PAIRS),
    "ranges": lambda: _typed_boxes(("S7.IN_RANGE", "S7.OUT_RANGE"), (
        ("D0", "D8", "D16"), (-5, "D4", 70), ("D8", "D8.1", "D12"))),
    "OK, NOT_OK": lambda: _oks(),
    "MOVE": lambda: _typed_boxes(("S7.MOVE",), (("D0", "D32"), ("D4", "D44.2"), (-7, "D56"),
                                                (2143289345, "D68"), ("D9.5", "D80"))),
    "arithmetic": lambda: _typed_boxes(("S7.ADD", "S7.SUB", "S7.MUL", "S7.DIV"), (
        ("D0", "D8", "D32"), ("D4", 1, "D44"), ("D12", "D12", "D56.3"),
        (-32768, "D16", "D68"), ("D8", 0, "D80"), ("D20", -1, "D92")), INTEGERS),
    "INC, DEC": lambda: _typed_boxes(("S7.INC", "S7.DEC"), (("D0",), ("D8",), ("D17.4",)),
                                     INTEGERS),
    "CONVERT": lambda: _converts(),
}


def _oks() -> BinaryProgram:
    program = Program()
    for name in ("S7.OK", "S7.NOT_OK"):
        for k, operand in enumerate(("D0", "D4", "D8", "D12", "D16", "D20", "D1.1", 2139095040,
                                     1, 0, -8388608)):
            program.box(name, operand, inputs=(_inputs(k),))
    return program.binary()


def _signed32(value: object) -> object:
    return value - (1 << 32) if isinstance(value, int) and value >= 1 << 31 else value


def _converts() -> BinaryProgram:
    program, k = Program(), 0
    for source in (*INTEGERS, VT.REAL):
        for target in (*INTEGERS, VT.REAL, VT.LREAL):
            program.box("S7.CONVERT", int(source), int(target), f"D{k % 20}", f"D{32 + 8 * k}",
                        inputs=(_inputs(k % 16),))
            k += 1
    for k, target in enumerate((VT.INT, VT.REAL, VT.LREAL)):
        program.box("S7.CONVERT", int(VT.DINT), int(target), -(1 << 31) + k, "D3.1",
                    inputs=(_inputs(k),))
    for k, (source, target, operand, out) in enumerate((  # Real constants, bits, a Real's bit
            (VT.REAL, VT.DINT, 0x4F000000, "D3000"), (VT.REAL, VT.INT, 0x3FC00000, "D3004"),
            (VT.REAL, VT.SINT, 0x40200000, "D3008"), (VT.REAL, VT.UINT, 0xBF000001, "D3012"),
            (VT.REAL, VT.INT, 0x7FC00000, "D3016"), (VT.REAL, VT.REAL, 0x7F800001, "D3020"),
            (VT.REAL, VT.LREAL, 0xFF800001, "D3024"), (VT.REAL, VT.DINT, 0x5F000000, "D3032"),
            (VT.REAL, VT.DINT, "D1.3", "D3036"), (VT.REAL, VT.LREAL, "D2.6", "D3040"),
            (VT.REAL, VT.WORD, "D4", "D3050.2"), (VT.REAL, VT.LREAL, "D8", "D3051.5"),
            (VT.REAL, VT.DINT, 0x3F000000, "D3052.1"), (VT.REAL, VT.INT, 0x3F800000, "D3054"))):
        program.box("S7.CONVERT", int(source), int(target), _signed32(operand), out,
                    inputs=(_inputs(k),))
    return program.binary()


# 4-byte words: the limits of every width, and Real/LReal bits: ±0, denormals, the smallest
# normal, the largest finite, ±infinity, signalling and quiet NaNs
WORDS = (0x00000000, 0xFFFFFFFF, 0x7FFFFFFF, 0x80000000, 0x00007FFF, 0x00008000, 0x0000FFFF,
         0x7F7F80FF, 0x80000001, 0x00000001, 0x00800000, 0x00400000, 0x7F7FFFFF, 0xFF7FFFFF,
         0x7F800000, 0xFF800000, 0x7F800001, 0xFFBFFFFF, 0x7FC00000, 0xFFC00001, 0x3F800000,
         0x7FF00000, 0x7FF40000, 0xFFF80000, 0x41200000, 0xC1200000, 20, 50, 0x00FF0001,
         0x40200000, 0x3FC00000, 0xBF000000, 0x5F000000, 0x4F000000, 0xCF000000, 0x4B7FFFFF)
_word = st.one_of(st.sampled_from(WORDS), st.integers(0, 0xFFFFFFFF)).map(
    lambda w: list(w.to_bytes(4, "big")))
_data = st.lists(st.one_of(_word, st.lists(_byte, min_size=4, max_size=4)),
                 min_size=DATA // 4, max_size=DATA // 4).map(
    lambda words: b"".join(map(bytes, words)))
SCANS = st.lists(st.tuples(_data, st.integers(0, 255), st.integers(0, 255)),
                 min_size=1, max_size=6)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(ROWS))
@settings(max_examples=examples(10), deadline=None)
@given(scans=SCANS)
def test_an_s7_row_runs_natively_as_in_python(row: str, monitored: bool, scans: list) -> None:
    make = ROWS[row]
    assert callable(make)
    _run(make(), monitored, scans, counters=False)


@pytest.mark.parametrize("row", sorted(ROWS))
def test_every_edge_word_of_an_s7_row_runs_natively_as_in_python(row: str) -> None:
    """Each of WORDS in each operand place (rotated), every input on and then off."""
    make = ROWS[row]
    assert callable(make)
    scans = [(b"".join(WORDS[(k + n) % len(WORDS)].to_bytes(4, "big") for n in range(6)), x, x)
             for x in (255, 0) for k in range(len(WORDS))]
    _run(make(), False, scans, counters=False)


def _bits_program() -> BinaryProgram:
    """The edge rows with memory bits the data does not overwrite (D30, D31) and in the data,
    an operand that is its own memory bit, SR and RS on data bits and kept bits."""
    program = Program()
    for k, name in enumerate(("S7.P", "S7.N")):
        program.box(name, "D0.1", f"D30.{k}", inputs=(_inputs(k),))
        program.box(name, "D1.2", f"D2.{k}", inputs=(_inputs(k + 2),))
        program.box(name, f"D31.{k}", f"D31.{k}", inputs=(_inputs(k + 4),))
    for k, name in enumerate(("S7.P_COIL", "S7.N_COIL")):
        program.box(name, f"D32.{k}", f"D30.{k + 2}", inputs=(_inputs(k + 6),))
        program.box(name, f"D33.{k}", f"D33.{k}", inputs=(_inputs(k + 8),))
        program.box(name, f"D3.{k}", f"D30.{k + 4}", inputs=(_inputs(k + 10),))
    for k, name in enumerate(("S7.P_TRIG", "S7.N_TRIG")):
        program.box(name, f"D34.{k}", inputs=(_inputs(k + 12),))
        program.box(name, f"D4.{k}", inputs=(_inputs(k + 14),))
    for k, name in enumerate(("S7.SR", "S7.RS")):
        program.box(name, f"D35.{k}", inputs=(_inputs(k), _inputs(k + 5)))
        program.box(name, f"D5.{k}", inputs=(_inputs(k + 3), _inputs(k + 9)))
    return program.binary()


def _timers_program() -> BinaryProgram:
    """Each timer with a constant PT (a few scans), a PT from the data, ET to a word, a bit
    or nowhere; -(PT)- and -(RT)- on a TON's and a TP's instance."""
    program, k = Program(), 0
    for name in ("S7.TON", "S7.TOF", "S7.TP", "S7.TONR"):
        for pt, et in ((30, f"D{300 + 8 * k}"), ("D0", f"D{304 + 8 * k}.3"), ("D5.2", 0),
                       (-5, f"D{40 + 16 * k}")):
            inputs = (_inputs(k % 16), _inputs((k + 7) % 16))[:2 if name == "S7.TONR" else 1]
            program.box(name, f"D{40 + 16 * k}", pt, et, inputs=inputs)
            k += 1
    program.box("S7.PT", "D40", "D4", inputs=("X1.6",))
    program.box("S7.PT", "D72", 20, inputs=("X1.7",))
    program.box("S7.RT", "D88", inputs=("X1.5",))
    program.box("S7.RT", "D136", inputs=("X1.4",))
    return program.binary()


def _counters_program() -> BinaryProgram:
    """CTU, CTD and CTUD of every integer type, PV a constant or from the data, CV to a
    word, a bit address's byte or nowhere, CTUD's QD to a bit or nowhere."""
    program, k = Program(), 0
    for vtype in INTEGERS:
        for pv, cv in ((3, f"D{600 + 8 * k}"), ("D8", f"D{604 + 8 * k}.1"), ("D2.5", 0)):
            base = 40 + 12 * k
            program.box("S7.CTU", f"D{base}", int(vtype), pv, cv,
                        inputs=(_inputs(k % 16), _inputs((k + 3) % 16)))
            program.box("S7.CTD", f"D{base + 400}", int(vtype), pv, cv,
                        inputs=(_inputs((k + 1) % 16), _inputs((k + 5) % 16)))
            program.box("S7.CTUD", f"D{base + 800}", int(vtype), pv, cv,
                        f"D{1300 + k}.2" if k % 2 else 0,
                        inputs=tuple(_inputs((k + n) % 16) for n in (0, 1, 9, 13)))
            k += 1
    return program.binary()


STATEFUL = {"bits": _bits_program, "timers": _timers_program, "counters": _counters_program}
# each scan: the data (D0-D23), the inputs held for 1-4 scans, and now and then bytes written
# over the instances (D40-D1400: anything a program might leave there)
STATEFUL_SCANS = st.lists(st.tuples(_data, st.integers(0, 255), st.integers(0, 255),
                                    st.integers(1, 4),
                                    st.one_of(st.none(), st.tuples(st.integers(40, 1400),
                                                                   _word))),
                          min_size=1, max_size=8)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("rows", sorted(STATEFUL))
@settings(max_examples=examples(10), deadline=None)
@given(scans=STATEFUL_SCANS)
def test_s7_bits_timers_and_counters_run_natively_as_in_python(rows: str, monitored: bool,
                                                                scans: list) -> None:
    python, native = _engines(STATEFUL[rows](), monitored)
    for data, low, high, repeat, scramble in scans:
        for engine in (python, native):
            engine.memory.areas[Area.D][:DATA] = bytes(data)
            if scramble is not None:
                engine.memory.areas[Area.D][scramble[0]:scramble[0] + 4] = bytes(scramble[1])
            engine.memory.areas[Area.X][0:2] = bytes((low, high))
            for _ in range(repeat):
                engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        assert native._ctx.wake_ms == python._ctx.wake_ms
        if monitored:
            assert native.power_flow == python.power_flow


# the PMC's last four: BYT, CNV/RW, RST and ACT on X0.0-3 / X0.4-7 / X1.0-3 (address operands
# in the data; tables in the data and past it, one reaching the end of the D area)
PMC_ROWS = {
    "DCNV": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nDCNV D0 D30\nWRT Y0.0\n"
            "RD X0.4\nRD.STK X0.5\nRD.STK X0.6\nRD.STK X0.7\nDCNV D2 D2\nWRT Y0.1\n"
            "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nDCNV D4 D32\nWRT Y0.2\n",
    "DSCH": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nDSCH 8 D4 D0 D30\nWRT Y0.0\n"
            "RD X0.4\nRD.STK X0.5\nRD.STK X0.6\nDSCH 150 D2 D1 D32\nWRT Y0.1\n"
            "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nDSCH 20 D9990 D3 D34\nWRT Y0.2\n",
    "DSCHB": "RD X0.1\nRD.STK X0.2\nDSCHB 1 D36 D4 D0 D40\nWRT Y0.0\n"
             "RD X0.5\nRD.STK X0.6\nDSCHB 2 D36 D2 D1 D44\nWRT Y0.1\n"
             "RD X1.1\nRD.STK X1.2\nDSCHB 4 D48 D9980 D3 D52\nWRT Y0.2\n",
    "XMOV": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nXMOV 6 D8 D0 D2\nWRT Y0.0\n"
            "RD X0.4\nRD.STK X0.5\nRD.STK X0.6\nRD.STK X0.7\nXMOV 120 D4 D30 D6\nWRT Y0.1\n"
            "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nXMOV 30 D9980 D32 D1\nWRT Y0.2\n",
}
_SIZES = st.sampled_from((0, 1, 3, 7, 200, 30, -1, (1 << 31) - 1))


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(PMC_ROWS))
@settings(max_examples=examples(15), deadline=None)
@given(scans=st.lists(st.tuples(st.lists(_byte, min_size=DATA, max_size=DATA),
                                st.integers(0, 255), st.integers(0, 255), _SIZES,
                                st.lists(_byte, min_size=20, max_size=20)),
                      min_size=1, max_size=8))
def test_a_pmc_search_row_runs_natively_as_in_python(row: str, monitored: bool,
                                                     scans: list) -> None:
    """The data D0-D23 (a search's data equal to a table entry now and then), DSCHB's sizes
    at D36 and D48, the last 20 bytes of the D area."""
    python, native = _engines(_pmc(PMC_ROWS[row]), monitored)
    for data, low, high, size, tail in scans:
        data = list(data)
        data[0:2] = data[4 + 2 * (low % 4):6 + 2 * (low % 4)] if high & 1 else data[0:2]
        for engine in (python, native):
            d = engine.memory.areas[Area.D]
            d[:DATA] = bytes(data)
            d[36:40] = d[48:52] = size.to_bytes(4, "little", signed=True)
            d[9980:10000] = bytes(tail)
            engine.memory.areas[Area.X][0:2] = bytes((low, high))
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        if monitored:
            assert native.power_flow == python.power_flow


_EDGE_ROWS = "".join(
    f"RD X0.0\nRD.STK X0.2\nRD.STK X0.3\nDSCH {n} D1000 D0 D{200 + 2 * k}\nWRT Y{k}.0\n"
    f"RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nXMOV {n} D1000 D{300 + 2 * k} D2\n"
    f"WRT Y{k}.1\n" for k, n in enumerate((1, 2, 3, 4, 99, 100, 101, 200))) + \
    "RD X0.2\nRD.STK X0.3\nDSCHB 1 D36 D1000 D0 D40\nWRT Y10.0\n" \
    "RD X0.2\nRD.STK X0.3\nDSCHB 2 D36 D1000 D0 D44\nWRT Y10.1\n" \
    "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nDCNV D4 D50\nWRT Y10.2\n"
_PLACES = (0, 1, 2, 3, 4, 5, 98, 99, 100, 101, 102, 199, 200, 201)
_CONVERTED = (0, 9, 0x0A, 0x99, 0x9A, 99, 100, 255, 0x9999, 0x999A, 9999, 10000, 0xA000, 0xFFFF)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_pmc_searches_at_their_bounds_run_natively_as_in_python(monitored: bool) -> None:
    """A match in each place about each table size (and the BCD index's 99/100 and 9999
    limits), every BYT and RW/CNV; DCNV of each digit and size limit."""
    python, native = _engines(_pmc(_EDGE_ROWS), monitored)
    table = bytes((7 * k + 3) % 256 for k in range(512))  # distinct bytes and byte pairs
    for engine in (python, native):
        engine.memory.areas[Area.D][1000:1512] = table
    for place, converted in zip(_PLACES, _CONVERTED, strict=True):
        for x in range(16):
            width = 2 if x & 1 else 1
            for engine in (python, native):
                d = engine.memory.areas[Area.D]
                d[0:2] = table[place * width:place * width + 2]
                d[2:4] = int(str(place % 10 ** (2 * width)), 16).to_bytes(2, "little")
                d[4:6] = converted.to_bytes(2, "little")
                d[36:40] = (place - x % 3).to_bytes(4, "little", signed=True)
                engine.memory.areas[Area.X][0] = x | 8
                engine.scan()
            assert native.memory.areas == python.memory.areas
            assert native.call_states() == python.call_states()
            if monitored:
                assert native.power_flow == python.power_flow


S7_EXAMPLES = sorted((Path(__file__).resolve().parents[3] / "resources" / "examples").glob(
    "s7*/*/*.s7dcl")) + sorted((Path(__file__).resolve().parents[3] / "resources" /
                                "examples").glob("s7-xml/*/*.xml"))


@pytest.mark.parametrize("skipping", [False, True], ids=["every scan, monitored", "skipping"])
@pytest.mark.parametrize("path", [p for p in S7_EXAMPLES if p.suffix == ".s7dcl"],
                         ids=lambda p: p.parent.name)
def test_every_s7_example_runs_natively_as_in_python(path: Path, skipping: bool) -> None:
    """A Python engine running every scan and a native one running every scan (monitored)
    or skipping scans (its timer wakes and states read from its state words): the same
    memory, states and scans after every run (test_skipping's Driver)."""
    compiled = compile_program(parse_file(path).program)
    assert compiled.binary is not None
    _same_when_driven(decode(compiled.binary), path.parent.name, skipping)


@pytest.mark.parametrize("rows", ["timers", "counters", "bits"])
def test_s7_timers_and_counters_skipping_scans_natively_as_python_every_scan(rows: str) -> None:
    _same_when_driven(STATEFUL[rows](), rows, True)


def _same_when_driven(binary: BinaryProgram, seed: str, skipping: bool) -> None:
    engines = (ScanEngine(binary, monitored=not skipping),
               ScanEngine(binary, monitored=not skipping, backend="native"))
    assert engines[1].backend_used == "native" and engines[1]._current.callbacks == []
    engines[0].every_scan, engines[1].every_scan = True, not skipping
    inputs, used, coils = program_inputs(binary)
    driver = Driver(engines, random.Random(seed), inputs or bytes_of(Area.X, 2),
                    used, coils[:4])
    driver.run(1000, rate=0.1)
    for engine in engines:
        engine.cold_start()
    driver.run(300, rate=0.2)
