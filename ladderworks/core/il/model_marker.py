"""The PMC model kept in the file: a comment line the seed's own tools skip (docs/file-format.md).

A `.LAD` is a seed LadderWorks program unless it has the LADDER-III framing (`%@A`) or
network labels (`N00012:`), which make it a FANUC 30i program. A program whose model differs
from that default carries one comment line before its first section:
`// LADDERWORKS PMC MODEL: fanuc` (`;` in a framed file). A file without it is unchanged."""

from __future__ import annotations

import re
from collections.abc import Sequence

from ladderworks.core.il.program import FANUC, SEED, Program
from ladderworks.core.models import FANUC_PMC, MODELS, model_of

MARKER = "LADDERWORKS PMC MODEL: {0}"
_MARKER_RE = re.compile(r"^\s*(//|;|,)\s*LADDERWORKS PMC MODEL:\s*(\S+)\s*$", re.IGNORECASE)


def marked_model(lines: Sequence[str]) -> str | None:
    """The model a marker line among `lines` (those before the ladder) names, if any."""
    for line in lines:
        if "MODEL" in line.upper():
            match = _MARKER_RE.match(line)
            if match and match.group(2).lower() in MODELS:  # an unknown one is a comment
                return match.group(2).lower()
    return None


def framing_model(program: Program) -> str:
    """The model the file's framing gives without a marker (another family's program, a
    Delta or Fatek one: its own, so it never carries the marker)."""
    if model_of(program.dialect).family != FANUC_PMC:
        return program.dialect
    return FANUC if program.framed or any(n.label for n in program.networks) else SEED


def _marker_line(program: Program, mark: str = "") -> str:
    """The marker line for the program's model."""
    mark = mark or (";" if program.framed else "//")
    return f"{mark} {MARKER.format(program.dialect)}"


def header_texts(program: Program) -> list[str]:
    """The header comment texts for the canonical print: the marker (when needed) first, an
    old marker dropped."""
    texts = [t for t in program.header if not _MARKER_RE.match("//" + t)]
    if program.dialect != framing_model(program):
        texts.insert(0, " " + MARKER.format(program.dialect))
    return texts


def head_lines(program: Program, lines: Sequence[str], ends: Sequence[str],
               newline: str) -> list[str]:
    """The lines before the ladder as Save writes them (with their ends): as read, with the
    marker added, changed or dropped only when it no longer says the program's model."""
    out = [line + end for line, end in zip(lines, ends, strict=True)]
    at = next((i for i, line in enumerate(lines) if _MARKER_RE.match(line)), None)
    needed = program.dialect != framing_model(program)
    if at is not None:
        match = _MARKER_RE.match(lines[at])
        assert match is not None
        if match.group(2).lower() == program.dialect:
            return out
        if needed:
            out[at] = _marker_line(program, match.group(1)) + ends[at]
        else:
            del out[at]
    elif needed:
        out.insert(0, _marker_line(program) + newline)
    return out
