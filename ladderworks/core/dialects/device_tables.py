"""A dialect's device monitor tables (WPLSoft's / WinProladder's): timers, counters, registers.

Qt-free. Each dialect gives a `DeviceTables` (data: its device letters, the instruction rows
that use a timer or a counter and where their number and preset are, its timer bases); these
functions turn a program and a memory image into rows. The device ⇄ memory mapping is the
dialect's `DeviceMap`; no instruction is named here (the dialect's data names its rows).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum

from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.dialects.devices import Device, DeviceMap

Areas = Mapping[Area, bytes | bytearray]  # a snapshot's areas or a Memory's
# (timer number, memory now) -> ms a count (Delta's T64-T126 read M1028)
TimerBase = Callable[[int, Areas], int]
MAX_RANGE = 256  # devices one INSERT may add


class Table(StrEnum):
    """The three device tables."""

    TIMERS = "timers"
    COUNTERS = "counters"
    REGISTERS = "registers"


@dataclass(frozen=True, slots=True)
class Use:
    """Where an instruction row keeps a timer's or counter's number and its preset."""

    device: int  # the parameter that names the device (its Address or its number)
    preset: int  # the parameter that holds the preset (a constant or a register)
    up_down: bool = False  # an up/down counter (Delta DCNT, Fatek UDCTR)


@dataclass(frozen=True, slots=True)
class ModuleUse:
    """Where a row reading or writing a special module's registers (Delta FROM/TO) keeps them."""

    module: int  # the parameter holding the module's number (a constant)
    first: int  # the parameter holding its first register's number
    count: int  # the parameter holding how many it moves
    words: int = 1  # registers a count moves (2: DFROM/DTO's pairs)


@dataclass(frozen=True, slots=True)
class DeviceTables:
    """A dialect's tables: data in `core/dialects/<d>/`."""

    timers: Mapping[str, Use]  # row name -> where its timer and preset are
    counters: Mapping[str, Use]
    timer_base: TimerBase
    timer_letter: str = "T"
    counter_letter: str = "C"
    registers: tuple[str, ...] = ("D",)  # the register letters, in tab order
    constant: str = "{0}"  # how a constant preset is written ("K{0}" for Delta)
    # timer number -> (the relay that switches its base, ms a count while it is on)
    switched_bases: Mapping[int, tuple[str, int]] = field(default_factory=dict)
    # row name -> where its module registers are; they are listed as `module_letter`
    # (module m's register n: number m * module_size + n) in the registers tab
    modules: Mapping[str, ModuleUse] = field(default_factory=dict)
    module_letter: str = ""
    module_size: int = 0


@dataclass(frozen=True, slots=True)
class Preset:
    """A timer's or counter's preset as its instruction writes it."""

    text: str  # "K10", "D5", "30", "R0"
    value: int  # the constant, or the register's value now
    register: bool = False  # a register names it (its value may change while running)


@dataclass(frozen=True, slots=True)
class DeviceRow:
    """One device of a table, as the memory holds it now."""

    table: Table
    device: str  # "T0", "C200", "D10"
    number: int
    address: Address  # where its value is
    width: int  # bytes of its value (2, or 4 for a 32-bit counter)
    value: int  # signed
    contact: bool | None = None  # timers and counters
    base_ms: int = 0  # timers
    preset: Preset | None = None  # None: no instruction of the program sets it
    up_down: bool = False  # counters
    letter: str = ""  # the device's letter ("T", "R")


@dataclass
class ProgramDevices:
    """What a program uses: timers and counters with their preset parameters, registers."""

    timers: dict[int, tuple[object, int]] = field(default_factory=dict)  # n -> (preset, width)
    counters: dict[int, tuple[object, int]] = field(default_factory=dict)
    up_down: set[int] = field(default_factory=set)
    registers: set[tuple[str, int]] = field(default_factory=set)  # (letter, number)


def _number(param: object, letter: str, devices: DeviceMap) -> int | None:
    """The device number a parameter names: a number, or the address of the device's value."""
    if isinstance(param, int) and not isinstance(param, bool):
        return param
    if isinstance(param, Address):
        found = devices.device_of(param)
        if found is not None and found[0].letter == letter:
            return found[1]
    return None


def program_devices(tables: DeviceTables, devices: DeviceMap, ops: object) -> ProgramDevices:
    """The timers, counters and registers a compiled program's ops use."""
    used = ProgramDevices()
    for op in ops or ():  # type: ignore[attr-defined]
        name = op.spec.name
        params = op.params
        for uses, found, letter in ((tables.timers, used.timers, tables.timer_letter),
                                    (tables.counters, used.counters, tables.counter_letter)):
            where = uses.get(name)
            if where is None or len(params) <= max(where.device, where.preset):
                continue
            number = _number(params[where.device], letter, devices)
            if number is None:
                continue
            width = op.spec.params[where.preset].width if where.preset < len(op.spec.params) \
                else 2
            found[number] = (params[where.preset], width if isinstance(width, int) else 2)
            if where.up_down and found is used.counters:
                used.up_down.add(number)
        module = tables.modules.get(name)
        if module is not None:
            used.registers.update(_module_registers(tables, devices, module, params))
        for where in (op.operand, *params):
            if isinstance(where, Address) and where.bit is None:
                device = devices.device_of(where)
                if device is not None and device[0].letter in tables.registers:
                    used.registers.add((device[0].letter, device[1]))
    return used


def _constant(param: object) -> int | None:
    return param if isinstance(param, int) and not isinstance(param, bool) else None


def _module_registers(tables: DeviceTables, devices: DeviceMap, use: ModuleUse,
                      params: tuple) -> set[tuple[str, int]]:
    """The module registers a FROM/TO row's constants name (a register operand: none known)."""
    if len(params) <= max(use.module, use.first, use.count):
        return set()
    module, first, count = (_constant(params[k]) for k in (use.module, use.first, use.count))
    if module is None or first is None or count is None or tables.module_size <= 0:
        return set()
    found = set()
    for number in range(max(first, 0), min(first + count * use.words, tables.module_size)):
        place = module * tables.module_size + number
        if _device(devices, tables.module_letter, place) is not None:
            found.add((tables.module_letter, place))
    return found


def _read(areas: Areas, address: Address, width: int) -> int:
    """The signed value of `width` bytes at `address`."""
    data = areas[address.area]
    return int.from_bytes(data[address.byte:address.byte + width], "little", signed=True)


def _bit(areas: Areas, address: Address) -> bool:
    return bool(areas[address.area][address.byte] >> (address.bit or 0) & 1)


def _device(devices: DeviceMap, letter: str, number: int) -> Device | None:
    return next((d for d in devices.by_letter.get(letter, ()) if d.first <= number <= d.last),
                None)


def preset(tables: DeviceTables, devices: DeviceMap, param: object, width: int,
           areas: Areas) -> Preset:
    """A preset parameter: a constant (`K10`), or a register (`D5`) and its value now."""
    if isinstance(param, Address):
        return Preset(devices.format(param) or str(param), _read(areas, param, width), True)
    value = int(param) if isinstance(param, int) else 0
    return Preset(tables.constant.format(value), value)


@dataclass(frozen=True, slots=True)
class Place:
    """What a row needs that does not change while a program runs: found once, read often."""

    table: Table
    device: str
    number: int
    letter: str
    address: Address
    width: int
    contact: Address | None
    preset: tuple[object, int] | None  # the preset parameter and its width
    up_down: bool


def place(table: Table, devices: DeviceMap, letter: str, number: int,
          used: ProgramDevices | None = None) -> Place | None:
    """Where device `letter``number` and its preset are; None if the dialect has no such
    word device."""
    device = _device(devices, letter, number)
    if device is None or device.words is None:
        return None
    counting = table is not Table.REGISTERS
    contact = device.bit_address(number) if counting and device.bits is not None else None
    uses = (used.timers if table is Table.TIMERS else used.counters) if used else {}
    up_down = used is not None and table is Table.COUNTERS and number in used.up_down
    return Place(table, device.spell(number), number, device.letter,
                 device.word_address(number), device.width(number), contact,
                 uses.get(number) if counting else None, up_down)


def table_places(table: Table, tables: DeviceTables, devices: DeviceMap, used: ProgramDevices,
                 listed: set[tuple[str, int]]) -> list[Place]:
    """The places of a table's rows: the devices the program uses and those the user listed,
    sorted (by letter in the table's order, then number)."""
    if table is Table.TIMERS:
        wanted = {(tables.timer_letter, n) for n in used.timers}
    elif table is Table.COUNTERS:
        wanted = {(tables.counter_letter, n) for n in used.counters}
    else:
        wanted = set(used.registers)
    letters = table_letters(table, tables)
    wanted |= {item for item in listed if item[0] in letters}
    order = {letter: index for index, letter in enumerate(letters)}
    found = (place(table, devices, letter, number, used)
             for letter, number in sorted(wanted, key=lambda item: (order[item[0]], item[1])))
    return [where for where in found if where is not None]


def read_rows(places: list[Place], tables: DeviceTables, devices: DeviceMap,
              areas: Areas) -> list[DeviceRow]:
    """The rows at these places as the memory `areas` hold them now."""
    rows = []
    for where in places:
        address = where.address
        start = address.byte
        value = int.from_bytes(areas[address.area][start:start + where.width], "little",
                               signed=True)
        if where.table is Table.REGISTERS:
            rows.append(DeviceRow(where.table, where.device, where.number, address, where.width,
                                  value, letter=where.letter))
            continue
        contact = _bit(areas, where.contact) if where.contact is not None else None
        set_by = (preset(tables, devices, where.preset[0], where.preset[1], areas)
                  if where.preset is not None else None)
        base = tables.timer_base(where.number, areas) if where.table is Table.TIMERS else 0
        rows.append(DeviceRow(where.table, where.device, where.number, address, where.width,
                              value, contact, base, set_by, where.up_down, where.letter))
    return rows


def table_rows(table: Table, tables: DeviceTables, devices: DeviceMap, used: ProgramDevices,
               listed: set[tuple[str, int]], areas: Areas) -> list[DeviceRow]:
    """The rows of a table now (`table_places` then `read_rows`)."""
    return read_rows(table_places(table, tables, devices, used, listed), tables, devices, areas)


def table_letters(table: Table, tables: DeviceTables) -> tuple[str, ...]:
    """The device letters a table lists."""
    if table is Table.TIMERS:
        return (tables.timer_letter,)
    if table is Table.COUNTERS:
        return (tables.counter_letter,)
    return tables.registers


def device_range(table: Table, tables: DeviceTables, devices: DeviceMap,
                 text: str) -> list[tuple[str, int]]:
    """The devices a user typed to add to a table: `D10`, `D0-D9` or `T5..T8`; AddressError
    (device-unknown, device-range, device-not-in-table, device-range-order)."""
    spelled = text.strip().replace("..", "-").replace("~", "-")
    first_text, dash, last_text = spelled.partition("-")
    letters = table_letters(table, tables)
    first_device, first = devices.split(first_text)
    if first_device.letter not in letters or first_device.words is None:
        raise AddressError("device-not-in-table", text=first_text.strip(),
                           letters=", ".join(letters))
    last = first
    if dash:
        last_device, last = devices.split(last_text if last_text.strip()[:1].isalpha()
                                          else first_device.letter + last_text.strip())
        if last_device.letter != first_device.letter:
            raise AddressError("device-not-in-table", text=last_text.strip(),
                               letters=first_device.letter)
    if last < first or last - first >= MAX_RANGE:
        raise AddressError("device-range-order", text=text.strip(), most=MAX_RANGE)
    return [(first_device.letter, n) for n in range(first, last + 1)]
