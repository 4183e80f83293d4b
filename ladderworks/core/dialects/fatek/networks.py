"""A Fatek listing's networks lowered one by one (lowering.py), each first with its TR branch
points (branch_points.py) and, where they cannot be drawn so, with its TR relays as before."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.branch_points import NoBranch, branch_points, drawn_as_branches
from ladderworks.core.dialects.fatek.branches import BranchError, Lowered, refused, split_networks
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.dialects.fatek.lowering import ProgramLowering, name_of
from ladderworks.core.dialects.fatek.tr_inputs import drop_unread


def _lower_network(network: list[Record], boxes: int, points: dict[int, int]
                   ) -> tuple[ProgramLowering, list[Diagnostic]]:
    """One Fatek network lowered (`points`: its TR points read as branch points), with its
    diagnostics; NoBranch when those points cannot be branches after all."""
    diagnostics: list[Diagnostic] = []
    warnings: list[Diagnostic] = []
    lowering = ProgramLowering(boxes, warnings)
    lowering.branch_points = dict(points)
    lowering.used_tr = {int(r.operand[2:]) for r in network
                        if r.modifier == "TR" and r.operand[2:].isdigit()}
    try:
        for index, record in enumerate(network):
            if record.mnemonic == "END":
                break
            lowering.following = network[index + 1] if index + 1 < len(network) else None
            lowering.ahead, lowering.index = network, index
            lowering.take_record(record)
        if lowering.depth > 1:
            last = network[-1]
            raise refused(last, "fatek-open-block", name=name_of(last), count=lowering.depth - 1)
    except BranchError as error:
        if points:
            raise NoBranch from None  # the error is given by the plain lowering
        diagnostics.append(error.diagnostic)
    if points and (lowering.open_points or not drawn_as_branches(lowering.parts)):
        raise NoBranch
    drop_unread(lowering.parts, lowering.copied)
    return lowering, diagnostics + warnings


def lower_program(records: list[Record]) -> tuple[list[Lowered], list[Diagnostic]]:
    """Every network of the listing as engine networks, and the diagnostics (one error per
    network at most, at the record that caused it; warnings for what is not simulated)."""
    parts: list[Lowered] = []
    diagnostics: list[Diagnostic] = []
    boxes = 0
    for network in split_networks(records):
        points = branch_points(network)
        try:
            lowering, found = _lower_network(network, boxes, points)
        except NoBranch:
            lowering, found = _lower_network(network, boxes, {})
        diagnostics.extend(found)
        boxes = lowering.boxes
        parts.extend(part for part in lowering.parts if part.instructions)
    return parts, diagnostics
