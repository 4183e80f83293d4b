"""Tests for the instruction table."""

from ladderworks.core import instructions as it


def test_counts() -> None:
    assert len(it.BASIC) == 12
    assert len(it.FUNCTIONS) == 38
    assert {s.name for s in it.ENDS} == {"END1", "END2", "END"}


def test_manual_order_lists_every_function_once() -> None:
    assert sorted(it.MANUAL_ORDER) == sorted(s.name for s in it.FUNCTIONS)


def test_sub_numbers_unique_and_fanuc() -> None:
    subs = [s.sub for s in it.FUNCTIONS + it.ENDS]
    assert len(subs) == len(set(subs))
    assert it.BY_NAME["SUB"].sub == 20  # the manual misprints 30; FANUC's number is 20
    assert it.BY_NAME["JMPE"].sub == 30
    assert it.BY_NAME["TMRB"].sub == 24
    assert it.BY_NAME["CTR"].sub == 5


def test_control_inputs_end_with_act() -> None:
    for spec in it.FUNCTIONS:
        if spec.inputs:
            assert spec.inputs[-1] == "ACT", spec.name
        else:
            assert spec.name in ("JMPE", "COME")


def test_tables_name_their_length_param() -> None:
    for spec in it.FUNCTIONS:
        table = spec.table_param()
        if table is not None:
            assert spec.param(table.length_of).kind is it.ParamKind.NUMBER


def test_format_widths_resolve() -> None:
    decb = it.BY_NAME["DECB"]
    assert it.width_of(decb, decb.param("code"), {"format": 4}) == 4
    addb = it.BY_NAME["ADDB"]
    assert it.width_of(addb, addb.param("a"), {"format": 1002}) == 2
    assert it.value_is_address(addb, {"format": 1002}) is True
    assert it.value_is_address(addb, {"format": 2}) is False


def test_every_row_has_titles_and_help_key() -> None:
    for spec in it.ALL:
        assert spec.title and spec.title_tr, spec.name
        assert spec.help_key.startswith("instr-")
    assert it.lookup("rd.not") is it.BY_NAME["RD.NOT"]
