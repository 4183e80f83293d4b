"""Each functional row made native equals its Python implementation exactly: a small program
of the row (its operands in D, its inputs on X) runs on a Python engine and a native one, fast
and monitored, with operand bytes and inputs drawn by hypothesis for every scan (edge values:
0, -1, the signed limits, BCD 99/9A, zero divisors); after every scan all memory (results,
R9000 flags, Delta's M1020-M1022/M1067/M1068), the call sites' states and W1 are equal, and
no op calls back into Python."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.dialects.fatek import DEVICES as FATEK_DEVICES
from ladderworks.core.il import parse_file
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import disk_cache
from tests.core.plc.test_skipping import binary_of
from tests.hypothesis_profiles import examples

DATA = 24  # operand bytes from D0, written before every scan
EDGE = (0x00, 0xFF, 0x7F, 0x80, 0x01, 0x99, 0x9A, 0x09, 0x10, 0x90)
_byte = st.one_of(st.sampled_from(EDGE), st.integers(0, 255))
_scans = st.lists(st.tuples(st.lists(_byte, min_size=DATA, max_size=DATA),
                            st.integers(0, 255), st.integers(0, 255)),
                  min_size=1, max_size=8)


@pytest.fixture(autouse=True)
def disk_cache_in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(disk_cache.ENV, str(tmp_path / "native-cache"))


def _pmc(body: str) -> BinaryProgram:
    return binary_of("%@3\n" + body + "%\n")


def _delta(body: str, tmp: Path) -> BinaryProgram:
    path = tmp / "program.txt"
    path.write_text(body + "END\n", encoding="ascii")
    result = compile_program(parse_file(path, dialect="delta").program)
    assert result.binary is not None, [d.message() for d in result.diagnostics][:3]
    return decode(result.binary)


def _bcd_rows(name: str) -> str:
    """The row with BYT, RST and ACT on X0.0-2 (address operand) and X0.3-5 (constant)."""
    return (f"RD X0.0\nRD.STK X0.1\nRD.STK X0.2\n{name} 1 D0 D2 D4\nWRT Y0.0\n"
            f"RD X0.3\nRD.STK X0.4\nRD.STK X0.5\n{name} 0 D6 37 D8\nWRT Y0.1\n"
            f"RD X1.0\nRD.STK X1.1\nRD.STK X1.2\n{name} 0 D10 0 D10\nWRT Y0.2\n")


PMC = {
    "ADD": _bcd_rows("ADD"), "SUB": _bcd_rows("SUB"), "MUL": _bcd_rows("MUL"),
    "DIV": _bcd_rows("DIV"),
    "COMP": "RD X0.0\nRD.STK X0.1\nCOMP 1 D0 D2\nWRT Y0.0\n"
            "RD X0.2\nRD.STK X0.3\nCOMP 0 45 D4\nWRT Y0.1\n"
            "RD X0.4\nRD.STK X0.5\nCOMP 0 9999 D6\nWRT Y0.2\n"
            "RD X0.4\nRD.STK X0.0\nCOMP 1 D8 D8\nWRT Y0.3\n",
    "COIN": "RD X0.0\nRD.STK X0.1\nCOIN 1 D0 D2\nWRT Y0.0\n"
            "RD X0.2\nRD.STK X0.3\nCOIN 0 99 D4\nWRT Y0.1\n"
            "RD X0.4\nRD.STK X0.5\nCOIN 0 120 D6\nWRT Y0.2\n"
            "RD X0.4\nRD.STK X0.0\nCOIN 1 D8 D8\nWRT Y0.3\n",
    "NUME": "RD X0.0\nRD.STK X0.1\nNUME 1234 D0\nRD X0.2\nRD.STK X0.3\nNUME 99 D2\n"
            "RD X0.4\nRD.STK X0.5\nNUME 100 D4\nRD X0.6\nRD.STK X0.7\nNUME 9999 D6\n",
    "DEC": "RD X0.0\nDEC D0 1211\nWRT Y0.0\nRD X0.1\nDEC D1 9901\nWRT Y0.1\n"
           "RD X0.2\nDEC D2 9010\nWRT Y0.2\nRD X0.3\nDEC D3 911\nWRT Y0.3\n"
           "RD X0.4\nDEC D4 1205\nWRT Y0.4\nRD X0.5\nDEC D5 0011\nWRT Y0.5\n",
    "COD": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nCOD 5 D0 D2 12 9999 100 -1 7 8\nWRT Y0.0\n"
           "RD X0.3\nRD.STK X0.4\nRD.STK X0.5\nCOD 3 D1 D4 1 2 3\nWRT Y0.1\n",
    "PARI": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nPARI D0\nWRT Y0.0\n"
            "RD X0.3\nRD.STK X0.4\nRD.STK X0.5\nPARI D1\nWRT Y0.1\n",
    "ROT": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nRD.STK X0.4\nRD.STK X0.5\n"
           "ROT 99 D0 D1 D2\nWRT Y0.0\n"
           "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nRD.STK X1.4\nRD.STK X1.5\n"
           "ROT 12 D4 D6 D8\nWRT Y0.1\n"
           "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nRD.STK X1.4\nRD.STK X1.5\n"
           "ROT 2 D10 D11 D9\nWRT Y0.2\n",
    "ROTB": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nRD.STK X0.4\n"
            "ROTB 1 D0 D1 D2 D3\nWRT Y0.0\n"
            "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nRD.STK X1.4\n"
            "ROTB 2 D4 D6 D8 D10\nWRT Y0.1\n",
    "SFT": "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nSFT D0\nWRT Y0.0\n"
           "RD X0.4\nRD.STK X0.5\nRD.STK X0.6\nRD.STK X0.7\nSFT D2\nWRT Y0.1\n"
           "RD X1.0\nRD.STK X1.1\nRD.STK X1.2\nRD.STK X1.3\nSFT D0\nWRT Y0.2\n",
}


def _gated(*lines: str) -> str:
    """Each instruction under its own input (X0-X7, X10-X17: X bytes 0 and 1), so any one
    may be the last to write the shared flags."""
    inputs = [f"X{k}" for k in range(8)] + [f"X1{k}" for k in range(8)]
    return "".join(f"LD {inputs[k]}\n{line}\n" for k, line in enumerate(lines))


# Delta: D0..D11 are the 24 data bytes; C200/C201 (32-bit) their first 8
DELTA = {
    "MOV": _gated("MOV D0 D20", "MOV K-7 C200", "MOV D1 C201", "MOV C200 D22", "MOV K-32768 D23"),
    "ADD": _gated("ADD D0 D1 D20", "ADD D2 K32767 D21", "ADD C200 D3 D22", "ADD K32767 K0 D23",
                  "ADD K32767 K1 D24", "ADD K-32768 K0 D25", "ADD K-32768 K-1 D26",
                  "ADD K-1 K1 D27", "ADD D4 D4 D28"),
    "SUB": _gated("SUB D0 D1 D20", "SUB K-32768 D2 D21", "SUB C200 D3 D22",
                  "SUB K-32768 K0 D23", "SUB K-32768 K1 D24", "SUB K32767 K-1 D25",
                  "SUB K5 K5 D26", "SUB D4 D4 D27"),
    "MUL": _gated("MUL D0 D1 D20", "MUL C200 D2 D22", "MUL K-3 D3 D24", "MUL C200 C201 D26"),
    "DIV": _gated("DIV D0 D1 D20", "DIV C200 D2 D22", "DIV D3 K0 D24", "DIV D4 K-1 D26",
                  "DIV K-32768 K-1 D28", "DIV K-7 K2 D30", "DIV D5 D5 D32"),
    "INC": _gated("INC D0", "INC C200", "INC D1", "INC C201"),
    "DEC": _gated("DEC D0", "DEC C200", "DEC D1", "DEC C201"),
    "CMP": _gated("CMP D0 D1 M0", "CMP K5 C200 M10", "CMP D2 D2 Y4", "CMP D3 K0 M7"),
    "ZCP": _gated("ZCP D0 D1 D2 M0", "ZCP K-5 K5 C200 M10", "ZCP D3 D4 D5 Y4",
                  "ZCP K5 K-5 D6 M20", "ZCP D7 D7 D7 M30"),
}

# the 32-bit D forms: device pairs, C200 (32-bit) and C0 (16-bit) counters, 32-bit limits
DELTA.update({
    "DMOV": _gated("DMOV D0 D20", "DMOV K-7 C200", "DMOV D2 C201", "DMOV C200 D22",
                   "DMOV K2147483647 D24", "DMOV D4 C0"),
    "DADD": _gated("DADD D0 D2 D20", "DADD D4 K2147483647 D22", "DADD C200 D6 D24",
                   "DADD K2147483647 K1 D26", "DADD K-2147483648 K-1 D28", "DADD K-1 K1 D30",
                   "DADD D8 D8 C0", "DADD K2147483647 K0 D34", "DADD K-2147483648 K0 D36"),
    "DSUB": _gated("DSUB D0 D2 D20", "DSUB K-2147483648 D4 D22", "DSUB C200 D6 D24",
                   "DSUB K-2147483648 K1 D26", "DSUB K5 K5 D28", "DSUB D8 D8 C0",
                   "DSUB K2147483647 K0 D30", "DSUB K-2147483648 K0 D32"),
    "DMUL": _gated("DMUL D0 D2 D20", "DMUL C200 D4 D24", "DMUL K-2147483648 K-2147483648 D28",
                   "DMUL D6 C0 D32"),
    "DDIV": _gated("DDIV D0 D2 D20", "DDIV C200 D4 D24", "DDIV D6 K0 D28",
                   "DDIV K-2147483648 K-1 D32", "DDIV D8 D8 D36", "DDIV K-7 C0 D40"),
    "DINC": _gated("DINC D0", "DINC C200", "DINC D2", "DINC C0"),
    "DDEC": _gated("DDEC D0", "DDEC C200", "DDEC D2", "DDEC C0"),
    "DCMP": _gated("DCMP D0 D2 M0", "DCMP K5 C200 M10", "DCMP D4 D4 Y4", "DCMP C0 K0 M7"),
    "DZCP": _gated("DZCP D0 D2 D4 M0", "DZCP K-5 K5 C200 M10", "DZCP D6 D8 D10 Y4",
                   "DZCP K5 K-5 C0 M20"),
})

_TESTS = ("=", ">", "<", "<>", "<=", ">=")
# the comparison contacts (LD= ... OR>=, DLD= ...) and the edge contacts (LDP ... ORF)
CONTACTS = {
    "LD": "".join(f"LD{t} D{k} D{k + 1}\nOUT Y{k}\nLD{t} C200 K{k - 3}\nOUT M{k}\n"
                  for k, t in enumerate(_TESTS)),
    "AND": "".join(f"LD X{k}\nAND{t} D{k} K0\nOUT Y{k}\n" for k, t in enumerate(_TESTS)),
    "OR": "".join(f"LD X{k}\nOR{t} D{k} D{k + 1}\nOUT Y{k}\n" for k, t in enumerate(_TESTS)),
    "STK": "".join(f"LD X{k}\nLD{t} D{k} D7\nORB\nOUT Y{k}\n" for k, t in enumerate(_TESTS)),
    "DLD": "".join(f"LD X{k}\nDAND{t} D0 D2\nDOR{t} C200 K-1\nOUT Y{k}\n"
                   f"DLD{t} D{2 * k} K2147483647\nOUT M{k}\n" for k, t in enumerate(_TESTS)),
    "EDGE": "LDP X0\nOUT Y0\nLDF X1\nOUT Y1\nLD X2\nANDP X3\nOUT Y2\nLD X4\nANDF X5\n"
            "OUT Y3\nLD X6\nORP X7\nOUT Y4\nLD X10\nORF X11\nOUT Y5\nLD X12\nLDP X13\n"
            "ANB\nOUT Y6\n",
    "PLS": "LD X0\nPLS M0\nLD X1\nPLF M1\nLD X2\nPLS Y0\nPLF Y1\nLD M0\nOUT Y2\n",
}

# the pulse forms (MOVP ...): run in the scan their input went on
DELTA_PULSE = {f"{name}P": text.replace(f"\n{name} ", f"\n{name}P ")
               for name, text in DELTA.items()}


def _fatek_arith(number: int, symbol: str) -> str:
    return "".join(f"ORG X{k}\nFUN {number}{form} ({symbol})\n Sa: {sa}\n Sb: {sb}\n D : {d}\n"
                   f"FO 0\nOUT Y{k}\n"
                   for k, (form, sa, sb, d) in enumerate((
                       ("", "R0", "R1", "R20"), ("P", "R2", "32767", "R22"),
                       ("D", "R4", "R6", "R24"), ("DP", "R8", "-1", "R28"),
                       ("", "R10", "0", "R32"), ("", "-32768", "R11", "R34"))))


FATEK = {
    "MOV": "ORG X0\nFUN 8 MOV\n S : R0\n D : R20\nORG X1\nFUN 8P MOV\n S : -5\n D : R21\n"
           "ORG X2\nFUN 8D MOV\n S : R2\n D : R22\nORG X3\nFUN 8DP MOV\n S : 100000\n D : R24\n",
    "ADD": _fatek_arith(11, "+"), "SUB": _fatek_arith(12, "-"), "MUL": _fatek_arith(13, "*"),
    "DIV": _fatek_arith(14, "/"),
    "INC": "".join(f"ORG X{k}\nFUN 15{form} (+1)\n D : R{2 * k}\nFO 0\nOUT Y{k}\n"
                   for k, form in enumerate(("", "P", "D", "DP"))),
    "DEC": "".join(f"ORG X{k}\nFUN 16{form} (-1)\n D : R{2 * k}\nFO 0\nOUT Y{k}\n"
                   for k, form in enumerate(("", "P", "D", "DP"))),
    "CMP": "".join(f"ORG X{k}\nFUN 17{form} CMP\n Sa: R{2 * k}\n Sb: {sb}\nFO 0\nOUT Y{k}\n"
                   f"FO 1\nOUT Y1{k}\nFO 2\nOUT Y2{k}\n"
                   for k, (form, sb) in enumerate((("", "R1"), ("P", "0"), ("D", "R6"),
                                                    ("DP", "-1")))),
    "170-175": "".join(f"ORG X{k}\nANDF {170 + k}{form} ({symbol})\n Sa: R{k}\n Sb: {sb}\n"
                       f"OUT Y{k}\n"
                       for k, (form, symbol, sb) in enumerate((
                           ("", "=", "R1"), ("", ">", "0"), ("D", "<", "R6"), ("", "<>", "-1"),
                           ("D", ">=", "R2"), ("", "<=", "R5"))))
               + "".join(f"ORG X{k + 6}\nANDF {170 + k} ({symbol})\n Sa: R7\n Sb: R7\n"
                         f"OUT Y1{k}\n"  # equal values: the boundary of every test
                         for k, symbol in enumerate(("=", ">", "<", "<>", ">=", "<="))),
}


def _engines(binary: BinaryProgram, monitored: bool) -> tuple[ScanEngine, ScanEngine]:
    python = ScanEngine(binary, monitored=monitored)
    native = ScanEngine(binary, monitored=monitored, backend="native")
    assert native.backend_used == "native", native.backend_reason
    assert native._current.callbacks == [], native._current.callbacks
    python.every_scan = native.every_scan = True
    return python, native


def _run(binary: BinaryProgram, monitored: bool, scans: list, counters: bool,
         data_at: tuple[Area, int] = (Area.D, 0)) -> None:
    python, native = _engines(binary, monitored)
    area, first = data_at
    for data, low, high in scans:
        for engine in (python, native):
            engine.memory.areas[area][first:first + DATA] = bytes(data)
            if counters:  # C200 and C201 (4 bytes each) and C0 from the data too
                engine.memory.areas[Area.C][800:808] = bytes(data[:8])
                engine.memory.areas[Area.C][0:2] = bytes(data[8:10])
            engine.memory.areas[Area.X][0] = low
            engine.memory.areas[Area.X][1] = high
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        if monitored:
            assert native.power_flow == python.power_flow


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(PMC))
@settings(max_examples=examples(15), deadline=None)
@given(scans=_scans)
def test_a_pmc_row_runs_natively_as_in_python(row: str, monitored: bool, scans: list) -> None:
    _run(_pmc(PMC[row]), monitored, scans, counters=False)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted({**DELTA, **DELTA_PULSE}))
@settings(max_examples=examples(15), deadline=None)
@given(scans=_scans)
def test_a_delta_row_runs_natively_as_in_python(row: str, monitored: bool, scans: list,
                                                tmp_path_factory: pytest.TempPathFactory
                                                ) -> None:
    tmp = tmp_path_factory.mktemp("delta")
    _run(_delta({**DELTA, **DELTA_PULSE}[row], tmp), monitored, scans, counters=True)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("rows", sorted(CONTACTS))
@settings(max_examples=examples(15), deadline=None)
@given(scans=_scans)
def test_delta_contacts_run_natively_as_in_python(rows: str, monitored: bool, scans: list,
                                                  tmp_path_factory: pytest.TempPathFactory
                                                  ) -> None:
    tmp = tmp_path_factory.mktemp("contacts")
    _run(_delta(CONTACTS[rows], tmp), monitored, scans, counters=True)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("row", sorted(FATEK))
@settings(max_examples=examples(15), deadline=None)
@given(scans=_scans)
def test_a_fatek_row_runs_natively_as_in_python(row: str, monitored: bool, scans: list) -> None:
    result = parse_bytes(FATEK[row].encode("ascii"), "fatek")
    assert not [d for d in result.diagnostics if d.is_error]
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.message() for d in compiled.diagnostics][:3]
    r0, _ = FATEK_DEVICES.word("R0")
    _run(decode(compiled.binary), monitored, scans, counters=False, data_at=(r0.area, r0.byte))


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_rot_and_rotb_give_every_small_rotation_as_in_python(monitored: bool) -> None:
    """Every current and target of 0..4 (4 positions: 4 is outside), every RN0, DIR, POS and
    INC (ties between the two ways included), ROTB with 0, 1, 4 and -1 positions."""
    binary = _pmc("RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nRD.STK X0.4\nRD.STK X0.5\n"
                  "ROT 4 D0 D1 D2\nWRT Y0.0\n"
                  "RD X0.0\nRD.STK X0.2\nRD.STK X0.3\nRD.STK X0.4\nRD.STK X0.5\n"
                  "ROTB 1 D4 D5 D6 D7\nWRT Y0.1\n")
    python, native = _engines(binary, monitored)
    for positions in (4, 1, 0, 255):
        for current in range(5):
            for target in range(5):
                for controls in range(16):
                    rn0, direction, pos, inc = (controls >> k & 1 for k in range(4))
                    x = rn0 | direction << 2 | pos << 3 | inc << 4 | 1 << 5
                    for engine in (python, native):
                        engine.memory.areas[Area.D][:8] = bytes(
                            (current, target, 0, 0, positions, current, target, 0))
                        engine.memory.areas[Area.X][0] = x | (controls & 2)
                        engine.scan()
                    assert native.memory.areas == python.memory.areas
                    assert native.call_states() == python.call_states()
