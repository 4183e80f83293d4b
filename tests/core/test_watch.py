"""The watch table's core: names and addresses of every family as places, values shown and
typed in each display format (S7's byte order), rows kept, modify values written to a PLC."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.il.program import Program
from ladderworks.core.il.reading import parse_file, parse_text
from ladderworks.core.plc.memory import Memory as PlcMemory
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.watch.places import WatchError, WatchPlace, resolve
from ladderworks.core.watch.rows import (
    WatchRow,
    modify,
    rows_from_text,
    rows_text,
    store,
    watched,
)
from ladderworks.core.watch.values import (
    Format,
    Memory,
    default_format,
    formats,
    parse,
    show,
    time_ms,
    time_text,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7"


@pytest.fixture(scope="module")
def calls() -> Program:
    """The S7 example with an FB instance DB and Time tags."""
    result = parse_file(EXAMPLES / "calls")
    assert result.ok, result.diagnostics
    return result.program


def _memory(memory: PlcMemory) -> Memory:
    return Memory(memory.bit, lambda address, width: memory.read(address, width))


def _place(area: Area, byte: int, width: int, type_name: str = "",
           bit: int | None = None) -> WatchPlace:
    return WatchPlace(Address(area, byte, bit), width, type_name, "")


@pytest.mark.parametrize(("name", "spelled", "type_name", "fmt"), [
    ('"Start"', "%I0.0", "Bool", Format.BOOL),
    ("Start", "%I0.0", "Bool", Format.BOOL),
    ('"motor"', "%Q0.0", "Bool", Format.BOOL),
    ('"Fan Süresi"', "%MD4", "Time", Format.TIME),
    ('"Gecikme_DB".Zaman.ET', "", "Time", Format.TIME),
    ("Gecikme_DB.Zaman.Q", "", "Bool", Format.BOOL),
    ('"Gecikme_DB".Sure', "", "Time", Format.TIME),
    ("%MW2", "%MW2", "", Format.HEX),  # TIA: an absolute word in Hex
    ("%MD12", "%MD12", "", Format.HEX),
    ("%I0.1", "%I0.1", "Bool", Format.BOOL),
    ("%DB1.DBW4", "%DB1.DBW4", "", Format.HEX),
])
def test_s7_names_and_addresses_are_places(calls, name: str, spelled: str, type_name: str,
                                           fmt: Format) -> None:
    found = watched(WatchRow(name), calls.symbols, "s7")
    assert found.place.type_name == type_name
    assert found.fmt is fmt
    if spelled:
        assert found.place.spelled == spelled
    else:  # an optimized DB member: LadderWorks' own layout in D, no address shown (TIA's)
        assert found.place.address.area is Area.D and found.place.spelled == ""


def test_a_struct_or_an_unknown_name_is_refused(calls) -> None:
    with pytest.raises(WatchError) as struct:
        resolve('"Gecikme_DB".Zaman', calls.symbols, "s7")
    assert struct.value.code == "watch-struct"
    with pytest.raises(WatchError) as unknown:
        resolve('"Nowhere"', calls.symbols, "s7")
    assert unknown.value.code == "watch-unknown"
    assert "'\"Nowhere\"'" in unknown.value.diagnostic.message()


@pytest.mark.parametrize(("dialect", "text", "area", "byte", "bit", "width", "fmt"), [
    (None, "X0.1", Area.X, 0, 1, 0, Format.BOOL),
    (None, "D100", Area.D, 100, None, 1, Format.SDEC),
    (None, "D100:2", Area.D, 100, None, 2, Format.SDEC),
    ("delta", "D0", Area.D, 0, None, 2, Format.SDEC),
    ("delta", "M1", Area.R, 0, 1, 0, Format.BOOL),
    ("fatek", "R0", None, None, None, 2, Format.SDEC),
])
def test_other_families_addresses(dialect: str | None, text: str, area: Area | None,
                                  byte: int | None, bit: int | None, width: int,
                                  fmt: Format) -> None:
    found = watched(WatchRow(text), None, dialect)
    if area is not None:
        assert found.place.address == Address(area, byte or 0, bit)
    assert found.place.width == width
    assert found.fmt is fmt
    assert found.place.spelled == text.partition(":")[0]


def test_a_pmc_symbol_is_watched() -> None:
    program = parse_text("%@2\nX0.1 START\nR10 COUNT\n%\n%@3\nN0001:\nRD X0.1\nWRT Y0.0\n%\n"
                         ).program
    assert watched(WatchRow("START"), program.symbols, None).place.address == \
        Address(Area.X, 0, 1)


@pytest.mark.parametrize(("fmt", "width", "text", "raw", "shown"), [
    (Format.SDEC, 2, "-2", 0xFFFE, "-2"),
    (Format.DEC, 2, "65535", 0xFFFF, "65535"),
    (Format.HEX, 2, "16#00ff", 0x00FF, "16#00FF"),
    (Format.HEX, 4, "0x1F", 0x1F, "16#0000001F"),
    (Format.BIN, 1, "2#0000_0101", 5, "2#0000_0101"),
    (Format.REAL, 4, "1.5", 0x3FC00000, "1.5"),
    (Format.REAL, 4, "-0,25", 0xBE800000, "-0.25"),
    (Format.TIME, 4, "T#1m30s500ms", 90_500, "T#1M_30S_500MS"),
    (Format.TIME, 4, "T#-2S", 0xFFFFF830, "T#-2S"),
    (Format.TIME, 4, "0", 0, "T#0MS"),
    (Format.CHAR, 1, "'A'", 65, "'A'"),
])
def test_values_typed_and_shown_in_big_endian_memory(fmt: Format, width: int, text: str,
                                                     raw: int, shown: str) -> None:
    memory = PlcMemory("big")
    place = _place(Area.R, 2, width)
    writes = parse(place, fmt, text)
    store(writes, memory.set_bit, memory.write)
    assert memory.read(Address(Area.R, 2), width) == raw
    assert show(place, fmt, _memory(memory)) == shown
    if width == 2:  # S7's byte order: the high byte first (%MB2 of %MW2)
        assert memory.read(Address(Area.R, 2), 1) == raw >> 8


def test_little_endian_families_store_low_byte_first() -> None:
    memory = PlcMemory("little")
    place = _place(Area.D, 0, 2)
    store(parse(place, Format.SDEC, "-2"), memory.set_bit, memory.write)
    assert memory.read(Address(Area.D, 0), 1) == 0xFE
    assert show(place, Format.SDEC, _memory(memory)) == "-2"


@pytest.mark.parametrize(("fmt", "width", "text", "code"), [
    (Format.SDEC, 2, "40000", "watch-range"),
    (Format.DEC, 1, "-1", "watch-range"),
    (Format.SDEC, 2, "12a", "watch-number"),
    (Format.REAL, 4, "abc", "watch-real"),
    (Format.REAL, 4, "1e39", "watch-real"),
    (Format.TIME, 4, "T#5x", "watch-time"),
    (Format.CHAR, 1, "'AB'", "watch-char"),
    (Format.HEX, 2, "", "watch-empty"),
])
def test_bad_values_are_refused_with_their_reason(fmt: Format, width: int, text: str,
                                                  code: str) -> None:
    with pytest.raises(WatchError) as refused:
        parse(_place(Area.R, 0, width), fmt, text)
    assert refused.value.code == code


def test_bits_take_true_false_and_one_zero() -> None:
    memory = PlcMemory("big")
    place = _place(Area.Y, 0, 0, "Bool", bit=3)
    store(parse(place, Format.BOOL, "true"), memory.set_bit, memory.write)
    assert show(place, Format.BOOL, _memory(memory)) == "TRUE"
    store(parse(place, Format.DEC, "0"), memory.set_bit, memory.write)
    assert show(place, Format.BOOL, _memory(memory)) == "FALSE"
    with pytest.raises(WatchError) as refused:
        parse(place, Format.BOOL, "maybe")
    assert refused.value.code == "watch-bool"


def test_an_s7_string_is_max_length_and_characters() -> None:
    memory = PlcMemory("big")
    place = _place(Area.D, 10, 12, "String[10]")
    assert place.string_length == 10
    store(parse(place, Format.STRING, "'Çay'"), memory.set_bit, memory.write)
    assert memory.read(Address(Area.D, 11), 1) == 3
    assert show(place, Format.STRING, _memory(memory)) == "'Çay'"
    with pytest.raises(WatchError) as long:
        parse(place, Format.STRING, "'abcdefghijk'")
    assert long.value.code == "watch-string"
    with pytest.raises(WatchError) as foreign:
        parse(place, Format.STRING, "'Şu'")
    assert foreign.value.code == "watch-latin1"


def test_time_spellings() -> None:
    assert time_ms("T#1D_2H_3M_4S_5MS") == 93_784_005
    assert time_text(93_784_005) == "T#1D_2H_3M_4S_5MS"
    assert time_ms("TIME#-1.5s") == -1500
    assert time_ms("T#") is None


def test_rows_keep_what_the_user_set_and_survive_damage() -> None:
    rows = [WatchRow('"Start"', "dec", "TRUE", True), WatchRow("%MW2", "", "16#FF")]
    assert rows_from_text(rows_text(rows)) == rows
    assert rows_from_text("{not json") == []
    assert rows_from_text('[{"name": 3}, {"name": "X0.0", "checked": "yes"}]') == \
        [WatchRow("X0.0")]


def test_modify_writes_each_good_row_and_says_where_a_bad_one_is(calls) -> None:
    rows = [WatchRow('"Start"', modify="TRUE"), WatchRow('"Fan Süresi"', modify="T#5x"),
            WatchRow('"Nowhere"', modify="1"), WatchRow("%MW20", modify="16#1234")]
    writes, errors = modify(rows, calls.symbols, "s7")
    assert sorted(errors) == [1, 2]
    assert errors[1].code == "watch-time" and errors[2].code == "watch-unknown"
    assert [(w.address, w.value, w.width) for w in writes] == [
        (Address(Area.X, 0, 0), 1, 0), (Address(Area.R, 20), 0x1234, 2)]


def test_a_modify_in_the_watch_table_drives_the_s7_program(calls) -> None:
    plc = PlcRun()
    assert plc.load_program(calls).binary is not None
    assert plc.start()
    memory = Memory(plc.bit, plc.read)
    motor = watched(WatchRow('"Motor"'), calls.symbols, "s7")
    plc.run_scans(2)
    assert show(motor.place, motor.fmt, memory) == "FALSE"
    writes, errors = modify([WatchRow('"Start"', modify="TRUE")], calls.symbols, "s7")
    assert not errors
    store(writes, plc.set_bit, plc.write)
    plc.run_scans(3)
    assert show(motor.place, motor.fmt, memory) == "TRUE"
    elapsed = watched(WatchRow('"Gecikme_DB".Zaman.ET'), calls.symbols, "s7")
    plc.step(1000)
    assert show(elapsed.place, elapsed.fmt, memory).startswith("T#")
    assert show(elapsed.place, elapsed.fmt, memory) != "T#0MS"


def test_a_block_opened_alone_is_watched_by_its_interface() -> None:
    """An FB by itself (issue 39 item 5): `#Member`, `#Timer.ET` are its interface's places."""
    program = parse_file(EXAMPLES / "calls" / "Gecikme.s7dcl").program
    giris = watched(WatchRow("#Giris"), program.symbols, "s7")
    elapsed = watched(WatchRow("#Zaman.ET"), program.symbols, "s7")
    output = watched(WatchRow("#Cikis"), program.symbols, "s7")
    assert (giris.fmt, elapsed.fmt, output.fmt) == (Format.BOOL, Format.TIME, Format.BOOL)
    plc = PlcRun()
    assert plc.load_program(program).binary is not None
    assert plc.start()
    writes, errors = modify([WatchRow("#Giris", modify="TRUE"),
                             WatchRow("#Sure", modify="T#200MS")], program.symbols, "s7")
    assert not errors
    store(writes, plc.set_bit, plc.write)
    memory = Memory(plc.bit, plc.read)
    plc.step(100)
    assert show(output.place, output.fmt, memory) == "FALSE"
    plc.step(150)
    assert show(output.place, output.fmt, memory) == "TRUE"
    assert show(elapsed.place, elapsed.fmt, memory) == "T#200MS"


def test_an_ltod_is_named_not_shown() -> None:
    symbols = SymbolTable()
    symbols.by_symbol['"Clock"'] = Address(Area.D, 0)
    symbols.types['"Clock"'] = ("LTOD", 8)
    with pytest.raises(WatchError) as wide:
        resolve('"Clock"', symbols, "s7")
    assert wide.value.code == "watch-wide"


@pytest.mark.parametrize(("type_name", "fmt", "text", "raw", "shown"), [
    ("LReal", Format.REAL, "-1.25", 0xBFF4000000000000, "-1.25"),
    ("LReal", Format.REAL, "0.1", 0x3FB999999999999A, "0.1"),  # every digit of a double
    ("LInt", Format.SDEC, "-2", 0xFFFFFFFFFFFFFFFE, "-2"),
    ("LInt", Format.SDEC, str(-2**63), 2**63, str(-2**63)),
    ("ULInt", Format.DEC, str(2**64 - 1), 2**64 - 1, str(2**64 - 1)),
    ("LWord", Format.HEX, "16#0123456789ABCDEF", 0x0123456789ABCDEF, "16#0123456789ABCDEF"),
    ("LTime", Format.TIME, "LT#1d2h3m4s5ms6us7ns", 93_784_005_006_007,
     "LT#1D_2H_3M_4S_5MS_6US_7NS"),
    ("LTime", Format.TIME, "LTIME#-5s", (-5 * 10**9) & (2**64 - 1), "LT#-5S"),
    ("Date", Format.DATE, "D#2024-01-31", 12_448, "D#2024-01-31"),
    ("Date", Format.DATE, "DATE#1990-1-1", 0, "D#1990-01-01"),
    ("Time_Of_Day", Format.TOD, "TOD#12:30:00.000", 45_000_000, "TOD#12:30:00.000"),
    ("TOD", Format.TOD, "23:59:59.5", 86_399_500, "TOD#23:59:59.500"),
])
def test_64_bit_dates_and_times_of_day_in_the_memorys_byte_order(
        type_name: str, fmt: Format, text: str, raw: int, shown: str) -> None:
    """Issue 39: LReal, LInt, ULInt, LWord, LTime (8 bytes), Date and Time_Of_Day as TIA's
    watch table shows them, written and read in S7's byte order (the high byte first)."""
    symbols = SymbolTable()
    symbols.by_symbol['"V"'] = Address(Area.D, 8)
    symbols.types['"V"'] = (type_name, 0)
    place = resolve('"V"', symbols, "s7")
    assert default_format(place, "s7") is fmt and fmt in formats(place)
    memory = PlcMemory("big")
    store(parse(place, fmt, text), memory.set_bit, memory.write)
    width = place.width
    assert memory.read(Address(Area.D, 8), width) == raw
    assert memory.read(Address(Area.D, 8), 1) == raw >> (8 * width - 8)  # big-endian
    assert show(place, fmt, _memory(memory)) == shown
    little = PlcMemory("little")
    store(parse(place, fmt, text), little.set_bit, little.write)
    assert little.read(Address(Area.D, 8), 1) == raw & 0xFF  # a little-endian family's order


@pytest.mark.parametrize(("fmt", "width", "text", "code"), [
    (Format.DATE, 2, "D#2024-02-30", "watch-date"),
    (Format.DATE, 2, "D#1989-12-31", "watch-date"),
    (Format.DATE, 2, "D#2169-06-07", "watch-date"),
    (Format.TOD, 4, "TOD#24:00:00", "watch-tod"),
    (Format.TOD, 4, "noon", "watch-tod"),
    (Format.TIME, 8, "LT#5x", "watch-time"),
    (Format.TIME, 8, f"LT#{2**63}ns", "watch-time"),
    (Format.REAL, 8, "inf", "watch-real"),
    (Format.SDEC, 8, str(2**63), "watch-range"),
])
def test_bad_wide_and_dated_values_are_refused(fmt: Format, width: int, text: str,
                                               code: str) -> None:
    with pytest.raises(WatchError) as refused:
        parse(_place(Area.R, 0, width), fmt, text)
    assert refused.value.code == code


@given(text=st.one_of(st.text(max_size=40), st.from_regex(r"[T#0-9._smhdSMHD+-]{1,30}"),
                      st.just("9" * 5000), st.just("T#" + "9" * 290 + "d"),
                      st.just("9" * 299)),
       fmt=st.sampled_from(list(Format)), width=st.sampled_from([0, 1, 2, 4, 8]))
def test_any_typed_value_is_stored_or_refused_never_a_crash(text: str, fmt: Format,
                                                            width: int) -> None:
    place = _place(Area.R, 4, width, "String[8]" if fmt is Format.STRING else "",
                   bit=0 if width == 0 else None)
    memory = PlcMemory("big")
    try:
        writes = parse(place, fmt, text)
    except WatchError as refused:
        assert refused.diagnostic.message()  # a message to show at the cell
        return
    store(writes, memory.set_bit, memory.write)
    if fmt in formats(place):
        assert show(place, fmt, _memory(memory))
