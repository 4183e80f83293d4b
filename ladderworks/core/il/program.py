"""The program model: networks of instructions with their comments and source positions."""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.address import Address
from ladderworks.core.instructions import InstructionSpec, Kind, spec_for

ParamValue = int | Address


@dataclass(frozen=True, slots=True)
class Instruction:
    """One instruction: a mnemonic with its address operand or its parameters."""

    name: str
    operand: Address | None = None
    params: tuple[ParamValue, ...] = ()
    comment: str = ""  # trailing `// ...` comment, stripped: the element's comment
    lead: tuple[str, ...] = ()  # comment lines just before it, inside a network
    line: int = field(default=0, compare=False)
    column: int = field(default=0, compare=False)

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


@dataclass(slots=True)
class Network:
    """A rung: instructions from the first RD to the last coil/function, with its comment lines."""

    instructions: list[Instruction] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)  # comment lines before the network

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Network):
            return NotImplemented
        return self.instructions == other.instructions and self.comments == other.comments

    @property
    def line(self) -> int:
        """Source line of the first instruction (0 if unknown)."""
        return self.instructions[0].line if self.instructions else 0


@dataclass(slots=True)
class Section:
    """A FANUC section other than the ladder (`%@0`..`%@5`), kept verbatim."""

    number: int
    lines: list[str] = field(default_factory=list)  # the body, between `%@n` and `%`


@dataclass(slots=True)
class Program:
    """A whole `.LAD` / `.MOD` file: the ladder section and any other sections."""

    networks: list[Network] = field(default_factory=list)
    header: list[str] = field(default_factory=list)  # comment lines before `%@3`
    trailer: list[str] = field(default_factory=list)  # comment lines after the last network
    before: list[Section] = field(default_factory=list)  # sections before the ladder
    after: list[Section] = field(default_factory=list)  # sections after the ladder
    footer: list[str] = field(default_factory=list)  # comment lines after the last section

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Program):
            return NotImplemented
        return (
            self.networks == other.networks
            and self.header == other.header
            and self.trailer == other.trailer
            and self.footer == other.footer
            and [(s.number, s.lines) for s in self.before]
            == [(s.number, s.lines) for s in other.before]
            and [(s.number, s.lines) for s in self.after]
            == [(s.number, s.lines) for s in other.after]
        )

    def instructions(self) -> list[Instruction]:
        """Every instruction in order."""
        return [ins for net in self.networks for ins in net.instructions]

    def step_count(self) -> int:
        """Number of instructions (PLC steps)."""
        return sum(len(net.instructions) for net in self.networks)
