"""The compiler's checks give the same diagnostics on the real programs as when they were made
single-pass (issue #13): a digest of every diagnostic (code, line, column, arguments, severity,
network) under the program's own dialect and the seed and FANUC overrides.

A change that means to change these diagnostics updates the digests (print them with
`_digest`); an optimisation never does. (Issue 30, item 9: the seed override now checks the
seed's address map too; the program's own and the FANUC digests did not change.)"""

from __future__ import annotations

import hashlib

import pytest

from ladderworks.core.compiler import check
from ladderworks.core.il import parse_bytes
from tests.real_programs import real_bytes

PINNED = {
    "FANUC_STUDER_X22_P036": "ee3efa440cd63bc6",
    "FANUC_STUDER_S41_F036": "d099f18d9bf068e2",
    "FANUC_STUDER_S41_F034": "2286e6df42f66a68",
    "FANUC_X22_FRAG_END2_FIRST_SUBPROGRAM": "0b19c9903dbb086e",
    "FANUC_X22_FRAG_LEVEL1": "0a08a6f79aae4e4e",
    "FANUC_X22_FRAG_fc62180_DECODE_MSTB": "783cea512347b783",
    "FANUC_X22_FRAG_fc62196_RESET_EVENT": "6d63b8492f7541f2",
    "FANUC_X22_FRAG_fc62199_EMERGENCY_STOP": "91eef454d360e282",
    "FANUC_X22_FRAG_fc62224_DRESSING": "e27991878ef64553",
    "FANUC_X22_FRAG_fc62500_DCS_BASE": "56eb0f3b53e0bd5c",
}


def _digest(data: bytes) -> str:
    """The first 16 hex digits of the SHA-256 of every compile diagnostic of a program."""
    program = parse_bytes(data).program
    digest = hashlib.sha256()
    for dialect in (None, "seed", "fanuc"):
        for d in check(program, dialect):
            digest.update(repr((d.code, d.line, d.column, sorted(d.args.items()),
                                str(d.severity), d.network)).encode())
    return digest.hexdigest()[:16]


@pytest.mark.parametrize("name", sorted(PINNED))
def test_compile_diagnostics_are_unchanged(name: str) -> None:
    assert _digest(real_bytes(name)) == PINNED[name]
