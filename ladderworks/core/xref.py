"""Cross reference: every place a program reads or writes an address (docs/cross-reference.md).

A `Use` is one address operand or parameter of one instruction: a contact reads its bit, a coil
writes it, a functional instruction reads or writes the bytes of its address parameters, and a
TMR/CTR/CTRB number stands for its bytes in the T or C area. `CrossReference` indexes the uses
by byte, so the uses of a bit include the byte-wide uses covering it, and the uses of a byte
include the bit uses inside it. It is built from a Program (the CLI) or from the ladder grid's
networks (the console, which also knows the cell of each use).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from enum import StrEnum
from typing import NamedTuple

from ladderworks.core import dialects
from ladderworks.core.address import Address, Area, byte_in_range
from ladderworks.core.collector import collector_paused
from ladderworks.core.il.program import FANUC, Program
from ladderworks.core.instructions import (
    BASIC,
    Flow,
    InstructionSpec,
    Numbered,
    Param,
    ParamAccess,
    ParamKind,
    Write,
    spec_for,
    value_is_address,
    width_of,
)
from ladderworks.core.ladder.logic import coil_spec, contact_spec
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.plc.functions.counters import (
    counter_preset_address,
    counter_value_address,
    ctrb_value_address,
)
from ladderworks.core.plc.functions.timers import (
    FANUC_TIMER_BYTES,
    TIMER_BYTES,
    timer_precision_address,
    timer_preset_address,
)


class Access(StrEnum):
    """What a use does with the address."""

    READ = "read"
    WRITE = "write"
    READ_WRITE = "read-write"  # both (a register the instruction keeps, SFT data, XMOV table)


class UseKind(StrEnum):
    """The element that uses the address."""

    CONTACT = "contact"  # RD, AND, OR (and .STK)
    CONTACT_NOT = "contact-not"  # RD.NOT, AND.NOT, OR.NOT (and .STK)
    COIL = "coil"  # WRT
    COIL_NOT = "coil-not"  # WRT.NOT
    SET = "set"  # SET
    RESET = "reset"  # RST
    PARAMETER = "parameter"  # an address parameter of a functional instruction
    NUMBER = "number"  # the T/C bytes of a TMR, CTR or CTRB number


class Use(NamedTuple):
    """One use of an address: where (network, label, unit, cell, line), how, and what."""

    address: Address  # as written: a bit, or the first byte
    width: int  # bytes covered from `address` (0 for a bit)
    network: int  # index of the network (0-based)
    label: str  # the network's LADDER-III label (`N00012`), "" for none
    unit: str  # "L1", "L2", "L3" (a level's main program), "P5" (a subprogram), "" outside
    kind: UseKind
    access: Access
    instruction: str  # the mnemonic (`RD.NOT`, `MOVW`, `TMR`)
    parameter: str  # the parameter's name in the instruction table ("" for a bit operand)
    line: int  # source line (0 when unknown)
    cell: tuple[int, int] | None  # (row, column) of the element in the ladder grid, if known
    comment: str  # the element's own comment (`// ...` of its instruction)


# A parameter's access in the table, as the cross reference says it (EITHER: read-write).
_ACCESS = {ParamAccess.READ: Access.READ, ParamAccess.WRITE: Access.WRITE,
           ParamAccess.READ_WRITE: Access.READ_WRITE, ParamAccess.EITHER: Access.READ_WRITE}

_CONTACT_KIND = {False: UseKind.CONTACT, True: UseKind.CONTACT_NOT}
_COIL_KIND = {(Write.OUT, False): UseKind.COIL, (Write.OUT, True): UseKind.COIL_NOT,
              (Write.SET, False): UseKind.SET, (Write.RESET, False): UseKind.RESET}


def _bit_uses() -> dict[str, tuple[UseKind, Access]]:
    """The use of each basic instruction's bit operand, by mnemonic."""
    table: dict[str, tuple[UseKind, Access]] = {}
    for spec in BASIC:
        if spec.is_coil:
            table[spec.name] = (_COIL_KIND.get((spec.write, spec.negated), UseKind.COIL),
                                Access.WRITE)
        elif spec.is_contact:
            table[spec.name] = (_CONTACT_KIND[spec.negated], Access.READ)
    return table


_BIT_USES = _bit_uses()


class Operand(NamedTuple):
    """An address an instruction uses, before it is placed in a network."""

    address: Address
    width: int
    kind: UseKind
    access: Access
    parameter: str


def _width(spec: InstructionSpec, param: Param, values: dict[str, object]) -> int:
    if isinstance(param.width, str) and not spec.param(param.width).choices:
        count = values.get(param.width)  # MOVN: the byte count itself, not a format
        return count if isinstance(count, int) and count > 0 else 1
    width = width_of(spec, param, values)
    if param.entries:
        size = values.get(param.entries)
        if isinstance(size, int) and size > 0:
            return width * size
    return width


def function_operands(spec: InstructionSpec, params: Sequence[object],
                      dialect: str) -> Iterator[Operand]:
    """The addresses a functional instruction uses: its address parameters, its T/C bytes."""
    values: dict[str, object] = {}
    fixed = spec.fixed_params()
    for param, value in zip(fixed, params, strict=False):
        values[param.name] = value
    for param, value in zip(fixed, params, strict=False):
        if not isinstance(value, Address):
            continue
        if param.kind is ParamKind.VALUE and value_is_address(spec, values) is False:
            continue
        if param.kind not in (ParamKind.ADDRESS, ParamKind.VALUE, ParamKind.RAW):
            continue
        access = _ACCESS[param.access]
        width = 0 if value.is_bit else _width(spec, param, values)
        yield Operand(value, width, UseKind.PARAMETER, access, param.name)
    yield from _numbered_operands(spec, values, dialect)


def _numbered_operands(spec: InstructionSpec, values: dict[str, object],
                       dialect: str) -> Iterator[Operand]:
    """A numbered timer (TMR) reads its preset (and a FANUC precision code); a counter (CTR) its
    preset and value; a fixed counter (CTRB) its value: where the engine keeps them
    (core/plc/functions/timers, counters). The number is the first parameter."""
    numbered = spec.numbered
    if numbered is Numbered.NONE or numbered is Numbered.FIXED_TIMER:
        return
    number = values.get(spec.params[0].name)
    if not isinstance(number, int) or number <= 0:
        return
    if numbered is Numbered.TIMER:
        fanuc = dialect == FANUC
        size = FANUC_TIMER_BYTES if fanuc else TIMER_BYTES
        yield from _area_operand(timer_preset_address(number, dialect), size, Access.READ,
                                 "preset")
        if fanuc:
            yield from _area_operand(timer_precision_address(number), FANUC_TIMER_BYTES,
                                     Access.READ, "precision")
    elif numbered is Numbered.COUNTER:
        yield from _area_operand(counter_preset_address(number), 2, Access.READ, "preset")
        yield from _area_operand(counter_value_address(number), 2, Access.READ_WRITE, "value")
    else:  # Numbered.FIXED_COUNTER
        yield from _area_operand(ctrb_value_address(number), 2, Access.READ_WRITE, "value")


def _area_operand(address: Address, width: int, access: Access,
                  parameter: str) -> Iterator[Operand]:
    if byte_in_range(address.area, address.byte, width):
        yield Operand(address, width, UseKind.NUMBER, access, parameter)


class _Units:
    """The level or subprogram each instruction is in, from the instruction table's flow."""

    def __init__(self, first_level: int) -> None:
        self.current = f"L{first_level}"

    def enter(self, spec: InstructionSpec, params: Sequence[object]) -> str:
        """The unit of this instruction; moves on at SP, SPE, END1/2/3 and END."""
        flow = spec.flow
        if flow is Flow.SUBPROGRAM:
            number = next((getattr(p, "number", p) for p in params), 0)
            self.current = f"P{number}"
            return self.current
        unit = self.current
        if flow is Flow.SUBPROGRAM_END or flow is Flow.PROGRAM_END:
            self.current = ""
        elif flow is Flow.LEVEL_END and not unit.startswith("P"):
            self.current = f"L{spec.level + 1}"
        return unit


def _first_level(specs: Iterable[InstructionSpec | None]) -> int:
    """1 when the first level end is END1, else 2 (as the compiler's structure reads it)."""
    for spec in specs:
        if spec is not None and spec.flow is Flow.LEVEL_END:
            return 1 if spec.level == 1 else 2
    return 2


class CrossReference:
    """The uses of every address of a program, indexed by byte."""

    def __init__(self, uses: list[Use], dialect: str = "") -> None:
        self.uses = uses  # in program order
        self.dialect = dialect  # a Delta/Fatek T0 is one device: its contact and its value
        self._sorted: list[Use] | None = None
        self._by_byte: dict[tuple[Area, int], list[int]] = {}
        index = self._by_byte
        for number, use in enumerate(uses):
            address = use.address
            if use.width <= 1:
                key = (address.area, address.byte)
                found = index.get(key)
                if found is None:
                    index[key] = [number]
                else:
                    found.append(number)
                continue
            for byte in range(address.byte, address.byte + use.width):
                index.setdefault((address.area, byte), []).append(number)

    def __len__(self) -> int:
        return len(self.uses)

    def uses_of(self, address: Address) -> list[Use]:
        """The uses of `address`: of a bit, its own uses and the byte uses covering its byte;
        of a byte, every use covering it and the uses of its bits (network order). A device of
        the dialect with a bit and a value (Delta's, Fatek's T0, C0) is one device: the uses of
        either are the uses of both (`AND T0` reads T0's bit, `TMR T0` writes its value)."""
        twin = device_twin(address, self.dialect)
        found = self._uses_at(address)
        if twin is not None:
            found += [use for use in self._uses_at(twin) if use not in found]
        return sorted(found, key=_place)

    def _uses_at(self, address: Address) -> list[Use]:
        found = self._by_byte.get((address.area, address.byte), [])
        uses = self.uses
        if address.bit is None:
            picked = [uses[k] for k in found]
        else:
            picked = [uses[k] for k in found
                      if uses[k].address.bit is None or uses[k].address.bit == address.bit]
        return picked

    def addresses(self) -> list[Address]:
        """Every address as written in the program, in address order."""
        return sorted({use.address for use in self.uses}, key=address_key)

    def sorted_uses(self) -> list[Use]:
        """Every use, by address (as written), then network."""
        if self._sorted is None:
            self._sorted = sorted(self.uses, key=_order)
        return self._sorted

    @classmethod
    def from_program(cls, program: Program) -> CrossReference:
        """The cross reference of a parsed program (no cells: the lines are known)."""
        with collector_paused():
            return cls(_collect(list(_program_items(program)), program.dialect),
                       program.dialect)

    @classmethod
    def from_ladder(cls, networks: Sequence[LadderNetwork], dialect: str) -> CrossReference:
        """The cross reference of the console's networks, with the cell of every element."""
        with collector_paused():
            return cls(_collect(list(_ladder_items(networks)), dialect), dialect)


def device_twin(address: Address, dialect: str) -> Address | None:
    """The other address of the dialect's device at `address` when it has both a bit and a
    value (Delta T0's contact at T1000.0, its value at T0), else None."""
    found = dialects.get(dialect)
    device = found.devices.device_of(address) if found is not None else None
    if device is None or device[0].bits is None or device[0].words is None:
        return None
    kind, number = device
    return kind.word_address(number) if address.bit is not None else kind.bit_address(number)


_Item = tuple[InstructionSpec, Sequence[object], Address | None, tuple[int, int] | None, str,
              int]  # spec, params, bit operand, cell, comment, line


def _program_items(program: Program) -> Iterator[tuple[str, list[_Item]]]:
    """Each network's label and its instructions as items."""
    specs = _SpecCache()
    for network in program.networks:
        items: list[_Item] = []
        for ins in network.instructions:
            spec = specs.get(ins.name, len(ins.params))
            if spec is not None:
                items.append((spec, ins.params, ins.operand, None, ins.comment, ins.line))
        yield network.label, items


def _ladder_items(networks: Sequence[LadderNetwork]) -> Iterator[tuple[str, list[_Item]]]:
    """Each grid network's label and its elements as items."""
    for network in networks:
        yield network.label, list(_network_elements(network))


def _collect(networks: list[tuple[str, list[_Item]]], dialect: str) -> list[Use]:
    """The uses of every item, with its network's index and label and its unit."""
    units = _Units(_first_level(item[0] for _, items in networks for item in items))
    unit = units.current
    uses: list[Use] = []
    append = uses.append
    none = Flow.NONE
    for index, (label, items) in enumerate(networks):
        for spec, params, operand, cell, comment, line in items:
            flow = spec.flow
            if flow is not none:
                unit = units.enter(spec, params)
            if operand is not None:
                bit = _BIT_USES.get(spec.name)
                if bit is not None:
                    append(Use(operand, 0 if operand.bit is not None else 1, index, label, unit,
                               bit[0], bit[1], spec.name, "", line, cell, comment))
            elif spec.is_function:
                for op in function_operands(spec, params, dialect):
                    append(Use(op.address, op.width, index, label, unit, op.kind, op.access,
                               spec.name, op.parameter, line, cell, comment))
            if flow is not none:
                unit = units.current
    return uses


class _SpecCache:
    """`spec_for` by (name, parameter count), remembered for one build."""

    def __init__(self) -> None:
        self._found: dict[tuple[str, int], InstructionSpec | None] = {}

    def get(self, name: str, count: int) -> InstructionSpec | None:
        """The instruction table's row."""
        key = (name, count)
        try:
            return self._found[key]
        except KeyError:
            spec = self._found[key] = spec_for(name, count)
            return spec


def _network_elements(network: LadderNetwork) -> Iterator[_Item]:
    """(spec, params, bit operand, cell, comment, line) of each element, in program order."""
    if network.listing is not None:
        for ins in network.listing:
            spec = spec_for(ins.name, len(ins.params))
            if spec is not None:
                yield spec, ins.params, ins.operand, None, ins.comment, ins.line
        return
    for cell, element in network.cells.items():
        if isinstance(element, Contact):
            if element.address is not None:
                yield contact_spec(element), (), element.address, cell, element.comment, 0
        elif isinstance(element, Coil):
            if element.address is not None:
                yield coil_spec(element), (), element.address, cell, element.comment, 0
        elif isinstance(element, FunctionBox):
            spec = spec_for(element.name, len(element.params))
            if spec is not None:
                yield spec, element.params, None, cell, element.comment, 0


_AREA_ORDER = {area: rank for rank, area in enumerate(Area)}


def address_key(address: Address) -> tuple[int, int, int]:
    """Sort key of an address: area in the PMC's order (X Y F G R A D T C K E), byte, bit."""
    return (_AREA_ORDER[address.area], address.byte, -1 if address.bit is None else address.bit)


def _order(use: Use) -> tuple[int, int, int, int, int]:
    return (*address_key(use.address), use.network, use.line)


def _place(use: Use) -> tuple[int, int, tuple[int, int], int, int, int]:
    return (use.network, use.line, use.cell or (0, 0), *address_key(use.address))
