"""The `.dvp` reader on the real WPLSoft projects in ../shared/real-programs/delta (read there,
never copied): all decode, the machine's project matches its CSV export, the training programs
hold what their names say and run."""

from __future__ import annotations

import contextlib
import io
import random
from functools import cache

import pytest

from ladderworks.cli import main
from ladderworks.core.compiler import compile
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.dialects.delta.dvp_drawing import DrawingError, drawing_program
from ladderworks.core.dialects.delta.dvp_encode import encode_all
from ladderworks.core.dialects.delta.dvp_file import (
    DATA_END,
    FIRST_SECTION,
    PROGRAM_START,
    SETTINGS_SIZE,
    DvpProject,
    read_dvp,
    read_or_diagnostic,
)
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.conftest import get, put
from tests.real_programs import real_programs_dir

MACHINE = "METALURGICA_c91257f_atual_no_programa.dvp"
EXPORT = "METALURGICA_c91257f_proejto_clp.csv"


def _names() -> list[str]:
    return sorted(p.name for p in (real_programs_dir() / "delta").glob("*.dvp"))


@cache
def _data(name: str) -> bytes:
    return (real_programs_dir() / "delta" / name).read_bytes()


@cache
def _project(name: str) -> DvpProject:
    return read_dvp(_data(name))


def _training(name: str) -> list[str]:
    return [each.text() for each in _project(f"NIRMALKUMAR_{name}.dvp").instructions]


def test_all_55_projects_decode_without_an_error() -> None:
    names = _names()
    assert len(names) == 55  # 54 training projects and the machine's
    instructions = comments = 0
    empty, drawn, unknown = [], [], []
    for name in names:
        project, diagnostic = read_or_diagnostic(_data(name))
        assert diagnostic is None, (name, diagnostic and diagnostic.message())
        assert project is not None
        instructions += len(project.instructions)
        comments += len(project.comments)
        short = name.removeprefix("NIRMALKUMAR_")
        if project.drawn:
            drawn.append(short)
        if not project.instructions:
            empty.append(short)
        unknown += [each.mnemonic for each in project.instructions if not each.known]
        assert all(w.code in ("dvp-no-program", "dvp-unknown-code", "dvp-from-drawing")
                   for w in project.warnings)
    assert (instructions, comments) == (919, 73983)
    # saved without a compiled instruction list: read from their ladder drawing
    assert drawn == ["Dvp1.dvp", "Dvp3.dvp", "contactcmp2.dvp", "counter1.dvp",
                     "doublezcp.dvp", "zonecmp.dvp"]
    assert empty == ["setreset.dvp"]  # neither a program nor a drawing
    assert unknown == ["?821C", "?821C"]  # timer1, timer2: one code not identified


def _drawn(name: str) -> list[tuple[int, str]] | None:
    data = _data(name)
    end = data.find(DATA_END, data.find(FIRST_SECTION)) + len(DATA_END) + 1
    try:
        return [(each.step, each.text()) for each in drawing_program(data, end)]
    except DrawingError:
        return None


def test_a_series_drawing_is_exactly_the_compiled_program() -> None:
    # every compiled project whose drawing has no branch: the same instructions, same steps
    same, differ, unread = [], [], 0
    for name in _names():
        project = _project(name)
        if project.drawn or not project.instructions:
            continue
        drawn = _drawn(name)
        if drawn is None:
            unread += 1
            continue
        short = name.removeprefix("NIRMALKUMAR_").removesuffix(".dvp")
        compiled = [(each.step, each.text()) for each in project.instructions]
        if drawn != compiled:  # rising_edge: its drawing has lost the END row
            assert drawn == compiled[:-1] and compiled[-1][1] == "END", name
            differ.append(short)
            continue
        same.append(short)
    assert (len(same), differ, unread) == (25, ["rising_edge"], 22)
    assert {"timer", "maths", "mathsdouble", "contactcomp", "division", "set_reset1", "inv",
            "counter", "compare", "float", "mc_mcr"} <= set(same)


@pytest.mark.parametrize(("name", "holds"), [
    ("Dvp1", ["LD M0", "ANI M1", "OUT Y0", "END"]),
    ("zonecmp", ["LD X0", "ZCP D0 D1 D2 M0", "LD M0", "OUT Y0", "LD M1", "OUT Y1", "LD M2",
                 "OUT Y2", "END"]),
    ("contactcmp2", ["LD>= D0 D1", "OUT Y0", "LD<= D2 D3", "OUT Y1", "FLD<= D4 D6", "OUT Y2",
                     "FLD>= D8 D10", "OUT Y3", "END"]),
    ("counter1", ["LD X0", "CNT C0 K5", "LD X1", "RST C0", "LD X2", "CNT C1 K5", "LD X3",
                  "CNT C2 K5", "LD X4", "ZRST C0 C2"]),  # drawn without END
])
def test_an_uncompiled_project_opens_from_its_drawing(name: str, holds: list[str]) -> None:
    project = _project(f"NIRMALKUMAR_{name}.dvp")
    assert project.drawn and [each.text() for each in project.instructions] == holds
    assert [w.code for w in project.warnings] == ["dvp-from-drawing"]


def test_every_program_memory_is_its_instructions_re_encoded_byte_for_byte() -> None:
    # the decoding loses nothing: instructions -> words -> scrambled with the project's key
    for name in _names():
        data = _data(name)
        project = _project(name)
        stop = data.find(FIRST_SECTION) - SETTINGS_SIZE
        words = [] if project.drawn else encode_all(project.instructions)
        words += [0x7FFF] * ((stop - PROGRAM_START) // 2 - len(words))
        plain = b"".join(word.to_bytes(2, "little") for word in words)
        if project.version == 215:
            key = data[0x5E:0x62]
            stream = bytes((key[0], key[1] ^ 0x80, key[2], key[3] ^ 0x80))
        else:
            byte = data[0x56 if project.version == 214 else 0x5E]
            stream = bytes((byte, byte ^ 0x80) * 2)
        key = (stream * (len(plain) // 4 + 1))[:len(plain)]
        scrambled = (int.from_bytes(plain, "little") ^ int.from_bytes(key, "little")).to_bytes(
            len(plain), "little")
        assert scrambled == data[PROGRAM_START:stop], name


def test_every_truncation_of_the_smallest_project_is_cut_short_at_its_length() -> None:
    data = _data(MACHINE)  # 95 531 bytes
    for length in range(len(data)):
        project, diagnostic = read_or_diagnostic(data[:length])
        assert project is None and diagnostic is not None
        assert diagnostic.code == ("dvp-truncated" if length >= 4 else "dvp-not-dvp"), length
        assert length < 4 or diagnostic.args["offset"] == length


def test_byte_flips_in_a_real_project_never_raise() -> None:
    rng = random.Random(2026)
    data = _data("NIRMALKUMAR_task8.dvp")
    used = PROGRAM_START + 2 * _project("NIRMALKUMAR_task8.dvp").steps
    stop = data.find(FIRST_SECTION)
    codes: set[str] = set()
    for turn in range(240):  # the header, the used steps, the rest of the program memory
        flipped = bytearray(data)
        flipped[rng.randrange(used if turn % 2 else stop)] ^= 1 << rng.randrange(8)
        project, diagnostic = read_or_diagnostic(bytes(flipped))
        assert (project is None) != (diagnostic is None)
        codes.add(diagnostic.code if diagnostic is not None else "read")
    assert {"read", "dvp-after-end", "dvp-unknown-device"} <= codes, codes


def _csv() -> list[tuple[int, str]]:
    rows = []
    for line in _data(EXPORT).decode("ascii").splitlines():
        step, *fields = line.split(",")
        rows.append((int(step), " ".join(fields)))
    return rows


def test_the_machine_project_is_its_csv_export_up_to_step_825() -> None:
    project = _project(MACHINE)
    decoded = [(each.step, each.text()) for each in project.instructions]
    exported = _csv()
    assert len(exported) == 373 and len(decoded) == 360
    # the same 336 instructions at the same steps up to FROM K0 K30 D50 K1 at step 825,
    # except two constants the machine's copy has changed (K40 -> K100, K5 -> K20)
    head = [row for row in exported if row[0] <= 825]
    assert len(head) == 336
    differ = [(a, b) for a, b in zip(head, decoded[:336], strict=True) if a != b]
    assert differ == [((11, "MOV K40 D580"), (11, "MOV K100 D580")),
                      ((17, "MOV K5 D582"), (17, "MOV K20 D582"))]
    # after it the two copies differ: the project's END is at step 907, the export's at 922
    assert decoded[336:338] == [(834, "LD> D50 K0"), (839, "TO K0 K1 H0 K1")]
    assert (decoded[-1], exported[-1]) == ((907, "END"), (922, "END"))
    assert project.title == "torno_" and project.comments == {}


@pytest.mark.parametrize(("name", "holds"), [
    ("timer", ["LD X0", "TMR T0 K5", "LD T0", "OUT Y0", "LD X1", "RST T0", "END"]),
    ("counter", ["LDP X0", "CNT C0 K10", "LD C0", "OUT Y0", "END"]),
    ("counter3clock", ["LD M1013", "CNT C0 K10", "LD C0", "OUT Y0", "END"]),
    ("set_reset1", ["LD X0", "OUT Y0", "LD X1", "SET Y0", "LD X2", "RST Y0", "LD X3",
                    "SET Y1", "LD X4", "RST Y1", "END"]),
    ("jump", ["LD X0", "OUT Y0", "LD X1", "CJ P0", "LD X2", "OUT Y2", "LD X3", "OUT Y3",
              "P0", "LD X4", "OUT Y4", "LD X5", "OUT Y5", "END"]),
    ("mc_mcr", ["LD X0", "MC N0", "LD X1", "OUT Y0", "LD X2", "OUT Y1", "LD X3", "OUT Y2",
                "MCR N0", "END"]),
    ("inv", ["LD X0", "INV", "OUT Y0", "LDI X1", "INV", "OUT Y1", "END"]),
    ("np", ["LD X0", "NP", "OUT M0", "LD M0", "OR Y0", "OUT Y0", "END"]),
    ("pn", ["LDI X0", "PN", "OUT M0", "LD M0", "OR Y0", "OUT Y0", "END"]),
    ("bcdbin", ["LD X0", "BCD D0 D1", "LD X1", "BIN D2 D3", "END"]),
    ("division", ["LD X1", "DIV D5 D6 D7", "LD= D8 K0", "OUT Y0", "LD X1", "DIV D9 D10 D11",
                  "LD= D12 K0", "OUT Y1", "END"]),
    ("rising_edge_outside", ["LD X0", "PLS Y0", "LD X1", "PLF Y1", "LDP X2", "OR M0",
                             "OUT M0", "LD X3", "PLS M1", "LD M1", "OR M2", "OUT M2", "END"]),
    ("contacttypeboolean", ["LD& K0 K1", "OUT Y0", "LD| K2 K3", "OUT Y1", "LD^ K3 K4",
                            "OUT Y2", "DLD& D0 D2", "OUT Y3", "LD& D4 D5", "OUT Y4", "END"]),
])
def test_a_training_program_holds_what_its_name_says(name: str, holds: list[str]) -> None:
    assert _training(name) == holds


def test_the_other_training_programs_use_the_instructions_they_are_named_for() -> None:
    uses = {"compare": {"CMP", "DMOVR", "DECMP"}, "float": {"DMOVR", "DEADD"},
            "maths": {"ADD", "SUB", "MUL", "DIV"}, "mathsdouble": {"DADD"},
            "increment": {"INC", "DEC", "LDP"}, "booleangates": {"WAND", "WOR", "WXOR", "NEG"},
            "callsubroutine": {"CALL", "FEND", "SRET", "P0", "P1"}, "pid": {"PID", "MOV"},
            "analog": {"FROM", "TO"}, "analoginput": {"FROM", "SCLP"}, "task7": {"ZRST", "MPS"},
            "contactcomp": {"LD>", "LD=", "LD<", "FLD=", "FLD>", "FLD<"},
            "cntrightleft": {"CNT", "RST"}, "kep": {"TMR"}, "memory": {"OR", "ANI"}}
    for name, mnemonics in uses.items():
        found = {text.split()[0] for text in _training(name)}
        assert mnemonics <= found, (name, found)


def _engine(name: str) -> ScanEngine:
    result = parse_bytes(_data(f"NIRMALKUMAR_{name}.dvp"))
    assert result.ok, [d.message() for d in result.diagnostics if d.is_error]
    return ScanEngine(compile(result.program), period_ms=10)


def test_the_timer_project_runs() -> None:
    plc = _engine("timer")
    put(plc, "X0", 1)
    plc.run_scans(45)
    assert get(plc, "Y0") == 0
    plc.run_scans(10)  # K5: 0.5 s
    assert get(plc, "Y0") == 1
    put(plc, "X0", 0)
    put(plc, "X1", 1)
    plc.run_scans(2)
    assert (get(plc, "Y0"), get(plc, "T0")) == (0, 0)


def test_the_counter_project_counts_rising_edges() -> None:
    plc = _engine("counter")
    for _ in range(10):
        assert get(plc, "Y0") == 0
        put(plc, "X0", 1)
        plc.run_scans(2)
        put(plc, "X0", 0)
        plc.run_scans(2)
    assert (get(plc, "C0"), get(plc, "Y0")) == (10, 1)


def test_the_subroutine_project_calls_its_subroutines() -> None:
    plc = _engine("callsubroutine")
    put(plc, "X3", 1)
    plc.run_scans(2)
    assert get(plc, "Y1") == 0  # P0 not called
    put(plc, "X1", 1)
    plc.run_scans(2)
    assert get(plc, "Y1") == 1


def test_device_comments_become_the_programs_symbols() -> None:
    result = parse_bytes(_data("NIRMALKUMAR_pid.dvp"))
    symbols = result.program.symbols
    assert symbols is not None
    assert symbols.lookup(DEVICES.word("D0")[0]).comment == "SP"
    assert symbols.lookup(DEVICES.word("D11")[0]).comment == "Kp"
    assert symbols.lookup(DEVICES.bit("M1000")).comment.startswith("Normally open contact")
    assert _project("NIRMALKUMAR_manualrightleft.dvp").comments["X1"] == "right limit switch"


def _cli(*args: str) -> tuple[int, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        code = main(list(args))
    return code, out.getvalue()


def test_the_cli_checks_and_draws_a_project() -> None:
    path = str(real_programs_dir() / "delta" / "NIRMALKUMAR_cjj.dvp")
    assert _cli("check", path)[0] == 0
    code, text = _cli("ladder", path)
    assert code == 0 and "CJ" in text and "Y4" in text
