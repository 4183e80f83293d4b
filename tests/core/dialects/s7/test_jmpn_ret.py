"""JMPN and RET as rows of the S7 table: the palette places them as TIA's -(JMPN)- and -(RET)-
coils, the grid reads back to the graph, the lowering emits the rows, and the engine (Python,
fast and monitored, and native) runs JMPN as a jump taken on 0 and RET's value as the ENO."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.dialects.s7 import palette
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.dialects.s7.from_grid import network_from_grid
from ladderworks.core.dialects.s7.rows import BY_NAME
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.instructions import Flow
from ladderworks.core.ladder.model import Coil
from ladderworks.core.plc.engine import ScanEngine

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples"


def _net(body: str) -> str:
    return f" NETWORK\n{body}\n END_NETWORK\n"


def test_the_rows_say_their_flow() -> None:
    assert BY_NAME["S7.JMPN"].flow is Flow.LABEL_JUMP and BY_NAME["S7.JMPN"].negated
    assert BY_NAME["S7.RET"].flow is Flow.LABEL_JUMP and not BY_NAME["S7.RET"].negated


def test_the_palette_places_jmpn_and_ret_coils() -> None:
    jmpn = palette.new_element("S7.JMPN")
    ret = palette.new_element("S7.RET")
    assert isinstance(jmpn, Coil) and jmpn.mark == "JMPN"
    assert isinstance(ret, Coil) and ret.mark == "RET"
    assert palette.operand_names(jmpn) == ["label"]
    assert palette.operand_names(ret) == ["value"]
    filled = palette.with_operands(ret, ["FALSE"])
    assert isinstance(filled, Coil) and filled.texts == ("FALSE",)


@pytest.mark.parametrize("monitored", [False, True])
@pytest.mark.parametrize("condition", [0, 1])
def test_the_engine_takes_jmpn_on_0(monitored: bool, condition: int) -> None:
    """JMPN (a negated LABEL_JUMP) in the Python scan, fast and monitored."""
    text = ('ORGANIZATION_BLOCK "Main"\n'
            + _net("RUNG wire#powerrail\n Contact( %I0.0 )\n I_JumpCoil( over )\n END_RUNG")
            + _net("RUNG wire#powerrail\n Coil( %Q0.0 )\n END_RUNG")
            + _net("Label( over )\n RUNG wire#powerrail\n Coil( %Q0.1 )\n END_RUNG")
            + "END_ORGANIZATION_BLOCK\n")
    result = parse_bytes(text.encode("utf-8"), "s7")
    jumps = [ins.name for net in result.program.networks for ins in net.instructions
             if ins.name.startswith("S7.J")]
    assert jumps == ["S7.JMPN"]
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary, monitored=monitored)
    engine.memory.set_bit(parse_absolute("%I0.0")[0], condition)
    engine.scan()
    assert [engine.memory.bit(parse_absolute(q)[0]) for q in ("%Q0.0", "%Q0.1")] == \
        [condition, 1]


def test_ret_returns_its_value_as_the_calls_eno(tmp_path: Path) -> None:
    """RET( FALSE ) in an FC: the call's ENO is 0 in that scan, the coil after it off."""
    (tmp_path / "F.s7dcl").write_text(
        'FUNCTION "F" : Void\n VAR_INPUT\n  a : Bool;\n END_VAR\n'
        + _net("RUNG wire#powerrail\n Contact( #a )\n Return( FALSE )\n END_RUNG")
        + "END_FUNCTION\n", encoding="utf-8")
    (tmp_path / "Main.s7dcl").write_text(
        'ORGANIZATION_BLOCK "Main"\n'
        + _net('RUNG wire#powerrail\n Contact( %I0.1 )\n "F"( a := %I0.0 )\n'
               ' Coil( %Q0.1 )\n END_RUNG') + "END_ORGANIZATION_BLOCK\n", encoding="utf-8")
    result = parse_file(tmp_path)
    assert result.diagnostics == []
    names = {ins.name for net in result.program.networks for ins in net.instructions}
    assert {"S7.RET", "S7.JMPN"} <= names and "S7.JMP" not in names
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)

    def eno(enable: int, a: int) -> int:
        engine.memory.set_bit(parse_absolute("%I0.1")[0], enable)
        engine.memory.set_bit(parse_absolute("%I0.0")[0], a)
        engine.scan()
        return engine.memory.bit(parse_absolute("%Q0.1")[0])

    assert [eno(1, 0), eno(1, 1), eno(1, 0), eno(0, 0)] == [1, 0, 1, 0]


def test_the_drawn_ret_and_jmpn_read_back_with_their_operands(tmp_path: Path) -> None:
    """Drawn as -(RET)- with FALSE above and -(JMPN)- with its label; the grid reads back to
    the same parts, and the program rebuilt from the grid lowers to the same instructions."""
    (tmp_path / "Main.s7dcl").write_text(
        'ORGANIZATION_BLOCK "Main"\n'
        + _net("RUNG wire#powerrail\n Contact( %I0.0 )\n I_JumpCoil( over )\n END_RUNG")
        + _net("RUNG wire#powerrail\n Contact( %I0.1 )\n Return( FALSE )\n END_RUNG")
        + _net("Label( over )\n RUNG wire#powerrail\n Coil( %Q0.1 )\n END_RUNG")
        + "END_ORGANIZATION_BLOCK\n", encoding="utf-8")
    program = parse_file(tmp_path / "Main.s7dcl").program
    model = program.model
    assert isinstance(model, S7Model)
    nets = model.draw()
    coils = [e for net in nets[:2] for _c, e in net.elements() if isinstance(e, Coil)]
    assert [(c.mark, c.texts) for c in coils] == [("JMPN", ("over",)), ("RET", ("FALSE",))]
    back = [network_from_grid(net, model.entry) for net in nets[:2]]
    assert [(p.name, p.label) for p in back[0].parts] == [("Contact", ""), ("JumpN", "over")]
    ret = next(p for p in back[1].parts if p.name == "Return")
    assert [w.source.operand.text for w in back[1].wires if w.source.operand is not None
            and any(t.part == ret.uid and t.pin == "operand" for t in w.targets)] == ["FALSE"]
    changed = [net.copy() for net in nets]
    for net in changed:
        net.comments = [*net.comments, "edited"]
    rebuilt, found = model.rebuild(changed)
    assert not found
    assert [n.instructions for n in rebuilt.networks] == \
        [n.instructions for n in program.networks]


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("name", ["calls", "jumps", "jump_list"])
def test_s7_examples_run_the_same_on_the_native_scan(name: str, monitored: bool,
                                                     tmp_path: Path,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    """The native scan takes JMPN (calls skipped on EN 0, the examples' jumps) as the Python
    scan does: the same memory (and power flow) after every scan, on random inputs. (The
    call sites' states are not compared: an S7 timer's state holds its places, an object.)"""
    from ladderworks.core.address import Area
    from ladderworks.core.plc.native import disk_cache

    monkeypatch.setenv(disk_cache.ENV, str(tmp_path / "native-cache"))
    compiled = compile_program(parse_file(EXAMPLES / "s7" / name).program)
    assert compiled.binary is not None
    binary = decode(compiled.binary)
    engines = (ScanEngine(binary, monitored=monitored),
               ScanEngine(binary, monitored=monitored, backend="native"))
    assert engines[1].backend_used == "native", engines[1].backend_reason
    rng = random.Random(name)
    for _scan in range(300):
        if rng.random() < 0.3:
            byte, value = rng.randrange(4), rng.randrange(256)
            for engine in engines:
                engine.memory.areas[Area.X][byte] = value
        for engine in engines:
            engine.scan()
        python, native = engines
        assert python.memory.areas == native.memory.areas
        assert not monitored or python.power_flow == native.power_flow


def test_returnfalse_spells_its_value_in_its_name(tmp_path: Path) -> None:
    """SD's `ReturnFalse()` is a RET of FALSE: the call's ENO is 0 when it is taken."""
    (tmp_path / "F.s7dcl").write_text(
        'FUNCTION "F" : Void\n VAR_INPUT\n  a : Bool;\n END_VAR\n'
        + _net("RUNG wire#powerrail\n Contact( #a )\n ReturnFalse()\n END_RUNG")
        + "END_FUNCTION\n", encoding="utf-8")
    (tmp_path / "Main.s7dcl").write_text(
        'ORGANIZATION_BLOCK "Main"\n'
        + _net('RUNG wire#powerrail\n "F"( a := %I0.0 )\n Coil( %Q0.1 )\n END_RUNG')
        + "END_ORGANIZATION_BLOCK\n", encoding="utf-8")
    result = parse_file(tmp_path)
    assert result.diagnostics == []
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    for a, eno in ((1, 0), (0, 1)):
        engine.memory.set_bit(parse_absolute("%I0.0")[0], a)
        engine.scan()
        assert engine.memory.bit(parse_absolute("%Q0.1")[0]) == eno
