"""The command line on WinProladder projects: `pdw` prints the decoded listing or the comments;
check and run read a .pdw by its header; a cut file is a diagnostic with its byte offset."""

from __future__ import annotations

from pathlib import Path

from ladderworks.cli import main
from tests.core.dialects.pdw_builder import build
from tests.core.dialects.test_pdw_real import project


def test_pdw_prints_the_listing_and_the_comments(capsys) -> None:
    assert main(["pdw", str(project())]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[:3] == ["Printed Item: Mnemonic - Main_unit1", "", "00000M ORG NOT X0"]
    assert lines[-1] == "00156M ORG OPEN" and len(lines) == 2 + 176
    assert main(["pdw", "--comments", str(project())]) == 0
    comments = capsys.readouterr().out.splitlines()
    assert len(comments) == 112 and "S12\tOPÓŹNIENIE" in comments


def test_pdw_refuses_what_is_not_a_project_or_is_cut(tmp_path: Path, capsys) -> None:
    other = tmp_path / "x.pdw"
    other.write_bytes(b"ORG X0\nOUT Y0\n")
    assert main(["pdw", str(other)]) == 1
    assert "pdw-header not a WinProladder project" in capsys.readouterr().err
    cut = tmp_path / "cut.pdw"
    cut.write_bytes(project().read_bytes()[:0x10230])
    assert main(["pdw", str(cut)]) == 1
    assert capsys.readouterr().err.strip() == (
        f"{cut}:1:1: pdw-truncated the .pdw file is cut short: its record at byte 66084 runs"
        " past the end")
    assert main(["check", str(cut)]) == 1
    assert "pdw-truncated" in capsys.readouterr().out


def test_run_reads_a_project_by_its_header(tmp_path: Path, capsys) -> None:
    path = tmp_path / "machine.bin"  # any name: the header decides
    path.write_bytes(build([0x4000, 0x9001, 0xC100]))
    assert main(["run", str(path), "--set", "X0=1", "--scans", "2", "--print", "Y0"]) == 0
    assert capsys.readouterr().out.splitlines()[0] == "Y0 = 1"
