"""The boxes a Delta/Fatek program's palette offers, and their operands read by the reader."""

from __future__ import annotations

from ladderworks.core.dialects import parse_target
from ladderworks.core.dialects.fatek.rows import NIBBLE_ROWS, TABLE_ROWS, WIDE_ROWS, WORD_ROWS
from ladderworks.core.dialects.functions import (
    check_params,
    contact_rows,
    operand_params,
    operand_texts,
    palette_groups,
    palette_rows,
    same_operation,
    structure_rows,
)
from ladderworks.core.instructions import lookup


def test_delta_offers_boxes_not_contacts_nor_structure() -> None:
    names = [spec.name for spec in palette_rows("delta")]
    assert "DVP.TMR" in names and "DVP.MOVP" in names
    assert not {"DVP.LD=", "DVP.LDP", "DVP.CJ", "DVP.CALL", "DVP.MC"} & set(names)
    assert palette_rows("seed") == () and palette_rows(None) == ()


def test_delta_offers_structure_and_one_contact_per_operation() -> None:
    assert [spec.name for spec in structure_rows("delta")] == [
        "DVP.CJ", "DVP.CALL", "DVP.SRET", "DVP.FEND", "DVP.P", "DVP.P.SUB", "DVP.MC", "DVP.MCR",
        "DVP.RET", "END"]  # not STL: read with its LD Sn; END last
    contacts = contact_rows("delta")
    assert [spec.name for spec in contacts] == [
        "DVP.LDP", "DVP.LDF", "DVP.LD=", "DVP.LD>", "DVP.LD<", "DVP.LD<>", "DVP.LD<=",
        "DVP.LD>=", "DVP.DLD=", "DVP.DLD>", "DVP.DLD<", "DVP.DLD<>", "DVP.DLD<=",
        "DVP.DLD>=", "DVP.FLD=", "DVP.FLD>", "DVP.FLD<", "DVP.FLD<>", "DVP.FLD<=",
        "DVP.FLD>="]  # the READ form: coding picks AND=/OR=/LD= .STK by the place; 32-bit apart
    equal = lookup("DVP.LD=")
    assert equal is not None
    assert [s.text_name for s in same_operation(equal)] == ["LD=", "AND=", "OR="]
    wide = lookup("DVP.DAND=")
    assert wide is not None
    assert [s.text_name for s in same_operation(wide)] == ["DLD=", "DAND=", "DOR="]
    assert [key for key, _rows in palette_groups("delta")] == [
        "delta", "delta.structure", "delta.contacts"]
    assert palette_groups("seed") == ()


def test_fatek_offers_fun_boxes_rst_and_edge_contacts() -> None:
    names = [spec.name for spec in palette_rows("fatek")]
    assert names == ["FBS.TMR", "FBS.CTR", "FBS.UDCTR", "FBS.RST", "FBS.MOV", "FBS.ADD",
                     "FBS.SUB", "FBS.MUL", "FBS.DIV", "FBS.INC", "FBS.DEC", "FBS.CMP",
                     "FBS.BCD", "FBS.BIN", *(spec.name for spec in WORD_ROWS),
                     *(spec.name for spec in (*NIBBLE_ROWS, *WIDE_ROWS, *TABLE_ROWS)),
                     "FBS.ASCWR"]
    # not FUN 140-143/176, nor an unknown FUN's box (FBS.FUN): kept, not simulated
    assert [spec.name for spec in contact_rows("fatek")] == [  # the rows that start a rung
        f"FBS.{name}.ORG" for name in ("TU", "TD", "EQ", "GT", "LT", "NE", "GE", "LE")]
    assert structure_rows("fatek") == ()
    spec = lookup("FBS.TMR")
    assert spec is not None
    assert [p.name for p in operand_params(spec)] == ["timer", "preset"]  # no FO byte
    add = lookup("FBS.ADD")
    assert add is not None
    assert [p.name for p in operand_params(add)] == ["mode", "Sa", "Sb", "output"]


def test_fatek_operands_read_as_listing_lines() -> None:
    add, reset, edge, mov = (lookup(n) for n in ("FBS.ADD", "FBS.RST", "FBS.TU", "FBS.MOV"))
    assert add is not None and reset is not None and edge is not None and mov is not None
    params, problems = check_params(add, ["P", "R0", "7", "R1"], "fatek")
    assert problems == [] and params is not None
    assert params[:4] == (1, parse_target("R0", "fatek")[0], 7, parse_target("R1", "fatek")[0])
    assert operand_texts(add, params) == ["P", "R0", "7", "R1"]
    params, problems = check_params(reset, ["C3"], "fatek")
    assert problems == [] and params == (1, 3) and operand_texts(reset, params) == ["C3"]
    params, problems = check_params(edge, ["X1"], "fatek")
    assert problems == [] and params == (parse_target("X1", "fatek")[0],)
    params, problems = check_params(mov, ["", "7", "X0"], "fatek")
    assert params is None and problems[0].args["index"] == 3  # the D line's row


def test_delta_structure_operands() -> None:
    for name, texts, spelled in (("DVP.CJ", ["P1"], ["P1"]), ("DVP.P.SUB", ["P2"], ["P2"]),
                                 ("DVP.MC", ["N0"], ["N0"]), ("DVP.FEND", [], []),
                                 ("DVP.LD<>", ["T0", "K5"], ["T0", "K5"])):
        spec = lookup(name)
        assert spec is not None
        params, problems = check_params(spec, texts, "delta")
        assert problems == [] and params is not None, name
        assert operand_texts(spec, params) == spelled
    mc = lookup("DVP.MC")
    assert mc is not None
    assert check_params(mc, ["0"], "delta")[1][0].code == "dialect-operand"  # N0, not 0


def test_operands_are_read_as_the_file_would_be() -> None:
    spec = lookup("DVP.MOV")
    assert spec is not None
    params, problems = check_params(spec, ["K5", "D10"], "delta")
    assert problems == [] and params == (5, parse_target("D10", "delta")[0])
    params, problems = check_params(spec, ["K5", "X0"], "delta")
    assert params is None and problems[0].code == "dialect-operand"
    timer = lookup("DVP.TMR")
    assert timer is not None
    assert check_params(timer, ["T0"], "delta")[1][0].code == "param-count"
