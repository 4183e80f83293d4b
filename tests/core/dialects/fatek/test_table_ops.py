"""The table FUNs added for issue 37, from key-in listings, fast and monitored: FUN 102 T->T,
105 R-T_S, 106 T-T_C, 108 T_SHF, 109 T_ROT, 110 QUEUE, 111 STACK, 113 SORT; the FBs manual's
own examples (pp. 7-95, 7-97, 7-100) where it gives one; P and D forms, FO flags, and each box
drawn with its inputs and FO pins coded back to the same instructions."""

from __future__ import annotations

from ladderworks.core.dialects.functions import check_params, operand_texts
from ladderworks.core.instructions import lookup
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from tests.core.dialects.fatek.test_families import MODES, get, plc, put, scan
from tests.core.dialects.fatek.test_programs import fatek

FO3 = "FO 0\nOUT Y0\nFO 1\nOUT Y1\nFO 2\nOUT Y2\n"


def _regs(engine: object, first: int, count: int) -> list[int]:
    return [get(engine, f"R{first + k}") for k in range(count)]  # type: ignore[arg-type]


@MODES
def test_sort_as_the_manuals_example(monitored: bool) -> None:
    """p. 7-100: R0-R9 sorted ascending (A/D = 1) into R10-R19; A/D = 0 descending; L outside
    2-127 is ERR, nothing written."""
    engine = plc("ORG X0\nLD X1\nFUN 113P SORT\n S : R0\n D : R10\n L : R30\nFO 0\nOUT Y0\n",
                 monitored)
    values = [1547, 2314, 7725, 13, 5247, 1925, 6744, 5319, 9788, 2796]
    for k, value in enumerate(values):
        put(engine, f"R{k}", value)
    put(engine, "R30", 10)
    scan(engine, X0=1, X1=1)
    assert _regs(engine, 10, 10) == sorted(values) and get(engine, "Y0") == 0
    assert _regs(engine, 0, 10) == values  # S is not changed
    scan(engine, X0=0, X1=0)
    scan(engine, X0=1)
    assert _regs(engine, 10, 10) == sorted(values, reverse=True)
    put(engine, "R30", 128)
    put(engine, "R10", -1)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert get(engine, "Y0") == 1 and get(engine, "R10") == -1
    put(engine, "R30", 1)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert get(engine, "Y0") == 1 and get(engine, "R10") == -1


@MODES
def test_sort_in_the_d_form_sorts_register_pairs(monitored: bool) -> None:
    engine = plc("ORG X0\nLD SHORT\nFUN 113D SORT\n S : R0\n D : R10\n L : 3\n", monitored)
    for k, value in enumerate((70000, -5, 65536)):
        put(engine, f"R{2 * k}", value & 0xFFFF)
        put(engine, f"R{2 * k + 1}", value >> 16)
    scan(engine, X0=1)
    pairs = [(get(engine, f"R{10 + 2 * k}") & 0xFFFF) | (get(engine, f"R{11 + 2 * k}") << 16)
             for k in range(3)]
    assert pairs == [-5, 65536, 70000]


@MODES
def test_stack_as_the_manuals_example(monitored: bool) -> None:
    """p. 7-97: IW R0, ST from R2, L 10, Pr R1 = 4 (ST1-ST4 = 1111-4444): a push (I/O = 1) puts
    5555 in ST5 (R6), Pr 5; a pop moves it to OW R20, Pr 4."""
    engine = plc("ORG X0\nLD X1\nFUN 111P STACK\n IW : R0\n ST : R2\n L : 10\n Pr : R1\n"
                 " OW : R20\n" + FO3, monitored)
    for k, value in enumerate((1111, 2222, 3333, 4444)):
        put(engine, f"R{2 + k}", value)
    put(engine, "R1", 4)
    put(engine, "R0", 5555)
    scan(engine, X0=1, X1=1)
    assert (get(engine, "R6"), get(engine, "R1")) == (5555, 5)
    scan(engine, X0=0, X1=0)
    scan(engine, X0=1)
    assert (get(engine, "R20"), get(engine, "R1")) == (5555, 4)
    assert [get(engine, y) for y in ("Y0", "Y1", "Y2")] == [0, 0, 0]
    for _ in range(4):
        scan(engine, X0=0)
        scan(engine, X0=1)
    assert (get(engine, "R20"), get(engine, "R1"), get(engine, "Y0")) == (1111, 0, 1)  # EPT
    scan(engine, X0=0)
    scan(engine, X0=1)  # a pop on an empty stack is not done
    assert (get(engine, "R20"), get(engine, "R1"), get(engine, "Y0")) == (1111, 0, 1)


@MODES
def test_queue_as_the_manuals_example(monitored: bool) -> None:
    """p. 7-95: QU from R2, Pr R1 = 4 (QU1-QU4 = 4444-1111, the oldest at Pr): a push moves
    them up and takes IW as QU1, Pr 5; a pop moves the oldest (1111) to OW R20, Pr 4."""
    engine = plc("ORG X0\nLD X1\nFUN 110P QUEUE\n IW : R0\n QU : R2\n L : 10\n Pr : R1\n"
                 " OW : R20\n" + FO3, monitored)
    for k, value in enumerate((4444, 3333, 2222, 1111)):
        put(engine, f"R{2 + k}", value)
    put(engine, "R1", 4)
    put(engine, "R0", 5555)
    scan(engine, X0=1, X1=1)
    assert _regs(engine, 2, 5) == [5555, 4444, 3333, 2222, 1111] and get(engine, "R1") == 5
    scan(engine, X0=0, X1=0)
    scan(engine, X0=1)
    assert (get(engine, "R20"), get(engine, "R1")) == (1111, 4)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert get(engine, "R20") == 2222  # first in, first out


@MODES
def test_queue_full_and_pointer_error(monitored: bool) -> None:
    engine = plc("ORG X0\nLD SHORT\nFUN 110 QUEUE\n IW : R0\n QU : R2\n L : 2\n Pr : R1\n"
                 " OW : R20\n" + FO3, monitored)
    put(engine, "R0", 7)
    scan(engine, X0=1)
    scan(engine)
    assert (get(engine, "R1"), get(engine, "Y0"), get(engine, "Y1")) == (2, 0, 1)  # FUL
    put(engine, "R0", 8)
    scan(engine)  # a push on a full queue is not done
    assert _regs(engine, 2, 2) == [7, 7] and get(engine, "Y1") == 1
    put(engine, "R1", 3)
    scan(engine)
    assert [get(engine, y) for y in ("Y0", "Y1", "Y2")] == [0, 0, 1]  # ERR
    assert _regs(engine, 2, 3) == [7, 7, 0]


@MODES
def test_table_compare_finds_pairs_step_by_step(monitored: bool) -> None:
    """p. 7-90: from Pr + 1 (or the head with FHD = 1, or after the end), the first pair that
    differs (D/S = 1) or is equal (D/S = 0): Pr := it, FND; the last pair reached: END, Pr
    stays at L - 1; Pr out of range: ERR, nothing done."""
    engine = plc("ORG X0\nLD X1\nLD X2\nFUN 106P T-T_C\n Ta : R0\n Tb : R10\n L : 5\n"
                 " Pr : R20\n" + FO3, monitored)
    for k, (a, b) in enumerate(((1, 1), (2, 9), (3, 3), (4, 8), (5, 5))):
        put(engine, f"R{k}", a)
        put(engine, f"R{10 + k}", b)
    steps = []
    for _ in range(4):
        scan(engine, X0=1, X1=0, X2=1)
        steps.append((get(engine, "R20"), get(engine, "Y0"), get(engine, "Y1")))
        scan(engine, X0=0)
    assert steps == [(1, 1, 0), (3, 1, 0), (4, 0, 1), (1, 1, 0)]  # after the end: the head
    scan(engine, X0=1, X1=1, X2=0)  # from the head, equal pairs
    assert (get(engine, "R20"), get(engine, "Y0")) == (0, 1)
    scan(engine, X0=0)
    put(engine, "R20", 5)
    scan(engine, X0=1, X1=0)
    assert [get(engine, y) for y in ("Y0", "Y1", "Y2")] == [0, 0, 1]
    assert get(engine, "R20") == 5


@MODES
def test_register_to_table_search(monitored: bool) -> None:
    engine = plc("ORG X0\nLD X1\nFUN 105P R-T_S\n Rs : R30\n Ts : R0\n L : 4\n Pr : R20\n"
                 + FO3, monitored)
    for k, value in enumerate((6, 7, 6, 6)):
        put(engine, f"R{k}", value)
    put(engine, "R30", 6)
    found = []
    for _ in range(4):
        scan(engine, X0=1, X1=0)
        found.append((get(engine, "R20"), get(engine, "Y0"), get(engine, "Y1")))
        scan(engine, X0=0)
    assert found == [(2, 1, 0), (3, 1, 1), (0, 1, 0), (2, 1, 0)]  # the last entry: FND and END
    put(engine, "R30", 9)
    scan(engine, X0=1, X1=1)
    assert (get(engine, "R20"), get(engine, "Y0"), get(engine, "Y1")) == (3, 0, 1)


@MODES
def test_table_to_table_moves_entry_by_entry(monitored: bool) -> None:
    engine = plc("ORG X0\nLD X1\nLD X2\nFUN 102DP T->T\n Ts : R0\n Td : R10\n L : 2\n"
                 " Pr : R20\nFO 0\nOUT Y0\nFO 1\nOUT Y1\n", monitored)
    for k, value in enumerate((1, 2, 3, 4)):
        put(engine, f"R{k}", value)
    scan(engine, X0=1, X1=1)
    assert (_regs(engine, 10, 4), get(engine, "R20"), get(engine, "Y0")) == ([1, 2, 0, 0], 1, 0)
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (_regs(engine, 10, 4), get(engine, "R20"), get(engine, "Y0")) == ([1, 2, 3, 4], 1, 1)
    scan(engine, X0=0, X2=1)  # CLR: Pr := 0, nothing moved
    assert get(engine, "R20") == 0
    put(engine, "R20", 2)
    scan(engine, X0=1, X2=0)
    scan(engine, X0=0)
    assert get(engine, "Y1") == 1


@MODES
def test_table_shift_and_rotate_both_ways(monitored: bool) -> None:
    """Left is toward the higher registers (p. 7-83): L/R = 1 left, 0 right."""
    engine = plc("ORG X0\nLD X1\nFUN 108P T_SHF\n IW : 9\n Ts : R0\n L : 3\n OW : R10\n"
                 "FO 0\nOUT Y0\n"
                 "ORG X2\nLD X3\nFUN 109P T_ROT\n Ts : R20\n L : R30\nFO 0\nOUT Y1\n", monitored)
    for k, value in enumerate((1, 2, 3)):
        put(engine, f"R{k}", value)
        put(engine, f"R{20 + k}", value)
    put(engine, "R30", 3)
    scan(engine, X0=1, X1=1, X2=1, X3=1)
    assert (_regs(engine, 0, 3), get(engine, "R10")) == ([9, 1, 2], 3)
    assert _regs(engine, 20, 3) == [3, 1, 2]
    scan(engine, X0=0, X2=0)
    scan(engine, X0=1, X1=0, X2=1, X3=0)
    assert (_regs(engine, 0, 3), get(engine, "R10")) == ([1, 2, 9], 9)
    assert _regs(engine, 20, 3) == [1, 2, 3]
    put(engine, "R30", 1)
    scan(engine, X2=0)
    scan(engine, X2=1)
    assert get(engine, "Y1") == 1 and _regs(engine, 20, 3) == [1, 2, 3]  # L below 2: ERR


def test_each_box_is_drawn_with_its_inputs_and_coded_back() -> None:
    text = ("ORG X0\nLD X1\nLD X2\nFUN 106P T-T_C\n Ta : R0\n Tb : R10\n L : 5\n Pr : R20\n"
            + FO3 + "ORG X0\nLD X1\nFUN 110 QUEUE\n IW : R0\n QU : R2\n L : 10\n Pr : R1\n"
            " OW : R20\n" + FO3 + "ORG X0\nLD X1\nFUN 113D SORT\n S : R0\n D : R10\n L : 4\n"
            "FO 0\nOUT Y3\n")
    program = fatek(text)
    assert len(program.networks) == 3
    for index, network in enumerate(program.networks):
        net = layout_network(network.instructions)
        assert net.listing is None, network.instructions
        code, problems = network_to_instructions(net, index, "fatek")
        assert code == network.instructions, problems


def test_the_function_dialog_reads_their_operands_as_listing_lines() -> None:
    queue, sort = lookup("FBS.QUEUE"), lookup("FBS.SORT")
    assert queue is not None and sort is not None
    texts = ["P", "R0", "R2", "10", "R1", "R20"]
    params, problems = check_params(queue, texts, "fatek")
    assert problems == [] and params is not None and operand_texts(queue, params) == texts
    params, problems = check_params(sort, ["D", "R0", "7", "4"], "fatek")
    assert params is None and problems[0].args["index"] == 3  # D must be a register


@MODES
def test_block_compare_sets_a_bit_per_zone(monitored: bool) -> None:
    """[chosen] BKCMP: zone k's limits at Ts[2k], Ts[2k + 1]; bit k of D on inside them."""
    engine = plc("ORG X0\nFUN 112 BKCMP\n Rs : R20\n Ts : R0\n L : R21\n D : R10\n"
                 "FO 0\nOUT Y0\n", monitored)
    for k, value in enumerate((0, 10, 5, 15, 20, 30, 9, 1)):  # the last zone is upside down
        put(engine, f"R{k}", value)
    put(engine, "R20", 9)
    put(engine, "R21", 4)
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "Y0")) == (0b0011, 0)
    put(engine, "R20", 25)
    scan(engine)
    assert get(engine, "R10") == 0b0100
    put(engine, "R21", 0)
    scan(engine)
    assert (get(engine, "R10"), get(engine, "Y0")) == (0b0100, 1)


def test_a_queue_with_a_pin_and_its_contact_prints_in_winproladders_form_and_reads_back() -> None:
    from ladderworks.core.dialects.fatek.printed import style_of
    from ladderworks.core.dialects.fatek.printer import network_lines
    from ladderworks.core.il.reading import parse_file
    from tests.core.dialects.fatek.test_printed import EXAMPLE, HEAD

    source = parse_file(EXAMPLE).program.source
    assert source is not None
    style = style_of(source.lines)
    program = fatek("ORG X0\nLD X1\nFUN 110P QUEUE\n IW : R0\n QU : R2\n L : 10\n Pr : R1\n"
                    " OW : R20\n" + FO3.replace("FO 1\nOUT Y1", "FO 1\nAND X3\nOUT Y1"))
    lines = network_lines(program.networks[0], True, style)
    assert "00002M FUN 110 P.QUEUE" in lines and "00006M AND      X3" in lines
    again = fatek(HEAD + "\n".join(lines))
    assert again.networks[0].instructions == program.networks[0].instructions
