"""Fuzzing the save of a changed S7 block: random networks of the SD and XML examples changed
(operands renamed, networks dropped, moved or duplicated as new) are written by `save_block`
and read back to the changed graph; the untouched networks' text is kept."""

from __future__ import annotations

import copy
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.s7.graph import End, Operand, OperandKind
from ladderworks.core.dialects.s7.graph_shape import shape
from ladderworks.core.dialects.s7.saving import save_block
from ladderworks.core.dialects.s7.sd_parser import parse_sd
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_writer import write_block
from tests.hypothesis_profiles import examples

ROOT = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7"
_SD = [p.read_bytes() for p in sorted(ROOT.glob("*/Main.s7dcl"))]
_SETTINGS = settings(max_examples=examples(100), deadline=None,
                     suppress_health_check=[HealthCheck.too_slow])


def _change(block, draw: st.DrawFn) -> list[int]:
    """Rename some operands, drop, move or add networks; the indexes changed."""
    networks = list(block.networks)
    changed: set[int] = set()
    for network in networks:
        if draw(st.booleans()):
            for wire in network.wires:
                if wire.source.operand is not None and \
                        wire.source.operand.kind is OperandKind.GLOBAL:
                    wire.source = End(operand=Operand(OperandKind.GLOBAL, ("Değişti ş",)))
                    changed.add(id(network))
                    break
    if len(networks) > 1 and draw(st.booleans()):
        del networks[draw(st.integers(0, len(networks) - 1))]
    if len(networks) > 1 and draw(st.booleans()):
        networks.append(networks.pop(0))
    if networks and draw(st.booleans()):
        fresh = copy.deepcopy(networks[draw(st.integers(0, len(networks) - 1))])
        fresh.line = fresh.end_line = 0
        networks.insert(draw(st.integers(0, len(networks))), fresh)
    block.networks = networks
    return [i for i, n in enumerate(networks) if id(n) in changed or not n.line]


@_SETTINGS
@given(st.sampled_from(_SD), st.data())
def test_a_changed_sd_block_saves_and_reads_back(data: bytes, draw: st.DataObject) -> None:
    block = parse_sd(data.decode("utf-8-sig")).block
    changed = _change(block, draw.draw)
    out = save_block(data, "sd", block, changed)
    again = parse_sd(out.decode("utf-8-sig")).block
    assert [shape(n) for n in again.networks] == [shape(n) for n in block.networks]
    assert out.startswith(data[:data.index(b"NETWORK") - 60])


@_SETTINGS
@given(st.sampled_from(_SD), st.integers(0, 5), st.data())
def test_a_changed_xml_block_saves_and_reads_back(data: bytes, version: int,
                                                  draw: st.DataObject) -> None:
    sd = parse_sd(data.decode("utf-8-sig")).block
    document = write_block(sd, version).encode("utf-8")
    block = read_document(document).blocks[0]
    changed = _change(block, draw.draw)
    out = save_block(document, "xml", block, changed)
    back = read_document(out)
    assert [d for d in back.diagnostics if d.is_error] == []
    assert [shape(n) for n in back.blocks[0].networks] == [shape(n) for n in block.networks]
