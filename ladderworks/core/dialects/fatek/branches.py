"""Seed 002's branch logic on the engine's result stack: Fatek contacts, blocks and TR points
as RD / AND / OR (.NOT, .STK), AND.STK / OR.STK and WRT (docs/dialects.md, Fatek)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.address import Address, Area
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.devices import (
    BIT_RANGES,
    Device,
    DeviceError,
    bit_address,
    parse_device,
)
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.il.program import Instruction

ALWAYS_OFF = Address(Area.R, 9091, 0)  # OPEN: the engine's always-0 system relay
ALWAYS_ON = Address(Area.R, 9091, 1)  # SHORT: its always-1 relay
MAX_TR = 40  # TR points a network (002:361)

CONTACT_DEVICES = ("X", "Y", "M", "S", "T", "C", "TR")  # 002:90-99
EDGE_DEVICES = ("X", "Y", "M", "S")  # TU / TD (002:92-93)
COIL_DEVICES = ("Y", "M", "S")  # OUT, OUT NOT (002:96-97)
LATCH_DEVICES = ("Y",)  # OUT L (002:98)


@dataclass(slots=True)
class Lowered:
    """One engine network made from Fatek records: its instructions, and the record each came
    from (its source line; None for nothing)."""

    instructions: list[Instruction] = field(default_factory=list)
    records: list[Record] = field(default_factory=list)
    continues: bool = False  # the rest of the Fatek network before it (after LD TR n, FO n)


class BranchError(Exception):
    """A record the stack rules cannot take; its `diagnostic` is at the record's line."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.code)
        self.diagnostic = diagnostic


def refused(record: Record, code: str, **args: object) -> BranchError:
    """The error of a record the rules refuse: `code` at its line and column."""
    return BranchError(Diagnostic(code, dict(args), record.line, record.column))


def contact_address(record: Record) -> Address:
    """The engine bit a contact reads (OPEN, SHORT, a device)."""
    if record.operand == "OPEN":
        return ALWAYS_OFF
    if record.operand == "SHORT":
        return ALWAYS_ON
    device = bit_device(record, CONTACT_DEVICES)
    return bit_address(device)


def bit_device(record: Record, kinds: tuple[str, ...]) -> Device:
    """The record's bit device, which must be one of `kinds`."""
    if not record.operand:
        raise refused(record, "fatek-missing-device", name=spelling_of(record))
    try:
        device = parse_device(record.operand, bit=True)
    except DeviceError as error:
        if error.code == "fatek-device-range":
            raise refused(record, "fatek-device-range", text=error.text,
                        range=error.detail) from None
        raise refused(record, "fatek-device-kind", text=record.operand, name=spelling_of(record),
                    kinds=", ".join(kinds)) from None
    if device.kind not in kinds:
        raise refused(record, "fatek-device-kind", text=record.operand, name=spelling_of(record),
                    kinds=", ".join(kinds))
    return device


def spelling_of(record: Record) -> str:
    """The record's mnemonic with its modifier, for a message (`OUT NOT`)."""
    return f"{record.mnemonic} {record.modifier}".strip()


class StackLowering:
    """Turns the records of one Fatek network into engine networks, keeping seed 002's stack:
    ORG starts the result, LD pushes it and starts anew, AND/OR combine, ANDLD/ORLD pop and
    combine, OUT writes and keeps it, OUT TRn saves it in TRn, LD TRn pushes TRn (002:150-414).
    After an output, LD TRn starts a new engine network `RD TRn` (its pushed value could never
    be used): a branched circuit is drawn as the networks a temporary relay makes."""

    def __init__(self) -> None:
        self.parts: list[Lowered] = []
        self.depth = 0  # values on the Fatek stack (0: nothing yet)
        self.after_output = False
        self.tr_points: set[int] = set()

    @property
    def current(self) -> Lowered:
        """The engine network being made."""
        if not self.parts:
            self.parts.append(Lowered())
        return self.parts[-1]

    def emit(self, record: Record, name: str, operand: Address | None = None) -> None:
        """Append a basic instruction made from `record`."""
        self.current.instructions.append(Instruction(name, operand, line=record.line,
                                                     column=record.column))
        self.current.records.append(record)

    def new_part(self) -> None:
        """Start the next engine network (it goes on from the one before)."""
        self.parts.append(Lowered(continues=True))

    def contact(self, record: Record, address: Address) -> None:
        """ORG / LD / AND / OR (NOT) of a bit."""
        negated = ".NOT" if record.modifier == "NOT" else ""
        kind = record.mnemonic
        if kind == "ORG":  # ORG always starts a network (split_networks)
            self.emit(record, "RD" + negated, address)
            self.depth = 1
        elif kind == "LD":
            if self.after_output and self.current.instructions:
                self.new_part()
                self.emit(record, "RD" + negated, address)
                self.depth = 1
            elif not self.depth:
                self.emit(record, "RD" + negated, address)  # 002:265: a network from LD
                self.depth = 1
            else:
                self.emit(record, "RD" + negated + ".STK", address)
                self.depth += 1
        else:
            if not self.depth:
                raise refused(record, "fatek-no-input", name=kind)
            self.emit(record, kind + negated, address)
        self.after_output = False

    def stack(self, record: Record) -> None:
        """ANDLD / ORLD: the two top values joined."""
        if self.depth < 2:
            raise refused(record, "fatek-stack-empty", name=record.mnemonic)
        self.emit(record, "AND.STK" if record.mnemonic == "ANDLD" else "OR.STK")
        self.depth -= 1
        self.after_output = False

    def save_tr(self, record: Record) -> None:
        """OUT TRn: the point's value kept in TRn."""
        number = self.tr_number(record)
        if number in self.tr_points:
            raise refused(record, "fatek-tr-reused", number=number)
        if len(self.tr_points) >= MAX_TR:
            raise refused(record, "fatek-tr-count", limit=MAX_TR)
        if not self.depth:
            self.emit(record, "RD", ALWAYS_ON)  # 002:465-485 starts at a rail TR point
            self.depth = 1
        self.tr_points.add(number)
        self.emit(record, "WRT", bit_address(Device("TR", number)))

    def load_tr(self, record: Record) -> None:
        """LD TRn: the point's value pushed (a new engine network after an output)."""
        number = self.tr_number(record)
        if number not in self.tr_points:
            raise refused(record, "fatek-tr-unset", number=number)
        record_address = bit_address(Device("TR", number))
        if self.after_output or not self.depth:
            if self.after_output and self.current.instructions:
                self.new_part()
            self.emit(record, "RD", record_address)
            self.depth = 1
        else:
            self.emit(record, "RD.STK", record_address)
            self.depth += 1
        self.after_output = False

    def tr_number(self, record: Record) -> int:
        """The number of the record's TR point (0-39)."""
        text = record.operand[2:]
        low, high = BIT_RANGES["TR"]
        if not text.isdigit() or not low <= int(text) <= high:
            raise refused(record, "fatek-device-range", text=record.operand or "TR",
                        range=f"TR{low}-TR{high}")
        return int(text)

    def coil(self, record: Record) -> None:
        """OUT / OUT NOT / OUT L / OUTS / OUTR: writes the result, which stays."""
        if not self.depth:
            raise refused(record, "fatek-output-on-rail", name=spelling_of(record))
        if self.depth > 1:
            raise refused(record, "fatek-open-block", name=spelling_of(record),
                          count=self.depth - 1)
        kinds = LATCH_DEVICES if record.modifier == "L" else COIL_DEVICES
        device = bit_device(record, kinds)
        name = {"OUTS": "SET", "OUTR": "RST"}.get(record.mnemonic, "WRT")
        if record.modifier == "NOT":
            name = "WRT.NOT"
        elif record.modifier == "L":
            name = "FBS.OUTL"  # kept as its own row: saved `OUT L` again
        self.emit(record, name, bit_address(device))
        self.after_output = True

    def take(self, record: Record) -> bool:
        """Lower a record of the branch logic; False if it is not one (a box, FO …)."""
        kind = record.mnemonic
        if kind in ("ORG", "LD", "AND", "OR") and record.modifier in ("", "NOT"):
            if kind == "LD" and record.operand.upper().startswith("TR") and \
                    record.modifier == "":
                self.load_tr(record)
                return True
            self.contact(record, contact_address(record))
            return True
        if kind in ("ANDLD", "ORLD"):
            self.stack(record)
            return True
        if kind == "OUT" and record.modifier == "TR":
            self.save_tr(record)
            return True
        if kind == "LD" and record.modifier == "TR":
            self.load_tr(record)
            return True
        if kind in ("OUT", "OUTS", "OUTR") and record.modifier != "TR":
            self.coil(record)
            return True
        return False


def split_networks(records: list[Record]) -> list[list[Record]]:
    """The Fatek networks: each starts at ORG (002:156), or at a box with no input before it."""
    networks: list[list[Record]] = []
    for record in records:
        starts = record.mnemonic in ("ORG", "ORGF")
        if starts or not networks:
            networks.append([record])
        else:
            networks[-1].append(record)
    return networks


def lower_branches(records: list[Record]) -> tuple[list[Lowered], list[Diagnostic]]:
    """Engine networks for records of contacts, blocks, TR points and coils only (the seed 002
    examples); the first record the rules refuse gives its network's diagnostic."""
    parts: list[Lowered] = []
    diagnostics: list[Diagnostic] = []
    for network in split_networks(records):
        lowering = StackLowering()
        try:
            for record in network:
                if not lowering.take(record):
                    raise refused(record, "fatek-unknown-instruction", name=record.mnemonic)
        except BranchError as error:
            diagnostics.append(error.diagnostic)
            continue
        parts.extend(lowering.parts)
    return parts, diagnostics
