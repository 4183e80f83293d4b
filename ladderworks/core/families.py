"""PLC families for File › New and Program properties: a new program of a model, and a
program moved to another family's model when its instructions read back the same there."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import FANUC, Instruction, Network, Program
from ladderworks.core.instructions import BY_NAME, Flow, InstructionSpec, lookup
from ladderworks.core.models import FANUC_PMC, MODELS, PmcModel


@dataclass(frozen=True, slots=True)
class Family:
    """A PLC family: its key (`PmcModel.family`), English title and its models."""

    key: str
    title: str
    title_tr: str
    models: tuple[PmcModel, ...]


def families() -> list[Family]:
    """Every family with its models, the PMC's first (the order File › New lists them)."""
    grouped: dict[str, list[PmcModel]] = {}
    for model in MODELS.values():
        grouped.setdefault(model.family, []).append(model)
    found = []
    for key, models in grouped.items():
        dialect = dialects.get(key)
        title = dialect.title if dialect is not None else "LadderWorks / FANUC PMC"
        title_tr = dialect.title_tr if dialect is not None else "LadderWorks / FANUC PMC"
        found.append(Family(key, title, title_tr, tuple(models)))
    return sorted(found, key=lambda family: family.key != FANUC_PMC)


def program_end(dialect: str) -> InstructionSpec | None:
    """The table's END row when a program of `dialect` holds it as an instruction of its own
    (Delta's END; a Fatek listing's END is written by its printer; a PMC program's END)."""
    found = dialects.get(dialect)
    for spec in list(BY_NAME.values()):
        if spec.flow is Flow.PROGRAM_END and not spec.dialect:
            if found is None:
                return spec
            from ladderworks.core.il.reading import parse_text

            result = parse_text(found.instruction_name(spec) + "\n", found.name)
            if any(i.name == spec.name for i in result.program.instructions()):
                return spec
    return None


def new_program(key: str) -> Program:
    """An empty program of model `key`: a Delta program holds its END (kept last)."""
    program = Program(dialect=key)
    end = program_end(key) if dialects.get(key) is not None else None
    if end is not None:
        program.networks = [Network([Instruction(end.name)])]
    return program


def _ends(network: Network) -> bool:
    """True for a network that is the program's END alone."""
    specs = [lookup(i.name) for i in network.instructions]
    return len(specs) == 1 and specs[0] is not None and specs[0].flow is Flow.PROGRAM_END


def _steps(program: Program) -> list[tuple[str, object, object]]:
    """What a program does, instruction by instruction (END networks left out)."""
    return [(i.name, i.operand, i.params) for network in program.networks
            if not _ends(network) for i in network.instructions]


def change_family(program: Program, key: str) -> Program | Diagnostic:
    """`program` as a program of model `key` of another family, written in that family's text
    and read back; the reader's first error, or `family-differs` at the first instruction that
    does not read back the same, when its instructions do not carry over."""
    from ladderworks.core.il.printer import print_program
    from ladderworks.core.il.reading import parse_text

    networks = [Network(list(n.instructions), list(n.comments)) for n in program.networks
                if not _ends(n)]
    moved = Program(networks=networks, dialect=key)
    end = program_end(key) if dialects.get(key) is not None else None
    if end is not None:
        moved.networks.append(Network([Instruction(end.name)]))
    if program.symbols is not None and len(program.symbols) and dialects.get(key) is not None:
        return Diagnostic("family-symbols", {"count": len(program.symbols)})
    text = print_program(moved)
    target = dialects.get(key)
    result = parse_text(text, target.name if target is not None else
                        (FANUC if key == FANUC else None))
    errors = [d for d in result.diagnostics if d.is_error]
    if errors:
        return errors[0]
    before, after = _steps(program), _steps(result.program)
    for index, step in enumerate(before):
        if index >= len(after) or after[index] != step:
            spec = lookup(step[0])
            source = dialects.get(program.dialect)
            name = (source.instruction_name(spec) if source is not None and spec is not None
                    else step[0])
            return Diagnostic("family-differs", {"name": name, "step": index + 1})
    if len(after) != len(before):
        return Diagnostic("family-differs", {"name": "END", "step": len(before) + 1})
    result.program.source = None
    return result.program
