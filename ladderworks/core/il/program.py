"""The program model: networks of instructions with their comments and source positions."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, NamedTuple

from ladderworks.core.address import Address
from ladderworks.core.il.textform import TextForm
from ladderworks.core.instructions import InstructionSpec, Kind, spec_for

if TYPE_CHECKING:
    from ladderworks.core.symbols import SymbolTable


@dataclass(frozen=True, slots=True, order=True)
class ProgramRef:
    """A subprogram number as a parameter (`P5` in CALL, CALLU, SP)."""

    number: int

    def __str__(self) -> str:
        return f"P{self.number}"


@dataclass(frozen=True, slots=True, order=True)
class LabelRef:
    """A jump label as a parameter (`L5` in JMPB, JMPC, LBL)."""

    number: int

    def __str__(self) -> str:
        return f"L{self.number}"


ParamValue = int | Address | ProgramRef | LabelRef

SEED = "seed"  # a LadderWorks (seed manual) program
FANUC = "fanuc"  # a LADDER-III export: `%@A` framing or `N00012:` network labels


class Instruction(NamedTuple):
    """One instruction: a mnemonic with its address operand or its parameters.

    A tuple underneath because the parser makes one per line and a tuple is made in one call (a
    frozen slots dataclass, as it was, sets its fields one by one: ~3x slower). It keeps the
    dataclass's meaning: immutable, equality and hash ignore `line` and `column` (the hash is
    the same number), never equal to a plain tuple, no order."""

    name: str
    operand: Address | None = None
    params: tuple[ParamValue, ...] = ()
    comment: str = ""  # trailing `// ...` comment, stripped: the element's comment
    lead: tuple[str, ...] = ()  # comment lines just before it, inside a network
    line: int = 0  # not compared
    column: int = 0  # not compared

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not Instruction:
            return False if isinstance(other, tuple) else NotImplemented
        return self[:_COMPARED] == other[:_COMPARED]

    def __ne__(self, other: object) -> bool:
        equal = self.__eq__(other)
        return equal if equal is NotImplemented else not equal

    def __hash__(self) -> int:
        return hash(self[:_COMPARED])

    # no tuple ordering: `<` raises TypeError as it did on the dataclass
    def __lt__(self, other: object) -> bool:
        raise TypeError("instructions have no order")

    def __le__(self, other: object) -> bool:
        raise TypeError("instructions have no order")

    def __gt__(self, other: object) -> bool:
        raise TypeError("instructions have no order")

    def __ge__(self, other: object) -> bool:
        raise TypeError("instructions have no order")

    @property
    def spec(self) -> InstructionSpec:
        """The instruction table row."""
        spec = spec_for(self.name, len(self.params))
        assert spec is not None, self.name
        return spec

    @property
    def is_function(self) -> bool:
        """True for a functional instruction."""
        return self.spec.kind is Kind.FUNCTION

    def param_map(self) -> dict[str, object]:
        """Parameters by name (a TABLE collects the remaining values as a tuple)."""
        values: dict[str, object] = {}
        fixed = self.spec.fixed_params()
        for param, value in zip(fixed, self.params, strict=False):
            values[param.name] = value
        table = self.spec.table_param()
        if table is not None:
            values[table.name] = tuple(self.params[len(fixed):])
        return values


_COMPARED = 5  # name, operand, params, comment, lead: the fields equality and hash look at
_new = tuple.__new__


def new_instruction(name: str, operand: Address | None, params: tuple[ParamValue, ...],
                    comment: str, lead: tuple[str, ...], line: int, column: int) -> Instruction:
    """Instruction(...) with every field given, faster: the parser makes one per line. It
    makes the tuple directly, without the default handling of Instruction's __new__."""
    return _new(Instruction, (name, operand, params, comment, lead, line, column))


@dataclass(slots=True, init=False)
class Network:
    """A rung: instructions from the first RD to the last coil/function, with its comment lines."""

    instructions: list[Instruction] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)  # comment lines before the network
    label: str = ""  # LADDER-III network label without its colon (`N00012`), "" for none

    # by hand: `[]` for a None default is quicker than default_factory (one Network per rung)
    def __init__(self, instructions: list[Instruction] | None = None,
                 comments: list[str] | None = None, label: str = "") -> None:
        self.instructions = [] if instructions is None else instructions
        self.comments = [] if comments is None else comments
        self.label = label

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Network):
            return NotImplemented
        return (self.instructions == other.instructions and self.comments == other.comments
                and self.label == other.label)

    def key(self) -> tuple[object, ...]:
        """What the network says, as a hashable value (equal keys print the same)."""
        return (self.label, tuple(self.comments), tuple(self.instructions))

    @property
    def line(self) -> int:
        """Source line of the first instruction (0 if unknown)."""
        return self.instructions[0].line if self.instructions else 0


@dataclass(slots=True)
class Section:
    """A FANUC section other than the ladder (`%@0`..`%@5`, `%@2-C` ...), kept verbatim."""

    number: int
    lines: list[str] = field(default_factory=list)  # the body, between `%@n` and `%`
    header: str = ""  # the header line as written (`%@2-C`); "" means `%@<number>`

    @property
    def title(self) -> str:
        """The header line, `%@2-C` or `%@<number>`."""
        return self.header.strip() or f"%@{self.number}"


@dataclass(frozen=True, slots=True)
class Message:
    """A `%@4` message: the A bit that raises it, its number and its text."""

    address: Address
    number: int
    text: str


@dataclass(frozen=True, slots=True)
class IoModule:
    """A `%@5` I/O module line: first byte address, group, base, slot and module name."""

    address: str
    group: int
    base: int
    slot: int
    name: str


@dataclass(slots=True, eq=False)
class FileSource:
    """The text a program was read from, kept so an unmodified part is written back as read.

    `lines`/`ends` are every line of the file and its own line end. The ladder body is lines
    `ladder_start` .. `ladder_stop - 1`; network k of the parse was lines `spans[k]` and said
    `keys[k]`; the lines after the last network (comments, blanks) are `trailer_span`."""

    form: TextForm
    lines: list[str]
    ends: list[str]
    ladder_start: int = 0
    ladder_stop: int = 0
    keys: list[tuple[object, ...]] = field(default_factory=list)
    spans: list[tuple[int, int]] = field(default_factory=list)
    heads: list[int] = field(default_factory=list)  # first instruction line of each network
    trailer: tuple[str, ...] = ()
    trailer_span: tuple[int, int] = (0, 0)


@dataclass(slots=True)
class Program:
    """A whole `.LAD` / `.MOD` file: the ladder section and any other sections."""

    networks: list[Network] = field(default_factory=list)
    header: list[str] = field(default_factory=list)  # comment lines before `%@3`
    trailer: list[str] = field(default_factory=list)  # comment lines after the last network
    before: list[Section] = field(default_factory=list)  # sections before the ladder
    after: list[Section] = field(default_factory=list)  # sections after the ladder
    footer: list[str] = field(default_factory=list)  # comment lines after the last section
    framed: bool = False  # wrapped in `%@A` ... `%@E` (LADDER-III "ALL" format)
    dialect: str = SEED  # FANUC for a LADDER-III export (`%@A` or network labels)
    source: FileSource | None = None  # the text it was read from (None: built in memory)
    # views of the other sections, filled by the parser (read-only in the console)
    title: dict[int, str] = field(default_factory=dict)  # %@1: item number -> text
    system_params: dict[str, str] = field(default_factory=dict)  # %@0: item -> value
    symbols: SymbolTable | None = None  # %@2: address <-> symbol, comments
    messages: dict[Address, Message] = field(default_factory=dict)  # %@4 by A bit
    io_modules: list[IoModule] = field(default_factory=list)  # %@5
    # a dialect's own model of its source, kept beside the engine's networks it lowered to
    # (S7: the network graph, its memory layout, each network's engine networks and the entry
    # block's file as read): the console draws it and rebuilds the program from a changed
    # drawing (ladder/source_model.py); the dialect's writer saves a change from it (S7:
    # dialects/s7/saving.py)
    model: object | None = None

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Program):
            return NotImplemented
        return (
            self.networks == other.networks
            and self.header == other.header
            and self.trailer == other.trailer
            and self.footer == other.footer
            and self.framed == other.framed
            and [(s.title, s.lines) for s in self.before]
            == [(s.title, s.lines) for s in other.before]
            and [(s.title, s.lines) for s in self.after]
            == [(s.title, s.lines) for s in other.after]
        )

    @property
    def form(self) -> TextForm:
        """The text form to save in: the file's own, or UTF-8 with LF for a new program."""
        return self.source.form if self.source is not None else TextForm()

    def sections(self) -> list[Section]:
        """Every section other than the ladder, in file order."""
        return [*self.before, *self.after]

    def instructions(self) -> list[Instruction]:
        """Every instruction in order."""
        return [ins for net in self.networks for ins in net.instructions]

    def step_count(self) -> int:
        """Number of instructions (PLC steps)."""
        return sum(len(net.instructions) for net in self.networks)
