"""A Fatek program made by File › New saves with END last (WinProladder's listing closes so)
and reads back to the same program; a read listing keeps its own last lines."""

from __future__ import annotations

from ladderworks.core.families import new_program
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes


def test_a_new_program_saves_with_end_last_and_reads_back() -> None:
    program = new_program("fatek")
    assert encode_program(program) == b"END\n"
    program.networks = list(parse_bytes(b"ORG X0\nFUN 18 AND\n Sa : R0\n Sb : 255\n D : R1\n"
                                        b"ORG X1\nOUT Y0\n", "fatek").program.networks)
    data = encode_program(program)
    assert data.decode().splitlines()[-1] == "END" and data.count(b"END") == 1
    again = parse_bytes(data, "fatek")
    assert again.ok and not again.diagnostics
    assert [n.key() for n in again.program.networks] == [n.key() for n in program.networks]
    assert encode_program(again.program) == data


def test_a_read_listing_without_end_saves_as_it_was() -> None:
    data = b"ORG X0\nOUT Y0\n"
    assert encode_program(parse_bytes(data, "fatek").program) == data
