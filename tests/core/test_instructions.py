"""Tests for the instruction table."""

from ladderworks.core import instructions as it


def test_counts() -> None:
    assert len(it.BASIC) == 14  # the seed's 12 and FANUC's SET/RST
    assert len(it.SEED_FUNCTIONS) == 38
    assert len(it.PMC_FUNCTIONS) == 27
    assert {s.name for s in it.ENDS} == {"END1", "END2", "END3", "END"}


def test_manual_order_lists_every_function_once() -> None:
    assert sorted(it.MANUAL_ORDER) == sorted(s.name for s in it.SEED_FUNCTIONS)
    assert sorted(it.PMC_ORDER) == sorted(s.name for s in it.PMC_FUNCTIONS)


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
            assert spec.flow is not it.Flow.NONE, spec.name  # structure: JMPE, SP, LBL, ...


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


def test_meaning_is_on_the_table() -> None:
    rd_not = it.BY_NAME["RD.NOT.STK"]
    assert (rd_not.combine, rd_not.negated, rd_not.pushes) == (it.Combine.READ, True, 1)
    assert it.BY_NAME["SET"].write is it.Write.SET and it.BY_NAME["RST"].is_coil
    assert it.BY_NAME["WRT.NOT"].negated and not it.BY_NAME["WRT"].negated
    assert len({s.opcode for s in it.BASIC}) == len(it.BASIC)
    assert it.BY_SUB[65].flow is it.Flow.CALL and it.BY_SUB[2].level == 2
    assert it.BY_MNEMONIC["AND"].name == "LOGAND" and it.BY_SUB[60].text_name == "AND"


def test_fanuc_programs_have_the_30i_ranges() -> None:
    timer = it.BY_NAME["TMR"].param("timer")
    assert (timer.highest("seed"), timer.highest("fanuc")) == (100, 250)
    assert it.BY_NAME["CTR"].param("counter").highest("fanuc") == 100


def test_an_unknown_sub_keeps_its_parameters() -> None:
    spec = it.spec_for("SUB.300", 3)
    assert spec is not None and not spec.known and spec.sub == 300
    assert [p.kind for p in spec.params] == [it.ParamKind.RAW] * 3
    assert spec.inputs == ("ACT",) and spec.w1
