"""Find and replace addresses and symbols across a program (issue 18 item 7)."""

from __future__ import annotations

import pytest

from ladderworks.core.address import AddressError, parse_address
from ladderworks.core.diagnostics import Refused
from ladderworks.core.il import parse, parse_bytes, parse_file, print_program
from ladderworks.core.ladder import FunctionBox, LadderNetwork, convert
from ladderworks.core.ladder.find_replace import (
    OPERAND,
    Found,
    find,
    parse_query,
    replacement_address,
    replacements,
)
from ladderworks.core.symbols import Symbol, SymbolTable
from ladderworks.paths import EXAMPLES
from tests.real_programs import real_bytes

A = parse_address


def _networks(name: str) -> list[LadderNetwork]:
    program = parse_file(EXAMPLES / name).program
    return convert.program_to_ladder(program).networks


def test_a_bit_address_finds_every_contact_and_coil_that_uses_it() -> None:
    networks = _networks("or_double.LAD")
    found = find(networks, parse_query("R1.0"))  # type: ignore[arg-type]
    assert found
    for hit in found:
        element = networks[hit.network].cells[hit.cell]  # type: ignore[index]
        assert element.address == A("R1.0")  # type: ignore[union-attr]
    everywhere = [(i, c) for i, n in enumerate(networks) for c, e in n.cells.items()
                  if getattr(e, "address", None) == A("R1.0")]
    assert [(h.network, h.cell) for h in found] == everywhere


def test_a_byte_finds_its_bits_and_box_parameters() -> None:
    networks = _networks("all_functions.LAD")
    found = find(networks, parse_query("R18"))  # type: ignore[arg-type]
    kinds = {(hit.address, hit.slot == OPERAND) for hit in found}
    assert (A("R18"), False) in kinds  # MOVE's destination parameter
    box = networks[found[0].network].cells[found[0].cell]  # type: ignore[index]
    assert isinstance(box, FunctionBox) and box.name == "MOVE"
    assert all(hit.address.byte_address() == A("R18") for hit in found)


def test_words_find_addresses_and_program_symbols() -> None:
    symbols = SymbolTable()
    symbols.add(A("X21.7"), Symbol("ESKIP", ("SKIP SIGNAL",)))
    network = LadderNetwork()
    from ladderworks.core.ladder import Coil, Contact

    network.cells[(0, 0)] = Contact(A("X21.7"))
    network.cells[(0, 1)] = Contact(A("X2.1"))
    network.cells[(0, network.columns)] = Coil(A("Y21.0"))
    by_symbol = find([network], parse_query("eski", symbols), symbols)  # type: ignore[arg-type]
    assert [h.cell for h in by_symbol] == [(0, 0)]
    exact = parse_query("ESKIP", symbols)
    assert exact is not None and exact.address == A("X21.7")
    by_text = find([network], parse_query("21."), symbols)  # type: ignore[arg-type]
    assert [h.cell for h in by_text] == [(0, 0), (0, network.columns)]
    assert parse_query("   ") is None


def test_replace_gives_edits_that_apply_and_undo() -> None:
    networks = _networks("or_double.LAD")
    before = [n.copy() for n in networks]
    query = parse_query("R1")  # the byte: its bits move, each keeps its bit number
    assert query is not None
    hits = find(networks, query)
    new = replacement_address("R7", query)
    edits = replacements(networks, hits, query, new)
    assert [i for i, _ in edits] == sorted({h.network for h in hits})
    assert networks == before  # nothing applied yet
    undo = [(i, edit.apply(networks[i])) for i, edit in edits]
    assert not find(networks, query)
    moved = find(networks, parse_query("R7"))  # type: ignore[arg-type]
    assert [(h.network, h.cell, h.address.bit) for h in moved] == [
        (h.network, h.cell, h.address.bit) for h in hits]
    for i, edit in undo:
        edit.apply(networks[i])
    assert networks == before


def test_replacement_must_be_an_address_of_the_same_kind() -> None:
    query = parse_query("X1.0")
    with pytest.raises(Refused) as kind:
        replacement_address("R2", query)
    assert kind.value.code == "replace-kind"
    with pytest.raises(AddressError):
        replacement_address("Q1.0", query)
    with pytest.raises(Refused) as words:
        replacement_address("R2.0", parse_query("spindle"))
    assert words.value.code == "replace-needs-address"
    assert "'spindle' is not an address" in words.value.diagnostic.message()
    with pytest.raises(Refused) as same:
        replacement_address("X1.0", query)
    assert same.value.code == "replace-same"


def test_replace_all_then_print_changes_only_those_addresses() -> None:
    program = parse_file(EXAMPLES / "all_functions.LAD").program
    document = convert.program_to_ladder(program)
    query = parse_query("D110")
    assert query is not None
    hits = find(document.networks, query)
    assert len(hits) >= 2
    for index, edit in replacements(document.networks, hits, query, A("D610")):
        edit.apply(document.networks[index])
    text = print_program(convert.ladder_to_program(document)[0])
    code = " ".join(line.split("//")[0].strip() for line in text.splitlines())
    assert "D110" not in code and "NUME 12 D610" in " ".join(code.split())
    assert "TABLE AT D110..D113" in text  # comments are the user's words: kept
    reparsed = parse(text)
    assert reparsed.ok


def test_a_listing_network_is_searched_and_replaced() -> None:
    document = convert.program_to_ladder(parse_bytes(real_bytes("FANUC_STUDER_S41_F036")).program)
    listing = next(i for i, n in enumerate(document.networks) if n.listing is not None)
    network = document.networks[listing]
    assert network.listing is not None
    operand = next(ins.operand for ins in network.listing if ins.operand is not None)
    query = parse_query(str(operand))
    assert query is not None
    hits = [h for h in find(document.networks, query) if h.network == listing]
    assert hits and all(h.cell is None and h.instruction is not None for h in hits)
    kind_of = A("R7999.7") if operand.bit is not None else A("R7999")
    [(index, edit)] = replacements(document.networks, hits, query, kind_of)
    edit.apply(document.networks[index])
    assert not [h for h in find(document.networks, query) if h.network == listing]


def test_the_real_program_finds_a_symbol_everywhere() -> None:
    program = parse_bytes(real_bytes("FANUC_STUDER_X22_P036")).program
    document = convert.program_to_ladder(program)
    query = parse_query("ESKIP", program.symbols)
    assert query is not None and query.address == A("X21.7")
    hits = find(document.networks, query, program.symbols)
    assert hits and all(isinstance(h, Found) and h.address == A("X21.7") for h in hits)
