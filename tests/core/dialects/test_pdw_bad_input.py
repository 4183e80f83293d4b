"""A cut or damaged .pdw: a diagnostic with its byte offset, never an exception or a hang, and
the file never written (docs/dialects.md, ".pdw projects")."""

from __future__ import annotations

import random

import pytest

from ladderworks.core.diagnostics import MESSAGES, Severity
from ladderworks.core.dialects.fatek.pdw_file import read_pdw
from ladderworks.core.dialects.fatek.pdw_records import COMMENT_TAG, records
from ladderworks.core.il.reading import parse_bytes
from tests.core.dialects.pdw_builder import build
from tests.core.dialects.test_pdw_real import project

CODES = {"pdw-header", "pdw-truncated", "pdw-checksum", "pdw-record", "pdw-no-program",
         "pdw-key", "pdw-image", "pdw-program-checksum", "pdw-code", "pdw-operand", "pdw-cut"}
END_RECORD = 0x19094  # the real file's end record (tag FFFF): the 6 bytes after it not read


@pytest.fixture(scope="module")
def real() -> bytes:
    return project().read_bytes()


def test_every_code_has_a_message() -> None:
    assert set(MESSAGES) >= CODES
    assert all("{offset}" in MESSAGES[code] for code in CODES - {"pdw-header"})


def test_every_cut_of_the_real_project_is_reported_at_a_byte_offset(real: bytes) -> None:
    for length in range(len(MAGICAL := real[:33]), len(real)):
        result = read_pdw(real[:length])
        if length >= END_RECORD + 4:
            assert result.error is None, length
            continue
        assert result.error is not None and result.error.code == "pdw-truncated", length
        assert 0 <= result.error.offset <= length
    assert read_pdw(MAGICAL).error is not None


def test_every_cut_of_a_small_project_is_reported(real: bytes) -> None:
    data = build([0x4000, 0xFC82, 0x042B, 0xF51A, 0x1428, 0x15B8, 0x6FFC, 0xC101],
                 {"X0": b"START"})
    whole = read_pdw(data)
    assert whole.error is None and len(whole.units[0][1]) == 5
    for length in range(len(data) - 4):
        result = read_pdw(data[:length])
        assert result.error is not None and result.error.code in CODES, length


def test_cut_bytes_open_as_a_diagnostic_not_a_program(real: bytes) -> None:
    result = parse_bytes(real[:5000])
    assert not result.ok
    first = result.diagnostics[0]
    assert first.code == "pdw-truncated" and first.severity is Severity.ERROR
    assert first.args["offset"] == 0x118  # the program record runs past the cut
    assert "byte 280" in first.message()


def test_seeded_byte_flips_are_caught_or_harmless(real: bytes) -> None:
    rng = random.Random(37)
    found = records(real)
    comments = [(r.offset, r.payload_offset + len(r.payload) + 2) for r in found
                if r.tag == COMMENT_TAG]
    code = range(0x11C + 0x200, 0x11C + 0x200 + 2 * 222)  # the code in the program record
    seen: set[str] = set()
    for _ in range(250):
        data = bytearray(real)
        at = rng.randrange(len(data))
        data[at] ^= rng.randrange(1, 256)
        result = read_pdw(bytes(data))
        if result.error is not None:
            seen.add(result.error.code)
            assert result.error.code in CODES
        if at in code:
            assert result.error is not None
            assert result.error.code == "pdw-program-checksum"
        elif any(start + 4 <= at < end for start, end in comments):
            assert result.error is not None and result.error.code == "pdw-checksum", at
    assert {"pdw-program-checksum", "pdw-checksum"} <= seen


def test_many_flips_at_once_never_raise(real: bytes) -> None:
    rng = random.Random(41)
    for _ in range(60):
        data = bytearray(real[:rng.randrange(0x100, len(real) + 1)])
        for _ in range(rng.randrange(1, 40)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        result = parse_bytes(bytes(data))
        assert result.program is not None


def test_a_pdw_without_erased_memory_cannot_be_unmasked() -> None:
    data = bytearray(build([0x4000, 0xC100]))
    start = 0x100 + 4 + 8 + 11 + 2 + 4  # the program record's payload
    rng = random.Random(5)
    for at in range(start, start + 0xA000):  # every block different: no mask to learn
        data[at] = rng.randrange(256)
    result = read_pdw(bytes(data))
    assert result.error is not None and result.error.code == "pdw-key"
    assert result.error.offset == start - 4
