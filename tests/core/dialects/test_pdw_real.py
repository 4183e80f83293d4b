"""The real WinProladder project (../shared/real-programs/fatek/VERTINO_SKO-Program.pdw) read,
checked against facts taken by hand from its PDF printout (VERTINO_SKO-Program.pdf: the ladder
pages' network numbers and first steps, chosen networks of the mnemonic pages, the whole cross
reference by step: every device of every step) and against the same machine's comment export.
The whole mnemonic was compared line by line with the PDF's text (pdftotext -layout, spaces
ignored): equal, 157 steps, 176 lines (docs/dialects.md)."""

from __future__ import annotations

import re
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


# The printout's cross reference by step ("Contact[No]"): each device's steps by use — a
# contact (NO, NC, TU, TD), a coil, or a function's parameter (SET/RST, FUN operands, a timer's
# preset) — and "Function[No]": each box's steps. Every device the program names is here.
NO, NC, TU, TD, COIL, PARAM = "-||-", "-|/|-", "-|U|-", "-|D|-", "--()", "F_Pa"
CROSS_REFERENCE: dict[str, dict[str, list[int]]] = {
    "X0": {NO: [12, 25, 35, 38, 57], NC: [0, 17, 29, 85, 137]}, "X1": {TD: [115]},
    "X3": {NO: [50, 53]}, "Y1": {COIL: [112]}, "Y4": {COIL: [48]},
    "T10": {NO: [132], PARAM: [73]}, "T30": {NO: [54]},
    "S1": {NO: [56], PARAM: [4, 28, 32]}, "S2": {NO: [30, 37, 60], NC: [26], PARAM: [5, 15, 20]},
    "S3": {NO: [2, 18, 31, 33, 84, 138], NC: [13, 27], PARAM: [1, 36, 82, 100, 154]},
    "S10": {NO: [83], NC: [61], PARAM: [6, 21, 59, 69, 101, 106]},
    "S11": {NO: [107, 113, 118, 120], NC: [62], TU: [67], PARAM: [7, 22, 66, 105, 127]},
    "S12": {NO: [108, 128, 131], NC: [63], PARAM: [8, 23, 70, 125, 135]},
    "S13": {NO: [136], NC: [64], PARAM: [9, 24, 71, 134, 152]},
    "M300": {TU: [11]}, "M301": {NO: [16]}, "M302": {NO: [34]}, "M305": {TU: [75]},
    "M310": {TU: [58]}, "M400": {NO: [40, 43, 49, 52, 129], COIL: [39]},
    "M401": {NO: [109], COIL: [42]}, "M403": {NC: [41, 45], COIL: [55]},
    "M410": {NO: [111, 114], COIL: [110]}, "M420": {NO: [116]}, "M421": {NO: [47]},
    "M431": {NC: [76], COIL: [144]}, "M432": {TU: [149], COIL: [148]},
    "M433": {NO: [153], COIL: [146]}, "M460": {NC: [77], COIL: [91]},
    "M461": {NO: [102], TU: [96], COIL: [95]}, "M462": {NO: [98], COIL: [93]},
    "M468": {NO: [81], COIL: [80]}, "M470": {NO: [14, 65], PARAM: [104]}, "M1924": {NO: [74]},
    "C0": {PARAM: [10, 72, 117, 119, 122]}, "R6": {PARAM: [121, 122]}, "R7": {PARAM: [130]},
    "R8": {PARAM: [51]}, "R100": {PARAM: [119]}, "R1200": {PARAM: [78]},
    "R1300": {PARAM: [89]}, "R1400": {PARAM: [142]}, "R1500": {PARAM: [89]},
    "R1501": {PARAM: [97]}, "R1510": {PARAM: [142]}, "R1511": {PARAM: [151]},
}
FUNCTIONS = {"T10": [130], "T30": [51], "08_.MOV": [97, 119, 151], "15_.(+1)": [117],
             "140.HSPSO": [89, 142], "141.MPARA": [78], "171_.>": [121], "174_.>=": [122]}
_DEVICE = re.compile(r"^[XYMSTCRD]\d+$")


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


def _uses(listing: list[list[str]]) -> tuple[dict[str, dict[str, list[int]]],
                                             dict[str, list[int]]]:
    """The decoded listing's cross reference, as the printout's is made (see CROSS_REFERENCE)."""
    uses: dict[str, dict[str, list[int]]] = {}
    boxes: dict[str, list[int]] = {}
    step = 0

    def use(device: str, kind: str) -> None:
        if _DEVICE.match(device):
            uses.setdefault(device, {}).setdefault(kind, []).append(step)

    for line in (line for net in listing for line in net):
        words = line.split()
        if words[0][:1].isdigit():
            step, name, rest = int(words[0][:5]), words[1], words[2:]
            if name in ("ORG", "LD", "AND", "OR"):
                kind = {"NOT": NC, "TU": TU, "TD": TD}.get(rest[0], NO)
                use(rest[-1], kind)
            elif name == "OUT":
                use(rest[-1], COIL)
            elif name in ("SET(", "RST("):
                use(rest[-1], PARAM)
            elif name in ("FUN", "ANDF"):
                boxes.setdefault("".join(rest), []).append(step)  # `08_.MOV`, `171_.>`
            elif _DEVICE.match(name):  # a timer line: `T30 .01 R8`
                boxes.setdefault(name, []).append(step)
                use(rest[-1], PARAM)
        else:  # an operand line of the box at `step`
            use(words[-1], PARAM)
    return uses, boxes


def test_every_device_is_used_where_the_printouts_cross_reference_says(listing) -> None:
    uses, boxes = _uses(listing)
    assert uses == CROSS_REFERENCE
    assert boxes == FUNCTIONS
