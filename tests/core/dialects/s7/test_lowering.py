"""SD rungs lowered onto the engine give the logic they draw, on every input: series and
parallel contacts, branches out to several coils, nested branches, NOT, edges, SR/RS, JMPN,
RET in a called FC, a coil passing power on."""

from __future__ import annotations

from itertools import product
from pathlib import Path

import pytest

from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.plc.engine import ScanEngine


class Plc:
    """An OB1 of SD networks compiled and run on the engine."""

    def __init__(self, networks: str) -> None:
        text = f'ORGANIZATION_BLOCK "Main"\n{networks}\nEND_ORGANIZATION_BLOCK\n'
        result = parse_bytes(text.encode("utf-8"), "s7")
        assert result.diagnostics == [], [d.message() for d in result.diagnostics]
        compiled = compile_program(result.program)
        assert compiled.binary is not None, [d.message() for d in compiled.diagnostics]
        self.engine = ScanEngine(compiled.binary)

    def set(self, **bits: int) -> Plc:
        for name, value in bits.items():
            self.engine.memory.set_bit(parse_absolute(f"%{name[0]}{name[1:].replace('_', '.')}")
                                       [0], value)
        return self

    def scan(self) -> Plc:
        self.engine.scan()
        return self

    def get(self, name: str) -> int:
        return self.engine.memory.bit(parse_absolute(name)[0])


def _net(body: str) -> str:
    return f" NETWORK\n{body}\n END_NETWORK\n"


def test_series_and_parallel_with_a_branch_out_to_two_coils() -> None:
    """(I0.0 OR I0.1) AND NOT I0.2 -> Q0.0; the point after I0.0/I0.1 also drives Q0.1."""
    plc = Plc(_net("""
        RUNG wire#powerrail
            Contact( %I0.0 )
            wire#w1
            I_Contact( %I0.2 )
            Coil( %Q0.0 )
        END_RUNG
        RUNG wire#powerrail
            Contact( %I0.1 )
        END_RUNG wire#w1
        RUNG wire#w1
            Coil( %Q0.1 )
        END_RUNG"""))
    for a, b, c in product((0, 1), repeat=3):
        plc.set(I0_0=a, I0_1=b, I0_2=c).scan()
        assert plc.get("%Q0.0") == int((a or b) and not c)
        assert plc.get("%Q0.1") == int(a or b)


def test_a_nested_branch_and_not() -> None:
    """Q0.0 = NOT((I0.0 AND (I0.1 OR I0.2)) OR I0.3)."""
    plc = Plc(_net("""
        RUNG wire#powerrail
            Contact( %I0.0 )
            Contact( %I0.1 )
            wire#w2
        END_RUNG wire#w1
        RUNG wire#powerrail
            Contact( %I0.0 )
            Contact( %I0.2 )
        END_RUNG wire#w2
        RUNG wire#powerrail
            Contact( %I0.3 )
        END_RUNG wire#w1
        RUNG wire#w1
            Not()
            Coil( %Q0.0 )
        END_RUNG"""))
    for a, b, c, d in product((0, 1), repeat=4):
        plc.set(I0_0=a, I0_1=b, I0_2=c, I0_3=d).scan()
        assert plc.get("%Q0.0") == int(not ((a and (b or c)) or d)), (a, b, c, d)


def test_coils_in_series_pass_the_power_on() -> None:
    plc = Plc(_net("""
        RUNG wire#powerrail
            Contact( %I0.0 )
            Coil( %Q0.0 )
            I_Coil( %Q0.1 )
            S_Coil( %M5.0 )
        END_RUNG"""))
    assert (plc.set(I0_0=1).scan().get("%Q0.0"), plc.get("%Q0.1"), plc.get("%M5.0")) == (1, 0, 1)
    assert (plc.set(I0_0=0).scan().get("%Q0.0"), plc.get("%Q0.1"), plc.get("%M5.0")) == (0, 1, 1)


def test_edge_contact_is_on_for_one_scan() -> None:
    plc = Plc(_net("""
        RUNG wire#powerrail
            P_Contact( operand := %I0.0, bit := %M9.0 )
            Coil( %Q0.0 )
        END_RUNG"""))
    seen = [plc.set(I0_0=v).scan().get("%Q0.0") for v in (0, 1, 1, 0, 1)]
    assert seen == [0, 1, 0, 0, 1]


def test_rs_from_a_second_wire() -> None:
    plc = Plc(_net("""
        RUNG wire#powerrail
            Contact( %I0.0 )
            %M7.0.S_RS( wire#w1 )
            Coil( %Q0.0 )
        END_RUNG
        RUNG wire#powerrail
            Contact( %I0.1 )
        END_RUNG wire#w1"""))
    assert plc.set(I0_1=1).scan().get("%Q0.0") == 1  # S1
    assert plc.set(I0_1=0).scan().get("%Q0.0") == 1
    assert plc.set(I0_0=1).scan().get("%Q0.0") == 0  # R
    assert plc.set(I0_1=1).scan().get("%Q0.0") == 1  # set dominant


@pytest.mark.parametrize("condition, skipped", [(0, True), (1, False)])
def test_jmpn_jumps_when_the_result_is_0(condition: int, skipped: bool) -> None:
    plc = Plc(_net("""
        RUNG wire#powerrail
            Contact( %I0.0 )
            I_JumpCoil( over )
        END_RUNG""") + _net("""
        RUNG wire#powerrail
            Coil( %Q0.0 )
        END_RUNG""") + _net("""
        Label( over )
        RUNG wire#powerrail
            Coil( %Q0.1 )
        END_RUNG"""))
    plc.set(I0_0=condition).scan()
    assert (plc.get("%Q0.0"), plc.get("%Q0.1")) == (0 if skipped else 1, 1)


def test_ret_in_a_called_fc_leaves_only_the_fc(tmp_path: Path) -> None:
    (tmp_path / "F.s7dcl").write_text(
        'FUNCTION "F" : Void\n VAR_INPUT\n  a : Bool;\n END_VAR\n VAR_OUTPUT\n  q : Bool;\n'
        ' END_VAR\n' + _net("RUNG wire#powerrail\n Coil( #q )\n END_RUNG")
        + _net("RUNG wire#powerrail\n Contact( #a )\n Return()\n END_RUNG")
        + _net("RUNG wire#powerrail\n R_Coil( #q )\n END_RUNG") + "END_FUNCTION\n",
        encoding="utf-8")
    (tmp_path / "Main.s7dcl").write_text(
        'ORGANIZATION_BLOCK "Main"\n'
        + _net('RUNG wire#powerrail\n Contact( %I0.1 )\n "F"( a := %I0.0, q => %Q0.0 )\n'
               ' Coil( %Q0.1 )\n END_RUNG')
        + _net("RUNG wire#powerrail\n Coil( %Q0.2 )\n END_RUNG") + "END_ORGANIZATION_BLOCK\n",
        encoding="utf-8")
    result = parse_file(tmp_path)
    assert result.diagnostics == []
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    engine = ScanEngine(compiled.binary)
    memory = engine.memory

    def outputs(enable: int, a: int) -> tuple[int, ...]:
        memory.set_bit(parse_absolute("%I0.1")[0], enable)
        memory.set_bit(parse_absolute("%I0.0")[0], a)
        engine.scan()
        return tuple(memory.bit(parse_absolute(f"%Q0.{n}")[0]) for n in range(3))

    assert outputs(1, 1) == (1, 1, 1)  # RET: the FC's last network skipped, OB1 goes on
    assert outputs(1, 0) == (0, 1, 1)  # the FC runs to its end: q reset
    assert outputs(0, 1) == (0, 0, 1)  # EN 0: the FC does not run, its output kept
