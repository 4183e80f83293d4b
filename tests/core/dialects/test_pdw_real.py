"""The real WinProladder project (../shared/real-programs/fatek/VERTINO_SKO-Program.pdw) read,
checked against facts taken by hand from its PDF printout (VERTINO_SKO-Program.pdf: the ladder
pages' network numbers and first steps, the mnemonic pages, the cross reference) and against
the same machine's comment export. The whole mnemonic was compared line by line with the PDF's
text (pdftotext -layout, spaces ignored): equal, 157 steps, 176 lines (docs/dialects.md)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.dialects.fatek.devices import Device, bit_address
from ladderworks.core.dialects.fatek.pdw_file import read_pdw
from ladderworks.core.il.reading import parse_file
from tests.real_programs import real_programs_dir

# The ladder pages print each network's number and first step: N0000 0000M … N0032 0156M
FIRST_STEPS = (0, 2, 11, 16, 25, 29, 33, 37, 40, 43, 49, 52, 56, 60, 67, 74, 81, 83, 96, 98,
               102, 107, 111, 113, 118, 120, 128, 131, 136, 149, 153, 155, 156)
# A few networks as the mnemonic pages print them (spaces aside)
NETWORKS = {
    0: ["00000M ORG NOT X0", "00001M SET( ) S3"],
    10: ["00049M ORG M400", "00050M AND X3", "00051M T30 .01 R8"],
    15: ["00074M ORG M1924", "00075M OR TU M305", "00076M AND NOT M431", "00077M AND NOT M460",
         "00078M FUN 141.MPARA", "Ps: 1", "SR: R1200", "00079M FO 0", "00080M OUT M468"],
    17: ["00083M ORG S10", "00084M LD S3", "00085M OR NOT X0", "00086M OUT TR 0",
         "00087M AND OPEN", "00088M LD TR 0", "00089M FUN 140.HSPSO", "Ps: 1", "SR: R1300",
         "WR: R1500", "00090M FO 0", "00091M OUT M460", "00092M FO 1", "00093M OUT M462",
         "00094M FO 2", "00095M OUT M461"],
    23: ["00113M ORG S11", "00114M AND M410", "00115M AND TD X1", "00116M AND M420",
         "00117M FUN 15 _.(+1)", ": C0"],
    25: ["00120M ORG S11", "00121M ANDF 171_.>", "Sa: R6", "Sb: 0", "00122M ANDF 174_.>=",
         "Sa: C0", "Sb: R6", "00123M OUT TR 0", "00124M AND SHORT", "00125M SET( ) S12",
         "00126M LD TR 0", "00127M RST( ) S11"],
    32: ["00156M ORG OPEN"],
}


def project() -> Path:
    """The real .pdw (a failure, not a skip, when ../shared is missing)."""
    return real_programs_dir() / "fatek" / "VERTINO_SKO-Program.pdw"


def networks(lines: list[str]) -> list[list[str]]:
    """The listing's lines split at each ORG step (a network starts with ORG), stripped."""
    found: list[list[str]] = []
    for line in lines:
        words = line.split()
        if not words or line.startswith("Printed Item"):
            continue
        if words[0][:1].isdigit() and words[1] == "ORG":
            found.append([])
        found[-1].append(" ".join(words))
    return found


@pytest.fixture(scope="module")
def listing() -> list[list[str]]:
    result = read_pdw(project().read_bytes())
    assert result.error is None, result.error.args_map if result.error else None
    assert result.model == "HB1-14M"
    assert [(unit, len(steps)) for unit, steps in result.units] == [
        ("Main_unit1", 157), ("Sub_unit1", 0)]
    return networks(result.lines)


def test_every_network_starts_at_the_step_the_ladder_pages_print(listing) -> None:
    assert [int(net[0][:5]) for net in listing] == list(FIRST_STEPS)
    assert int(listing[-1][-1][:5]) == 156  # the last step


@pytest.mark.parametrize("number", sorted(NETWORKS))
def test_chosen_networks_equal_the_printed_mnemonic(listing, number: int) -> None:
    assert listing[number] == NETWORKS[number]


def test_the_comments_equal_the_machines_comment_export() -> None:
    export = (real_programs_dir() / "fatek" / "VERTINO_export_comment.txt").read_bytes()
    rows = [line.split("\t") for line in export.decode("cp1250").splitlines()[1:] if line]
    expected = {row[0]: row[1] for row in rows}
    comments = read_pdw(project().read_bytes()).comments
    assert comments == expected
    assert len(comments) == 112
    assert comments["S12"] == "OPÓŹNIENIE" and comments["M1"] == "Bezpieczeństwo a"


def test_the_project_opens_as_a_fatek_program_with_its_symbols() -> None:
    result = parse_file(project())
    assert not [d for d in result.diagnostics if d.code.startswith("pdw-")]
    program = result.program
    assert program.dialect == "fatek"
    assert program.networks  # (how the Fatek reader splits them into engine networks is its own)
    assert program.symbols is not None
    entry = program.symbols.lookup(bit_address(Device("X", 0)))
    assert entry is not None and entry.symbol == "SAFETY_STATUS"
