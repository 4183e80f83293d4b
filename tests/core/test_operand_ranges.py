"""The operand ranges a dialect's reader takes, as the function dialog shows them; Fatek's
TMR T300 says its range (issue 38, item 8)."""

from __future__ import annotations

from ladderworks.core.dialects.operand_ranges import operand_ranges
from ladderworks.core.il.reading import parse_text


def test_delta_counters_split_at_c200_and_constants_are_k() -> None:
    assert operand_ranges("DVP.CNT", "delta")[0] == ("C0–C199",)
    assert operand_ranges("DVP.DCNT", "delta")[0] == ("C200–C255",)
    assert operand_ranges("DVP.MOV", "delta") == (
        ("K-32768–K32767", "T0–T255", "C0–C255", "D0–D9999"), ("T0–T255", "C0–C255", "D0–D9999"))


def test_fatek_timer_and_its_range_message() -> None:
    assert operand_ranges("FBS.TMR", "fatek")[0] == ("T0–T255",)
    result = parse_text("ORG X0\nTMR T300 50\nEND\n", "fatek")
    assert [(d.code, d.args.get("range")) for d in result.diagnostics if d.is_error] == [
        ("fatek-device-range", "T0-T255")]
