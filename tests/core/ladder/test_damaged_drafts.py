"""A `//@grid` draft that is not a valid drawing is kept as text, reported, and saved unchanged."""

from __future__ import annotations

import pytest

from ladderworks.core.il import parse_bytes
from ladderworks.core.il.printer import encode_program
from ladderworks.core.ladder.convert import damaged_drafts, ladder_to_program, program_to_ladder

GRID = '//@grid LADDERWORKS-GRID 1 '
DAMAGED = [
    GRID + '{"columns": Infinity, "rows": 1}',
    GRID + '{"columns": NaN, "rows": 1}',
    GRID + '{"columns": 8, "rows": 1e400}',
    GRID + '{"columns": 8, "rows": 99999999}',
    GRID + '{"columns": [8], "rows": 1}',
    GRID + '[1, 2]',
    GRID + '{"columns": 8, "rows": 1}\r\n//@grid {"at": [1e308, 0], "kind": "contact"}',
    GRID + '{"columns": 8, "rows": 1}\r\n//@grid {"at": [0, 0], "kind": "box", "name": "TMR",'
    ' "height": 1e9, "pins": [0]}',
    GRID + "[" * 100000,
]


@pytest.mark.parametrize("draft", DAMAGED, ids=range(len(DAMAGED)))
@pytest.mark.parametrize("where", ["before-network", "trailer"])
def test_damaged_draft_is_kept_reported_and_saved_unchanged(draft: str, where: str) -> None:
    body = (f"{draft}\r\nRD X0.0\r\nWRT Y0.0\r\n" if where == "before-network"
            else f"RD X0.0\r\nWRT Y0.0\r\n{draft}\r\n")
    data = ("%@3\r\n" + body + "%@E\r\n").encode()
    result = parse_bytes(data)
    doc = program_to_ladder(result.program)  # never raises
    comments = [*doc.trailer, *(c for net in doc.networks for c in net.comments)]
    assert any(c.startswith("@grid LADDERWORKS-GRID") for c in comments)  # shown as text
    found = damaged_drafts(result.program.source.lines)
    line = 2 if where == "before-network" else 4
    assert [(d.code, d.line) for d in found] == [("damaged-draft", line)]
    program, _diagnostics = ladder_to_program(doc)
    assert encode_program(program) == data


def test_valid_draft_is_not_reported() -> None:
    lines = ["%@3", GRID + '{"columns": 8, "rows": 1}', "RD X0.0", "WRT Y0.0"]
    assert damaged_drafts(lines) == []
