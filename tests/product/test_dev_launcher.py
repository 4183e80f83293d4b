"""tools/dev.py: the project-local environment is installed again only when it has to be."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from tools import dev


def _checkout(tmp_path: Path, pyproject: str = "[project]\nname = 'x'\n") -> Path:
    (tmp_path / "pyproject.toml").write_text(pyproject, "utf-8")
    return tmp_path


def test_no_stamp_means_install(tmp_path: Path) -> None:
    wanted = dev.wanted_install(_checkout(tmp_path), ())
    assert dev.needs_install(tmp_path / "missing.json", wanted)


def test_the_same_pyproject_and_extras_need_nothing(tmp_path: Path) -> None:
    stamp = tmp_path / "stamp.json"
    stamp.write_text(json.dumps(dev.wanted_install(_checkout(tmp_path), ("test",))), "utf-8")
    assert not dev.needs_install(stamp, dev.wanted_install(tmp_path, ("test",)))
    assert not dev.needs_install(stamp, dev.wanted_install(tmp_path, ()))  # run after test


def test_test_tools_are_added_after_a_run_install(tmp_path: Path) -> None:
    stamp = tmp_path / "stamp.json"
    stamp.write_text(json.dumps(dev.wanted_install(_checkout(tmp_path), ())), "utf-8")
    assert dev.needs_install(stamp, dev.wanted_install(tmp_path, ("test",)))


def test_a_changed_pyproject_means_install(tmp_path: Path) -> None:
    stamp = tmp_path / "stamp.json"
    stamp.write_text(json.dumps(dev.wanted_install(_checkout(tmp_path), ("test",))), "utf-8")
    _checkout(tmp_path, "[project]\nname = 'x'\nversion = '2'\n")
    assert dev.needs_install(stamp, dev.wanted_install(tmp_path, ("test",)))
    stamp.write_text("not json", "utf-8")
    assert dev.needs_install(stamp, dev.wanted_install(tmp_path, ()))


def test_a_python_without_ensurepip_is_told_to_install_python3_venv(
        monkeypatch: pytest.MonkeyPatch) -> None:
    real = dev.importlib.util.find_spec
    monkeypatch.setattr(dev.importlib.util, "find_spec",
                        lambda name: None if name == "ensurepip" else real(name))
    problem = dev.venv_problem()
    assert problem is not None and "sudo apt-get install python3-venv" in problem
    assert f"python3.{sys.version_info.minor}-venv" in problem


def test_an_old_python_is_named(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(dev, "MINIMUM", (sys.version_info.major, sys.version_info.minor + 1))
    problem = dev.venv_problem()
    assert problem is not None and sys.executable in problem


def test_test_runs_ruff_mypy_then_the_whole_suite_in_parallel_and_run_starts_the_ide() -> None:
    python = Path("venv/bin/python")
    ruff, mypy, pytest_run = dev.commands(python, "test", [])
    assert ruff == [str(python), "-m", "ruff", "check", "ladderworks", "tests", "benchmarks",
                    "tools"]
    assert mypy == [str(python), "-m", "mypy", "ladderworks"]
    assert pytest_run == [str(python), "-m", "pytest", "-q", "-n", "auto"]  # pytest-xdist
    assert dev.commands(python, "run", ["a.LAD"]) == [[str(python), "-m", "ladderworks", "a.LAD"]]
    assert dev.EXTRAS["run"] == () and dev.EXTRAS["test"] == ("test",)


def test_an_unknown_command_prints_the_usage(capsys: pytest.CaptureFixture[str]) -> None:
    assert dev.main(["deploy"]) == 1
    assert "usage: python3 tools/dev.py run|test" in capsys.readouterr().err


def test_bench_and_product_name_the_checkout_s_scripts() -> None:
    python = Path("py")
    benches = dev.commands(python, "bench", [])
    assert benches and all(Path(script).parent == dev.CHECKOUT / "benchmarks"
                           for _py, script in benches)
    assert dev.commands(python, "product", []) == [
        ["py", str(dev.CHECKOUT / "tools" / "product_check.py")]]
