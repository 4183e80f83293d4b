"""FBD networks in SimaticML run as the LAD they map to: operands on gate inputs become
contacts (negated: normally closed), an AND gate a series, an OR gate branches, a compare
feeding a gate its series contact, an unwired EN the rail; an XOR stays not simulated."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.il.reading import parse_bytes
from tests.core.dialects.s7.xml_docs import const, document, wire


def _abs(uid: int, area: str, kind: str, bit: int) -> str:
    return (f'<Access Scope="GlobalVariable" UId="{uid}"><Address Area="{area}" Type="{kind}" '
            f'BitOffset="{bit}" /></Access>')


# %I0.0 AND NOT %I0.1, OR %I0.2 → %Q0.0
_OR_AND = ("<Parts>" + _abs(21, "Input", "Bool", 0) + _abs(22, "Input", "Bool", 1) +
           _abs(23, "Input", "Bool", 2) + _abs(24, "Output", "Bool", 0) +
           '<Part Name="A" UId="30"><Negated Name="in2" /><TemplateValue Name="Card" '
           'Type="Cardinality">2</TemplateValue></Part><Part Name="O" UId="31" />'
           '<Part Name="Coil" UId="32" /></Parts><Wires>' +
           wire(40, "21", "30:in1") + wire(41, "22", "30:in2") + wire(42, "30:out", "31:in1") +
           wire(43, "23", "31:in2") + wire(44, "31:out", "32:in") + wire(45, "24", "32:operand") +
           "</Wires>")
# %I0.3 AND [%MW2 >= 10] → S %Q0.1 ; MOVE 5 → %MW4 with EN open
_CMP = ("<Parts>" + _abs(21, "Input", "Bool", 3) + _abs(22, "Memory", "Int", 16) +
        const(23, "10", "Int") + _abs(24, "Output", "Bool", 1) + const(25, "5", "Int") +
        _abs(26, "Memory", "Int", 32) +
        '<Part Name="Ge" UId="30"><TemplateValue Name="SrcType" Type="Type">Int</TemplateValue>'
        '</Part><Part Name="A" UId="31" /><Part Name="SCoil" UId="32" />'
        '<Part Name="Move" UId="33" /></Parts><Wires>' +
        wire(40, "22", "30:in1") + wire(41, "23", "30:in2") + wire(42, "21", "31:in1") +
        wire(43, "30:out", "31:in2") + wire(44, "31:out", "32:in") +
        wire(45, "24", "32:operand") + wire(46, "25", "33:in") + wire(47, "33:out1", "26") +
        "</Wires>")


def _run(tmp_path: Path, capsys: pytest.CaptureFixture[str], sets: list[str],
         prints: str) -> list[str]:
    path = tmp_path / "Main.xml"
    path.write_text(document([_OR_AND, _CMP], language="FBD"), "utf-8")
    capsys.readouterr()
    args = ["run", str(path), "--scans", "2", "--print", prints]
    for item in sets:
        args += ["--set", item]
    assert main(args) == 0, capsys.readouterr()
    return capsys.readouterr().out.splitlines()


def test_the_gates_become_contacts_in_series_and_branches() -> None:
    network = read_document(document([_OR_AND], language="FBD")).blocks[0].networks[0]
    names = sorted(p.name for p in network.parts)
    assert names == ["Coil", "Contact", "Contact", "Contact", "O"]
    closed = [p for p in network.parts if p.name == "Contact" and p.negated]
    assert len(closed) == 1


@pytest.mark.parametrize(("inputs", "expected"), [
    ([], "0"), (["%I0.0=1"], "1"), (["%I0.0=1", "%I0.1=1"], "0"), (["%I0.2=1"], "1"),
    (["%I0.0=1", "%I0.1=1", "%I0.2=1"], "1")])
def test_and_not_or_runs_as_the_fbd_says(inputs: list[str], expected: str, tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    assert _run(tmp_path, capsys, inputs, "%Q0.0") == [f"%Q0.0 = {expected}"]


def test_a_compare_in_series_and_a_move_without_en(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    assert _run(tmp_path, capsys, ["%I0.3=1", "%MW2=9"], "%Q0.1,%MW4") == [
        "%Q0.1 = 0", "%MW4 = 5"]
    assert _run(tmp_path, capsys, ["%I0.3=1", "%MW2=10"], "%Q0.1") == ["%Q0.1 = 1"]
    assert _run(tmp_path, capsys, ["%MW2=10"], "%Q0.1") == ["%Q0.1 = 0"]


def test_an_xor_is_lowered_too() -> None:
    body = _OR_AND.replace('<Part Name="O" UId="31" />', '<Part Name="X" UId="31" />')
    network = read_document(document([body], language="FBD")).blocks[0].networks[0]
    assert "X" in [p.name for p in network.parts]
    result = parse_bytes(document([body], language="FBD").encode(), "s7")
    assert [d.args.get("part") for d in result.diagnostics
            if d.code == "s7-part-unknown"] == []  # the lowering's XOR gate (s7/stack.py)
    assert not [d for d in result.diagnostics if d.is_error]
