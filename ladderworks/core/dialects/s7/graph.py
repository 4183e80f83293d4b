"""The S7-1200 network graph: what every S7 reader (SIMATIC SD, SimaticML XML) produces.

Plain data, no behaviour beyond lookups: a `Block` (OB/FC/FB with its interface) of
`S7Network`s, each a set of `Part`s (contacts, coils, boxes, calls) joined by `Wire`s between
the power rail, parts' named pins and `Operand`s; plus `Tag`s from PLC tag tables. The
lowering (`lowering.py`) turns a `Block` into the engine's `Program`. The contract is written
in docs/dialects.md, "S7-1200: the graph".
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

# The part names (SimaticML's `Part Name=`; the SD reader maps its spellings onto these).
PART_NAMES: frozenset[str] = frozenset({
    "Contact", "Coil", "SCoil", "RCoil", "PContact", "NContact", "PCoil", "NCoil",
    "O", "Sr", "Rs", "TP", "TON", "TOF", "TONR", "CTU", "CTD", "CTUD",
    "Eq", "Ne", "Gt", "Lt", "Ge", "Le", "InRange", "OutRange", "Ok", "NotOk",
    "Move", "Add", "Sub", "Mul", "Div", "Inc", "Dec", "Convert",
    "Jump", "JumpN", "Label", "JumpList", "Switch", "Return", "PTCoil", "RTCoil",
    "Call", "A", "X", "Not", "PTrig", "NTrig",
})


class OperandKind(Enum):
    """What an operand names."""

    GLOBAL = "global"  # a PLC tag or a global DB member: "Start", "DB_Celda".Contador.Total
    LOCAL = "local"  # a member of the block's interface: #Timer, #Timer.Q
    ABSOLUTE = "absolute"  # %I0.0, %MW2, %DB1.DBW4
    CONSTANT = "constant"  # 10, 1.5, TRUE, T#10s, 16#FF, INT#5 (typed or not)


@dataclass(frozen=True, slots=True)
class Operand:
    """A value a pin reads or writes.

    `path` holds the name's components without quotes or `#`: ("Start",), ("DB_Celda",
    "Contador", "Total"), ("Timer", "Q"); an array index is kept in its component text
    ("Arr[3]"). For ABSOLUTE, `path` is (the address as written, "%I0.0"). For CONSTANT, `text`
    is the constant as written ("T#10s", "INT#5", "16#FF", "1.5"); `type_name` its type when
    the export states it (SimaticML TypedConstant, an SD `INT#5` prefix) else "".
    `address` is the absolute address a global tag has in the tag table when the reader knows
    it ("" otherwise)."""

    kind: OperandKind
    path: tuple[str, ...] = ()
    text: str = ""
    type_name: str = ""
    address: str = ""

    def display(self) -> str:
        """The operand as TIA writes it: "Start", #Timer.Q, %I0.0, T#10s."""
        if self.kind is OperandKind.CONSTANT or (not self.path and self.text):
            return self.text  # a constant; an access the reader could not name: its scope
        if self.kind is OperandKind.ABSOLUTE:
            return self.path[0] if self.path else self.text
        if self.kind is OperandKind.LOCAL:
            return "#" + ".".join(self.path)
        head, *rest = self.path or ("",)
        return ".".join([f'"{head}"', *rest])


@dataclass(slots=True)
class Part:
    """One contact, coil or box of a LAD/FBD network.

    `name` is one of PART_NAMES. `negated` holds pin names drawn negated ("operand" for a
    normally closed contact, "in1" on an FBD input). `instance` is the timer/counter/FB
    instance (`#T1`, `"DB1"`) as an Operand. `template` holds TemplateValues ("SrcType":
    "Int", "Card": "3", "value_type": "Time"): the data types of a generic box. `call` is
    the called block's name for name "Call" (its pins are the parameter names); `label`
    the label name for Jump/JumpN/Label; `dests` the labels of JumpList/Switch in order;
    `line` the source line (SD, 1-based) or 0."""

    uid: str
    name: str
    negated: frozenset[str] = frozenset()
    instance: Operand | None = None
    template: dict[str, str] = field(default_factory=dict)
    call: str = ""
    call_kind: str = ""  # "FC" or "FB" when known
    label: str = ""
    dests: tuple[str, ...] = ()
    line: int = 0
    disabled_eno: bool = False  # SimaticML's DisabledENO: the box's ENO is its EN


@dataclass(frozen=True, slots=True)
class End:
    """One end of a wire: the power rail, a part's pin, or an operand.

    Exactly one form: `powerrail` True; or `part` (a Part uid) with `pin` (its pin name as
    SimaticML writes it: "in", "out", "operand", "en", "eno", "in1", "in2", "pre", "pt",
    "q", "et", "cu", "r", "pv", "cv", "min", "max", "val", "out1", "k", "dest0" …, lower case);
    or `operand`."""

    powerrail: bool = False
    part: str = ""
    pin: str = ""
    operand: Operand | None = None


@dataclass(slots=True)
class Wire:
    """A wire: one source end (rail, an output pin, or an operand read) to its targets.

    Power flows from `source` to each of `targets` (a branch is one wire with several
    targets). An operand read is a wire from the operand to an input pin; an operand
    written is a wire from an output pin to the operand. Contacts and coils name their
    operand through the "operand" pin."""

    source: End
    targets: list[End] = field(default_factory=list)
    line: int = 0


@dataclass(slots=True)
class S7Network:
    """One network: title, comment, language and its parts and wires (LAD/FBD).

    An SCL/STL network keeps its text in `source` and has no parts; the lowering marks it
    "not simulated"."""

    title: str = ""
    comment: str = ""
    language: str = "LAD"  # LAD, FBD, SCL, STL
    parts: list[Part] = field(default_factory=list)
    wires: list[Wire] = field(default_factory=list)
    source: str = ""
    line: int = 0  # first line in the source text (SD) or 0
    end_line: int = 0

    def part(self, uid: str) -> Part | None:
        """The part with that uid."""
        return next((p for p in self.parts if p.uid == uid), None)


@dataclass(frozen=True, slots=True)
class Member:
    """One interface member: name, data type ("Bool", "Int", "Time", "IEC_TIMER", "TON_TIME",
    a UDT or an FB name), start value text, comment, sub-members of a Struct."""

    name: str
    type_name: str
    start: str = ""
    comment: str = ""
    members: tuple[Member, ...] = ()


SECTIONS: tuple[str, ...] = ("Input", "Output", "InOut", "Static", "Temp", "Constant", "Return")


@dataclass(slots=True)
class Block:
    """One program block: OB, FC, FB (or GlobalDB/InstanceDB without networks, or a Type: a
    PLC data type whose members are its Static section).

    `number` is 0 when the export does not say (an SD `.s7dcl` drops OB numbers).
    `sections` maps a section name of SECTIONS to its members in order. `instance_of`: an
    instance DB's FB name."""

    kind: str  # "OB", "FC", "FB", "GlobalDB", "InstanceDB", "Type"
    name: str
    number: int = 0
    sections: dict[str, list[Member]] = field(default_factory=dict)
    networks: list[S7Network] = field(default_factory=list)
    title: str = ""
    comment: str = ""
    language: str = "LAD"
    instance_of: str = ""
    return_type: str = "Void"
    # a DB's actual start values (a `.db` source's BEGIN section): member path as written,
    # lower case (`("data", "counts[2]")`) → the value's text
    starts: dict[tuple[str, ...], str] = field(default_factory=dict)

    def members(self, section: str) -> list[Member]:
        """The members of one section ([] when absent)."""
        return self.sections.get(section, [])

    def member(self, name: str) -> tuple[str, Member] | None:
        """(section, member) of an interface member by name (case-insensitive as TIA)."""
        low = name.lower()
        for section, members in self.sections.items():
            for member in members:
                if member.name.lower() == low:
                    return section, member
        return None


@dataclass(frozen=True, slots=True)
class Tag:
    """One PLC tag: name, data type, logical address (%I0.0, %MW2; "" if none), comment; a
    user constant of a tag table (`SW.Tags.PlcUserConstant`) has its `value` instead."""

    name: str
    type_name: str
    address: str = ""
    comment: str = ""
    table: str = ""
    value: str = ""


@dataclass(slots=True)
class S7Program:
    """Everything read: blocks (the first OB, else the first block, is the entry) and tags."""

    blocks: list[Block] = field(default_factory=list)
    tags: list[Tag] = field(default_factory=list)

    def block(self, name: str) -> Block | None:
        """The block called `name` (case-insensitive)."""
        low = name.lower()
        return next((b for b in self.blocks if b.name.lower() == low), None)

    def tag(self, name: str) -> Tag | None:
        """The tag called `name` (case-insensitive, as TIA's names are)."""
        low = name.lower()
        return next((t for t in self.tags if t.name.lower() == low), None)
