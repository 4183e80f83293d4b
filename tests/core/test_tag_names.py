"""An S7 program's names in the utilities: tags typed with their types' widths, the name shown
for an address, internal relays hidden, typed values in scenarios, the CLI's xref by tag."""

from __future__ import annotations

import pytest

from ladderworks.cli import main
from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.s7.values import time_text
from ladderworks.core.il import parse_file
from ladderworks.core.plc.scenario import parse_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.plc.typed import real_bits
from ladderworks.core.tag_names import (
    TagNames,
    network_name,
    network_names,
    network_titles,
    split_names,
    typed_text,
    typed_value,
)
from ladderworks.paths import EXAMPLES

MODBUS = EXAMPLES / "s7" / "modbus"
TIMERS = EXAMPLES / "s7" / "timers" / "Main.s7dcl"


@pytest.fixture(scope="module")
def names() -> TagNames:
    return TagNames.of(parse_file(MODBUS).program)


@pytest.mark.parametrize(("typed", "shown", "address", "width", "type_name"), [
    ('"Start"', '"Start"', Address(Area.X, 0, 0), 1, "Bool"),
    ("start", '"Start"', Address(Area.X, 0, 0), 1, "Bool"),  # TIA's names: any case
    ('"Calisma_DB".Q', '"Calisma_DB".Q', Address(Area.D, 8, 1), 1, "Bool"),
    ("Calisma_DB.ET", '"Calisma_DB".ET', Address(Area.D, 4), 4, "Time"),
    ('"Hedef Hız"', '"Hedef Hız"', Address(Area.R, 10), 2, "Int"),
    ("Sıcaklık", '"Sıcaklık"', Address(Area.R, 16), 4, "Real"),
    ('"DB_Modbus".Durum', '"DB_Modbus".Durum', Address(Area.D, 18), 2, "Int"),
    ("%MW2", "%MW2", Address(Area.R, 2), 2, "Word"),
    ("%M10.1", "%M10.1", Address(Area.R, 10, 1), 1, "Bool"),
    ("%IW2", "%IW2", Address(Area.X, 2), 2, "Word"),
])
def test_a_tag_or_address_resolves_with_its_width(names: TagNames, typed: str, shown: str,
                                                  address: Address, width: int,
                                                  type_name: str) -> None:
    named = names.resolve(typed)
    assert (named.text, named.address, named.width, named.type_name) == (
        shown, address, width, type_name)


def test_names_shown_for_addresses_and_internal_relays(names: TagNames) -> None:
    assert names.shown(Address(Area.X, 0, 0)) == '"Start"'
    assert names.shown(Address(Area.D, 16)) == '"DB_Modbus".Komut'  # a member, not the DB
    assert names.shown(Address(Area.D, 0)) == '"Calisma_DB"'  # the instance
    assert names.spelled(Address(Area.D, 16)) == ""  # laid out: no S7 spelling
    assert names.spelled(Address(Area.R, 12), 4) == "%MD12"
    assert names.internal(Address(Area.R, 8192, 0))  # the engine's own relay
    assert not names.internal(Address(Area.R, 8191, 7))  # %M8191.7
    with pytest.raises(AddressError):
        names.resolve('"Yok"')
    assert not TagNames(None, None).typed


def test_a_blocks_own_members_by_hash_or_bare() -> None:
    names = TagNames.of(parse_file(EXAMPLES / "s7" / "calls" / "Gecikme.s7dcl").program)
    assert names.resolve("#Zaman.Q").type_name == "Bool"
    assert names.resolve("#Zaman.ET").width == 4
    assert names.resolve("Giris").text == "#Giris"
    assert names.resolve("sure").type_name == "Time"


def test_names_typed_on_one_line() -> None:
    assert split_names('"Lamba 1" %Q0.1, "Motor".Q;#Timer.Q  "Sıcaklık"') == [
        '"Lamba 1"', "%Q0.1", '"Motor".Q', "#Timer.Q", '"Sıcaklık"']


def test_values_as_their_types_write_them() -> None:
    assert [time_text(ms) for ms in (0, 5000, 90_000, -2500, 86_400_001)] == [
        "T#0MS", "T#5S", "T#1M_30S", "T#-2S_500MS", "T#1D_1MS"]  # as TIA's watch table
    assert typed_text(real_bits(21.5), "Real", 4) == "21.5"
    assert typed_text(0xFFFF, "Int", 2) == "-1"
    assert typed_text(5000, "Time", 4) == "T#5S"
    assert typed_text(7, "Word", 2) is None
    assert typed_value("T#1m30s", "Time", 4) == 90_000
    assert typed_value("-1.5", "Real", 4) == real_bits(-1.5)
    assert typed_value("12", "Int", 2) is None  # a plain number is the caller's


def test_network_titles_follow_the_s7_networks() -> None:
    program = parse_file(MODBUS).program
    titles = network_titles(program)
    assert titles[0] == "Start sets the motor"
    assert titles[-1] == "The temperature (Real) to the HMI"
    assert len(titles) == len(program.networks)


def scenario_result(text: str) -> list[str]:
    """The check messages of a scenario on the timers example."""
    program = parse_file(TIMERS).program
    binary = compile_program(program).binary
    assert binary is not None
    plc = PlcRun(period_ms=10)
    assert plc.load(binary, program) == []
    scenario = parse_scenario(text, "t.csv", program.symbols, program.dialect)
    assert scenario.ok, scenario.error_texts()
    result = run_scenario(plc, scenario)
    return [check.message("t.csv") for check in result.checks]


def test_a_scenario_checks_times_by_tag_with_comparisons() -> None:
    messages = scenario_result(
        'PMC SIGNAL DATA\nSET,0,"Start",1\nWAITFOR,6000,"IEC_Timer_0_DB".ET,>=T#5s\n'
        'EXPECT,0,"IEC_Timer_0_DB".ET,<T#5s\nEXPECT,0,"Lamba 2",1\n'
        'EXPECT,5000,"Geçen Süre",T#10s\nEXPECT,0,"IEC_Timer_0_DB".Q,<>0\n')
    assert messages[0] == 't.csv:3: "IEC_Timer_0_DB".ET>=T#5S at 5000 ms'
    assert messages[1] == 't.csv:4: expected "IEC_Timer_0_DB".ET<T#5S, got T#5S at 5000 ms'
    assert messages[2:] == ['t.csv:5: "Lamba 2"=1 at 5000 ms',
                            't.csv:6: "Geçen Süre"=T#10S at 10000 ms',
                            't.csv:7: "IEC_Timer_0_DB".Q<>0 at 10000 ms']


def test_a_bad_typed_value_or_comparison_is_said_at_its_line() -> None:
    program = parse_file(TIMERS).program
    scenario = parse_scenario('PMC SIGNAL DATA\nEXPECT,0,"Geçen Süre",T#5x\n'
                              'SET,0,"Start",>=1\nEXPECT,0,"Yok",1\n', "t.csv",
                              program.symbols, program.dialect)
    assert [(d.line, d.code) for d in scenario.diagnostics] == [
        (2, "scenario-value"), (3, "scenario-value"), (4, "scenario-address")]


def test_the_examples_typed_scenarios_pass(capsys: pytest.CaptureFixture[str]) -> None:
    for folder in (MODBUS, EXAMPLES / "s7" / "compare"):
        assert main(["test", str(folder / "Main.s7dcl"),
                     str(folder / "Main.scenario.csv")]) == 0
        assert "1 passed, 0 failed" in capsys.readouterr().out


def test_xref_lists_an_s7_programs_tags_by_network_title(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["xref", str(MODBUS)]) == 0
    out = capsys.readouterr().out
    assert "R8192" not in out and "TRUE" not in out  # the engine's own relays: never shown
    rows = [line.split("  ") for line in out.splitlines()]
    assert any(r[0] == "%MW10" and '"Hedef Hız"' in line
               and "The HMI's command word to the speed set point" in line
               for r, line in zip(rows, out.splitlines(), strict=True))
    assert '"DB_Modbus".Komut' in out and "%MD12    \"Çalışma Süresi\"" in out
    assert main(["xref", str(MODBUS), '"Motor"', "Calisma_DB.Q"]) == 0
    lines = capsys.readouterr().out.splitlines()[1:]
    assert [line.split()[:2] for line in lines[:3]] == [['%Q0.0', '"Motor"']] * 3
    assert "Start sets the motor" in lines[0] and "Stop resets the motor" in lines[1]
    assert main(["xref", str(MODBUS), '"Yok"']) == 2


def test_xref_of_one_block_file_takes_its_folders_tags(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["xref", str(MODBUS / "Main.s7dcl"), "Hazır"]) == 0
    assert capsys.readouterr().out.splitlines()[1].split()[:2] == ["%Q0.1", '"Hazır"']


def test_a_timers_preset_is_named_apart_from_its_instance(
        capsys: pytest.CaptureFixture[str]) -> None:
    """`"Karıştırma Süresi"` is a TP instance whose PT lies at its first byte: a MOVE to the
    PT names the PT, the TP's instance parameter the instance."""
    assert main(["xref", str(EXAMPLES / "s7" / "jumps" / "Main.s7dcl")]) == 0
    rows = [[cell.strip() for cell in line.split("  ") if cell.strip()]
            for line in capsys.readouterr().out.splitlines()]
    moves = [row for row in rows if "parameter OUT1" in row]
    instance = [row for row in rows if "parameter instance" in row]
    assert len(moves) == 2 and all(row[1] == '"Karıştırma Süresi".PT' for row in moves)
    assert instance[0][1] == '"Karıştırma Süresi"'


def test_a_recorded_s7_scenario_names_its_tags_and_replays() -> None:
    from ladderworks.core.dialects.s7.devices import parse_absolute
    from ladderworks.core.plc.recorder import ScenarioRecorder

    program = parse_file(MODBUS).program
    binary = compile_program(program).binary
    assert binary is not None
    plc = PlcRun(period_ms=10)
    assert plc.load(binary, program) == []
    plc.start()
    recorder = ScenarioRecorder(plc, "recorded")
    recorder.start()
    plc.run_scans(2)
    plc.set_bit(parse_absolute("%I0.0")[0], 1)
    plc.write(parse_absolute("%IW2")[0], 1234, 2)  # "Analog", an Int: by its tag
    plc.write(parse_absolute("%IB3")[0], 7, 1)  # one byte of it: by its address
    plc.run_scans(2)
    plc.force(parse_absolute("%I0.1")[0], 1)
    plc.run_scans(2)
    recorder.stop()
    written = recorder.text()
    assert written.splitlines()[2:] == [
        'SET,20,"Start",1', 'SET,0,"Analog",0x4D2,WORD', "SET,0,%IB3,0x7,BYTE",
        'FORCE,20,"Stop",1', 'EXPECT,10,"Motor",0,BIT']  # "Stop" forced: "Motor" reset
    again = PlcRun(period_ms=10)
    assert again.load(binary, program) == []
    scenario = parse_scenario(written, "again", program.symbols, program.dialect)
    assert scenario.ok, scenario.error_texts()
    assert run_scenario(again, scenario).passed


def test_xref_lists_uses_under_the_s7_network_number_and_title(
        capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 39: a use under `Network n: Title` of its S7 network (TIA's), the uses inside a
    called FC/FB (lowered inline) under the calling network of OB1."""
    calls = EXAMPLES / "s7" / "calls"
    program = parse_file(calls).program
    names = network_names(program)
    assert len(names) == len(program.networks)
    assert set(names) - {""} == {"Network 1: The motor held by the FC",
                                 "Network 2: The fan 3 s after the motor, by the FB"}
    assert main(["xref", str(calls), '"Fan"', '"Gecikme_DB".Cikis']) == 0
    rows = capsys.readouterr().out.splitlines()[1:]
    assert rows and all("Network 2: The fan 3 s after the motor, by the FB" in r for r in rows)
    assert not any("On-delay in the FB instance" in r for r in rows)  # the FB's own title
    assert network_name(3, "") == "Network 3" and network_name(3, "Network 3") == "Network 3"
    assert network_name(3, "Pompa", "Ağ") == "Ağ 3: Pompa" and network_name(0, "x") == ""
