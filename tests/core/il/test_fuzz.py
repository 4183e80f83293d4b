"""Property tests: the parser returns a program or diagnostics, never raises; printing is stable."""

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.il import parse, print_program
from ladderworks.core.instructions import ALL
from ladderworks.paths import EXAMPLES
from tests.hypothesis_profiles import examples

_NAMES = [spec.name for spec in ALL] + ["SUB", "FOO", "RD.XX"]
_WORDS = st.one_of(
    st.sampled_from(_NAMES),
    st.from_regex(r"[XYFGRADTCKQ][0-9]{1,5}(\.[0-9]{1,2})?", fullmatch=True),
    st.integers(-10**9, 10**9).map(str),
    st.sampled_from(["//", ";", ",", "%", "%@3", "%@1", "!!", "\t", "İŞ", "0011"]),
)
_LINE = st.lists(_WORDS, max_size=6).map(" ".join)
_TEXT = st.lists(_LINE, max_size=30).map("\n".join)
_EXAMPLE_TEXTS = [p.read_text("utf-8") for p in sorted(EXAMPLES.glob("*.LAD"))]


@settings(max_examples=examples(1500), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_TEXT)
def test_random_texts_never_raise(text: str) -> None:
    result = parse(text)
    for diagnostic in result.diagnostics:
        assert diagnostic.line >= 1 and diagnostic.message()
    if result.ok:
        again = parse(print_program(result.program))
        assert again.ok and again.program == result.program


@settings(max_examples=examples(1500), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(_EXAMPLE_TEXTS), st.data())
def test_mutated_examples_never_raise(text: str, data: st.DataObject) -> None:
    chars = list(text)
    for _ in range(data.draw(st.integers(1, 8))):
        position = data.draw(st.integers(0, len(chars)))
        action = data.draw(st.sampled_from(["insert", "delete", "replace"]))
        char = data.draw(st.characters(codec="utf-8"))
        if action == "insert":
            chars.insert(position, char)
        elif chars and position < len(chars):
            if action == "delete":
                del chars[position]
            else:
                chars[position] = char
    result = parse("".join(chars))
    if result.ok:
        assert parse(print_program(result.program)).program == result.program


@settings(max_examples=examples(300), deadline=None)
@given(st.binary(max_size=400))
def test_random_bytes_never_raise(data: bytes) -> None:
    from ladderworks.core.il import parse_bytes

    parse_bytes(data)
