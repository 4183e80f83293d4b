"""The boxes a Delta/Fatek program's palette offers, and their operands read by the reader."""

from __future__ import annotations

from ladderworks.core.dialects import parse_target
from ladderworks.core.dialects.functions import check_params, operand_params, palette_rows
from ladderworks.core.instructions import lookup


def test_delta_offers_boxes_not_contacts_nor_structure() -> None:
    names = [spec.name for spec in palette_rows("delta")]
    assert "DVP.TMR" in names and "DVP.MOVP" in names
    assert not {"DVP.LD=", "DVP.LDP", "DVP.CJ", "DVP.CALL", "DVP.MC"} & set(names)
    assert palette_rows("seed") == () and palette_rows(None) == ()


def test_fatek_offers_its_one_line_boxes() -> None:
    assert [spec.name for spec in palette_rows("fatek")] == ["FBS.TMR", "FBS.CTR"]
    spec = lookup("FBS.TMR")
    assert spec is not None
    assert [p.name for p in operand_params(spec)] == ["timer", "preset"]  # no FO byte


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
