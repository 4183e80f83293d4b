"""Addresses checked against the map of the program's PMC model: a seed program has the seed
manual's map (no E area, A0-A99, F/G 0-767 …), a FANUC 30i program the 30i's."""

from __future__ import annotations

from ladderworks.core.address import SEED_AREA_RANGES, Address, byte_in_range, format_address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import SEED, Program


def seed_ranges_text(address: Address) -> str:
    """The seed's byte ranges of the address's area as text (`0-99`)."""
    return ", ".join(f"{lo}-{hi}" for lo, hi in SEED_AREA_RANGES[address.area])


def model_problem(address: object, dialect: str) -> Diagnostic | None:
    """Why `address` is not in the map of `dialect` (None when it is)."""
    if dialect != SEED or not isinstance(address, Address) or not byte_in_range(
            address.area, address.byte):
        return None  # the 30i's map: parse_address and the general checks judge it
    ranges = SEED_AREA_RANGES.get(address.area)
    text = format_address(address)
    if ranges is None:
        return Diagnostic("unknown-area", {"text": text, "area": address.area.value})
    if any(lo <= address.byte <= hi for lo, hi in ranges):
        return None
    return Diagnostic("byte-range", {"text": text, "area": address.area.value,
                                     "last": ranges[-1][1], "ranges": seed_ranges_text(address)})


def model_address_problems(program: Program, dialect: str | None = None, *,
                           by_network: bool = False) -> list[Diagnostic]:
    """A diagnostic at each operand or address parameter outside the model's map, at its
    line (and network when `by_network`)."""
    dialect = dialect or program.dialect
    if dialect != SEED:
        return []
    # each distinct address judged once (a program repeats its operands); the walk that
    # places the diagnostics only when one is outside
    every = [ins for network in program.networks for ins in network.instructions]
    distinct: set[object] = {ins.operand for ins in every}
    distinct.update(p for ins in every if ins.params for p in ins.params)
    bad: dict[object, Diagnostic] = {address: problem for address in distinct
           if (problem := model_problem(address, dialect)) is not None}
    if not bad:
        return []
    found: list[Diagnostic] = []
    for index, network in enumerate(program.networks):
        for ins in network.instructions:
            for address in (ins.operand, *ins.params):
                problem = bad.get(address)
                if problem is not None:
                    found.append(Diagnostic(problem.code, problem.args, ins.line,
                                            ins.column or 1,
                                            network=index if by_network else None))
    return found
