"""Hypothesis strategies: logic blocks, networks and programs in the standard coding."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.il import parse, parse_file, print_program
from ladderworks.core.il.program import Instruction, Network, Program
from ladderworks.core.instructions import ENDS, FUNCTIONS, Write
from ladderworks.core.ladder.logic import Leaf, Logic, Parallel, Rung, Series, code_rung
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"

words = st.text(alphabet="ABCÇĞIİÖŞÜxyz0129 .-=*", min_size=1, max_size=12).map(
    str.strip).filter(bool)
bits = st.builds(Address, st.sampled_from([Area.X, Area.R, Area.F]),
                 st.integers(0, 3), st.integers(0, 7))
outputs = st.builds(Address, st.sampled_from([Area.Y, Area.R, Area.G]),
                    st.integers(0, 3), st.integers(0, 7))
comments = st.one_of(st.just(""), words)
leads = st.one_of(st.just(()), st.lists(words, min_size=1, max_size=2).map(tuple))


def contacts(with_comments: bool = True) -> st.SearchStrategy[Contact]:
    """Contacts on a small set of addresses."""
    if not with_comments:
        return st.builds(Contact, bits, st.booleans())
    return st.builds(Contact, bits, st.booleans(), comments, leads)


def _depth(logic: Logic) -> tuple[int, int, int]:
    """(columns, rows, pushes) of a block in the standard coding."""
    from ladderworks.core.ladder.layout import size
    from ladderworks.core.ladder.logic import code_logic, stack_depth

    w, h = size(logic)
    return w, h, stack_depth(code_logic(logic))


def logic_blocks(leaf: st.SearchStrategy[Contact] | None = None,
                 max_leaves: int = 14) -> st.SearchStrategy[Logic]:
    """Series/parallel blocks (flattened), small enough for the grid and the stack."""
    leaves = st.builds(Leaf, leaf if leaf is not None else contacts())

    def extend(inner: st.SearchStrategy[Logic]) -> st.SearchStrategy[Logic]:
        def combine(kind: str, items: list[Logic]) -> Logic:
            out: list[Logic] = []
            cls = Series if kind == "s" else Parallel
            for item in items:
                out.extend(item.items if isinstance(item, cls) else (item,))
            return cls(tuple(out))

        return st.builds(combine, st.sampled_from("sp"), st.lists(inner, min_size=2, max_size=3))

    return st.recursive(leaves, extend, max_leaves=max_leaves).filter(
        lambda logic: _fits(logic))


def _fits(logic: Logic) -> bool:
    w, h, pushes = _depth(logic)
    return w <= 8 and h <= 12 and pushes <= 6


# One line of text per FANUC PMC instruction (the seed's come from all_functions.LAD).
PMC_EXAMPLES: dict[str, str] = {
    "DIFU": "DIFU 5", "DIFD": "DIFD 6", "MOVB": "MOVB R10 R11", "MOVW": "MOVW D932 R5488",
    "MOVN": "MOVN 4 R10 R20", "MOVD": "MOVD R10 R20", "LOGAND": "AND 1 R10 255 R11",
    "LOGOR": "OR 1001 R10 R12 R11", "EOR": "EOR 1001 D5764 R5242 R5242",
    "NOT": "NOT 1 R14 G12", "TMRBF": "TMRBF 270 30000", "CTRB": "CTRB 2 15",
    "RNGB": "RNGB R1 R2 R3", "RNGW": "RNGW R6056 R6058 R14", "RNGD": "RNGD R1 R5 R9",
    "CALL": "CALL P5", "CALLU": "CALLU P7", "SP": "SP P5", "SPE": "SPE", "JMPB": "JMPB L3",
    "JMPC": "JMPC L4", "LBL": "LBL L3", "AXCTL": "AXCTL 1 R6076", "WINDR": "WINDR R200",
    "WINDW": "WINDW R200", "EXIN": "EXIN R5472", "DISPB": "DISPB 2",
}


@lru_cache(maxsize=1)
def function_examples() -> dict[str, Instruction]:
    """One real instruction per functional instruction (all_functions.LAD, PMC_EXAMPLES)."""
    program = parse_file(EXAMPLES / "all_functions.LAD").program
    found: dict[str, Instruction] = {}
    for ins in program.instructions():
        if ins.spec.kind.value != "basic":
            found.setdefault(ins.name, ins)
    for name, text in PMC_EXAMPLES.items():
        result = parse(f"%@3\n{text}\n%\n")
        assert result.ok, result.diagnostics
        found[name] = result.program.instructions()[0]
    for spec in ENDS:
        found.setdefault(spec.name, Instruction(spec.name))
    return found


def _plain_set_reset(coil: Coil) -> Coil:
    """SET and RST have no inverted form."""
    return coil if coil.write is Write.OUT else Coil(coil.address, False, coil.comment,
                                                     coil.lead, coil.write)


coils = st.builds(Coil, outputs, st.booleans(), comments, leads,
                  st.sampled_from([Write.OUT, Write.OUT, Write.SET, Write.RESET])
                  ).map(_plain_set_reset)
_LOGIC = {True: logic_blocks(contacts(True)), False: logic_blocks(contacts(False))}
_INPUTS = {True: logic_blocks(contacts(True), 4), False: logic_blocks(contacts(False), 4)}
_NAMES = sorted(s.name for s in FUNCTIONS + ENDS)


@st.composite
def rungs(draw: st.DrawFn, with_comments: bool = True) -> Rung:
    """A coil network or a function-box network in the standard coding."""
    if draw(st.integers(0, 3)) > 0:
        logic = draw(_LOGIC[with_comments])
        chain = draw(st.lists(st.tuples(_INPUTS[with_comments],
                                        st.lists(coils, min_size=1, max_size=2)), max_size=2))
        return Rung(logic=logic, coils=draw(st.lists(coils, min_size=1, max_size=3)),
                    chain=chain)
    name = draw(st.sampled_from(_NAMES))
    example = function_examples()[name]
    box = FunctionBox.new(name, example.params, draw(comments) if with_comments else "",
                          draw(leads) if with_comments else ())
    inputs = [draw(_INPUTS[with_comments]) for _ in box.inputs]
    out = draw(st.lists(coils, max_size=2)) if box.has_output else []
    return Rung(box=box, inputs=inputs, coils=out)


@st.composite
def programs(draw: st.DrawFn) -> Program:
    """Whole programs: networks in the standard coding, with network comments."""
    networks = []
    for rung in draw(st.lists(rungs(), min_size=1, max_size=4)):
        networks.append(Network(code_rung(rung), draw(st.lists(words, max_size=2))))
    program = Program(networks, header=draw(st.lists(words, max_size=1)),
                      trailer=draw(st.lists(words, max_size=1)))
    result = parse(print_program(program))  # what a file holding it reads back as
    assert result.ok, result.diagnostics
    return result.program


@st.composite
def stack_code(draw: st.DrawFn, leaves: int = 6) -> list[Instruction]:
    """Logic in any valid stack coding (not only the standard one), ending in one WRT."""

    def build(n: int, push: bool) -> list[Instruction]:
        if n == 1:
            contact = draw(contacts(False))
            name = "RD" + (".NOT" if contact.negated else "") + (".STK" if push else "")
            return [Instruction(name, contact.address)]
        split = draw(st.integers(1, n - 1))
        op = draw(st.sampled_from(["AND", "OR"]))
        out = build(split, push)
        if n - split == 1 and draw(st.booleans()):
            contact = draw(contacts(False))
            out.append(Instruction(op + (".NOT" if contact.negated else ""), contact.address))
        else:
            out.extend(build(n - split, True))
            out.append(Instruction(op + ".STK"))
        return out

    code = build(draw(st.integers(1, leaves)), False)
    code.append(Instruction("WRT", draw(outputs)))
    return code
