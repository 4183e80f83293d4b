"""Time an S7 block's Edit → Save: an SD block of N networks read, drawn, one contact's operand
changed, the drawing rebuilt (the block lowered again) and the file written with that network
spliced in. Prints the figures (seconds); run: python benchmarks/s7_edit_save.py [N]."""

from __future__ import annotations

import sys
import time
from pathlib import Path

from ladderworks.core.dialects.s7 import reader
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.textform import decode_lines
from ladderworks.core.ladder import edits
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder

NETWORK = """    {{ S7_Language := "LAD"; }}
    NETWORK
        RUNG wire#powerrail
            Contact( #In{n} )
            I_Contact( #Stop )
            Coil( #Out{n} )
        END_RUNG
    END_NETWORK
"""


def block(count: int) -> bytes:
    """An OB of `count` networks: In<k> and not Stop drive Out<k> (k: n mod 32, as a block
    has a few dozen members), all in its Temp section."""
    names = [f"In{n}" for n in range(32)] + [f"Out{n}" for n in range(32)] + ["Stop"]
    temp = "".join(f"        {name} : Bool;\n" for name in names)
    body = "".join(NETWORK.format(n=n % 32) for n in range(count))
    text = (f'ORGANIZATION_BLOCK "Main"\n    VAR_TEMP\n{temp}    END_VAR\n\n{body}'
            "END_ORGANIZATION_BLOCK\n")
    return text.encode("utf-8")


def main() -> None:
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 500
    data = block(count)
    start = time.perf_counter()
    text, form, _problems, (lines, ends) = decode_lines(data)
    program, diagnostics = reader.read(text, form, lines, ends)
    assert not diagnostics, diagnostics[:3]
    read = time.perf_counter()
    doc = program_to_ladder(program)
    drawn = time.perf_counter()
    model = program.model
    found = model.operand("#In0")  # type: ignore[union-attr]
    assert isinstance(found, tuple)
    edits.set_operand(doc.networks[count // 2], 0, 0, *found)
    rebuilt, problems = ladder_to_program(doc)
    assert not problems
    rebuilt_at = time.perf_counter()
    out = encode_program(rebuilt)
    saved = time.perf_counter()
    changed = sum(a != b for a, b in zip(data.splitlines(), out.splitlines(), strict=True))
    print(f"{count} networks ({len(data) // 1024} KiB): read {read - start:.3f} s, "
          f"draw {drawn - read:.3f} s, edit + rebuild {rebuilt_at - drawn:.3f} s, "
          f"save {saved - rebuilt_at:.3f} s; lines changed: {changed}")
    Path("/dev/null").write_bytes(out)


if __name__ == "__main__":
    main()
