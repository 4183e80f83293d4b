"""Fails when a rule (or alternative) of the lark grammar is never exercised by the tests."""

from lark import Tree

from ladderworks.core.il.parser import line_parser
from ladderworks.paths import EXAMPLES
from tests.core.il import cases


def _rule_names() -> set[str]:
    names: set[str] = set()
    for rule in line_parser().rules:
        names.add(rule.alias or rule.origin.name)
    return {n for n in names if not n.startswith("_")}


def _used(texts: list[str]) -> set[str]:
    used: set[str] = set()
    parser = line_parser()
    for text in texts:
        for line in text.splitlines():
            if line.strip().startswith("%"):
                continue
            try:
                tree = parser.parse(line)
            except Exception:
                continue
            used.update(t.data for t in tree.iter_subtrees() if isinstance(t, Tree))
    return {str(n) for n in used}


def test_every_grammar_rule_is_exercised() -> None:
    texts = list(cases.ALL_TEXTS)
    texts += [p.read_text("utf-8") for p in sorted(EXAMPLES.glob("*.LAD"))]
    missing = _rule_names() - _used(texts)
    assert missing == set(), f"grammar rules never exercised by the tests: {sorted(missing)}"
