"""The literal prefilter must never change a result: checked against the raw regex on every dev sentence."""

from __future__ import annotations

import importlib
import json
import re

import pytest

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.text.fastre import Gated, LazyPattern, build_all, end_gate, factors_of, folded, gate, twin, word_scanner, wordcase
from txt2sce_ros.text.mentions import normalise, sentences

_MODULES = ("lexicon", "mentions", "actions", "story", "sequences", "scene")


def _gated_patterns() -> list[tuple[str, Gated]]:
    """The extractor's gated patterns: module-level ones, and the inline ones an extraction over dev cached."""
    from txt2sce_ros.text import fastre
    from txt2sce_ros.text.extractor import extract

    for row in _dev_rows()[:60]:
        extract(row["text"], row["id"])
    out: list[tuple[str, Gated]] = [(f"inline {p!r}", g) for (p, _), g in fastre._CACHE.items() if isinstance(g, Gated)]
    for name in _MODULES:
        mod = importlib.import_module(f"txt2sce_ros.text.{name}")
        for key, val in vars(mod).items():
            items = val if isinstance(val, (list, tuple)) else [val]
            for k, item in enumerate(items):
                if isinstance(item, tuple) and len(item) == 2:
                    item = item[1]
                if isinstance(item, LazyPattern):
                    item = item.built()
                if isinstance(item, Gated):
                    out.append((f"{name}.{key}[{k}]", item))
    return out


def _dev_rows() -> list[dict[str, str]]:
    path = shared_dir() / "data" / "reports" / "dev.jsonl"
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


@pytest.fixture(scope="module")
def texts() -> list[str]:
    out: list[str] = []
    for r in _dev_rows():
        t = normalise(r["text"])
        out += [r["text"], t] + sentences(t)
    return out


def test_most_extractor_patterns_are_gated() -> None:
    gated = _gated_patterns()
    assert len(gated) >= 100, [n for n, _ in gated]
    assert sum(g.cs is not None for _, g in gated) >= 100  # and scanned case-folded


def test_gated_patterns_agree_with_the_raw_regex_on_dev(texts: list[str]) -> None:
    skipped = 0
    for name, g in _gated_patterns():
        for s in texts:
            raw = [m.span() for m in g.rx.finditer(s)]
            assert [m.span() for m in g.finditer(s)] == raw, (name, s)
            assert (g.search(s) is None) == (not raw), (name, s)
            assert g.sub("#", s) == g.rx.sub("#", s), (name, s)
            if raw:  # a template with a reference, and a callback
                assert g.sub(r"<\g<0>>", s) == g.rx.sub(r"<\g<0>>", s), (name, s)
                assert g.sub(lambda m: m.group(0).upper(), s, 1) == g.rx.sub(lambda m: m.group(0).upper(), s, 1)
            assert g.findall(s) == g.rx.findall(s), (name, s)
            assert g.split(s) == g.rx.split(s), (name, s)
            skipped += not g._may_match(s)
    assert skipped > 1000  # the gate does skip work on real text, or it is pure overhead


def test_factors_of_a_word_alternation() -> None:
    rx = re.compile(r"\b(?:collided|colliding|collision\s+with|struck)\b", re.I)
    fs = factors_of(rx)
    assert fs is not None and "struck" in fs and len(fs) <= 4
    for word in ("collided", "colliding", "collision with", "struck"):  # every match holds a factor
        assert any(f in word for f in fs), word
    assert not any(f in "the car stopped beside the curb" for f in fs)
    # A pattern that can match without a literal gets no gate.
    assert factors_of(re.compile(r"\s*(?:that\s+)?", re.I)) is None
    assert factors_of(re.compile(r"\b(?:it|he)\b")) is None  # factors too short to pay off


def test_non_ascii_text_always_runs_the_regex() -> None:
    # Under IGNORECASE "k" matches the Kelvin sign, which str.lower() does not turn into "k".
    g = gate(re.compile(r"\bkelvin\s+struck\s+(?:something|another\s+vehicle)", re.I))
    assert isinstance(g, Gated)
    s = "A careful narrative in which \u212aelvin struck another vehicle at the junction."
    assert g.search(s) is not None and g.rx.search(s) is not None
    assert g.search(s.replace("\u212a", "X")) is None


def test_possessive_part_of_ego_matches_the_backtracking_original(texts: list[str]) -> None:
    from txt2sce_ros.text.story import _PART_OF_EGO

    original = re.compile(r"((?:[\w'-]+\s+){1,6})(?:of|on|to)\s+(?:the\s+(?:stationary|stopped|parked)\s+)?EGO\b")
    found = 0
    for s in texts + ["the rear  driver-side\tof EGO", "x of of EGO", "- -  on EGO's", "a b c d e f g h to EGO",
                      "the rear driver's side of EGO", "' ' of EGO",
                      "the rear of the stationary EGO"]:
        want = [(m.span(), m.group(1)) for m in original.finditer(s)]
        assert [(m.span(), m.group(1)) for m in _PART_OF_EGO.finditer(s)] == want, s
        found += len(want)
    assert found > 50


def test_folded_classes_match_as_ignorecase_does() -> None:
    # Every ASCII character through classes with letters, ranges, negation, and a literal alternation.
    for pat in (r"[^A-Z]", r"[A-Fx]", r"[^a-c.]", r"[^\S ]", r"\bSt\.(?=\s+[a-z0-9(,])", r"(?:Mt|dr)\.", r"[^K]"):
        rx = re.compile(pat, re.I)
        cs = folded(rx)
        assert cs is not None, pat
        for code in range(128):
            ch = chr(code)
            for s in (ch, f"St.{ch}x", f"dR.{ch}"):
                want = [m.span() for m in rx.finditer(s)]
                assert [m.span() for m in cs.finditer(s.lower())] == want, (pat, s)


def test_scoped_case_sensitivity_is_not_folded() -> None:
    assert folded(re.compile(r"\bthe\s+(?-i:[A-Z])\w+", re.I)) is None
    assert folded(re.compile(r"(a)\1", re.I)) is None  # back-reference
    assert folded(re.compile(r"plain")) is None  # case-sensitive already


def test_patterns_anchored_at_the_start_are_not_gated() -> None:
    # A pattern anchored at the text's start is tried by `re` at one position: a factor looked for in the whole text,
    # or the text lowered for a folded scan, costs more than that attempt. Such a pattern is left as it is; one
    # anchored per line, or only in one branch, keeps its prefilter.
    rx = re.compile(r"^\s*(?:lanes?|racks?|stops?|paths?|signals?)\b(?!-)", re.I)
    assert gate(rx) is rx
    assert gate(re.compile(r"\Alanes?\b", re.I)).pattern == r"\Alanes?\b"
    assert factors_of(re.compile(r"\Alanes?\b", re.I)) is None
    assert factors_of(re.compile(r"^\s*(?:lanes?|racks?)\b", re.I | re.M)) is not None
    assert factors_of(re.compile(r"^lanes?\b|\bracks?\b", re.I)) is not None
    assert isinstance(gate(re.compile(r"^lanes?\b|\bracks?\b", re.I)), Gated)


def test_case_sensitive_twin_matches_as_the_original() -> None:
    # A leading \b moved behind the first literal, ASCII classes: the same spans and groups on ASCII text, and
    # the original itself on any other text.
    for pat in (r"\bEGO\b", r"\bEGO(?:\s+EGO)+\b", r"\b(?:was|were)\s+(\w+)\b", r"\b(rear|back|tail)\b",
                r"\b(St|Ave)\.(?=\s+[a-z])", r"\bthe\s+(?:EGO|EGOD)(?:'s)?"):
        rx = re.compile(pat)
        g = gate(rx)
        assert isinstance(g, Gated) and g.cs is not None and not g.fold, pat
        for s in ("EGO EGO  EGO\tEGOD was hit", "the rear of EGO, its back and tail", "St. west Ave. (Ave. x",
                  "were  stopped, was_x WAS here", "xEGO EGOx EGO_ EGO\x1cEGO", "\u00e9EGO EGO\u00e9 was \u00e9t\u00e9 EGO"):
            for text in (s, s * 3):
                want = [(m.span(), m.groups()) for m in rx.finditer(text)]
                assert [(m.span(), m.groups()) for m in g.finditer(text)] == want, (pat, text)
                assert g.sub("#", text) == rx.sub("#", text) and g.findall(text) == rx.findall(text), (pat, text)
                got, raw = g.search(text, 3), rx.search(text, 3)
                assert (got and (got.span(), got.groups())) == (raw and (raw.span(), raw.groups())), (pat, text)
    assert twin(re.compile(r"\bthe\s+(?i:SUV)\b")) is None  # a scoped flag: the original runs
    assert twin(re.compile(r"\bthe", re.I)) is None  # IGNORECASE: the folded scan's case
    assert twin(re.compile(r"\s+")) is None  # no literal to look for first: no faster than the original


def test_end_gate_never_hides_a_match() -> None:
    # A pattern anchored at the end: its reverse, anchored at the start of the reversed text, must accept every text
    # the original matches (trailing newline, spaces, words of any case), and turn most others away.
    cases = (r"\b(?:a|an|the|another|one)\s*$", r"\b(?:not|n't|never)\s+(?:\w+\s+){0,2}$", r"(?:^|[,;:]|\bwhen)\s*$",
             r"\b(?:into|onto)\s+(?:the\s+)?(?!x)$", r"\bhad\s+(?:already\s+|just\s+)?\Z", r"\bEGO's\s+(?:[\w-]++\s+){0,2}$")
    texts = ["A car drove into the ", "the car was the\n", "it had not yet ", "He said, ", "THE CAR HAD JUST ",
             "onto  ", "the vehicle when\n\n", "x had", "EGO's left rear ", "when", "then an", "another one\n",
             "struck EGO's ", "it did n't ", "\u212aelvin was the "]
    turned_away = 0
    for pat in cases:
        for flags in (re.I, 0):
            rx = re.compile(pat, flags)
            end = end_gate(rx)
            assert end is not None, pat
            g = gate(rx)
            for t in texts + [t + " and then the car " for t in texts]:
                want = [m.span() for m in rx.finditer(t)]
                assert [m.span() for m in g.finditer(t)] == want, (pat, t)
                assert g.sub("#", t) == rx.sub("#", t) and bool(g.search(t)) == bool(want), (pat, t)
                turned_away += not g._may_match(t)
    assert turned_away > 100
    assert end_gate(re.compile(r"\bthe\s+$", re.M)) is None  # "$" at every line end: not one end
    assert end_gate(re.compile(r"\s*$")) is None  # matches every text: no gate


def test_squeezed_white_space_is_the_regex_sub_it_replaces() -> None:
    # normalise squeezes white space with str.split: exact only while `re`'s \s and str.isspace take the same
    # characters, on every code point.
    from txt2sce_ros.text.mentions import _squeeze

    space = re.compile(r"\s")
    ws = [chr(c) for c in range(0x110000) if space.match(chr(c)) or chr(c).isspace()]
    assert all(space.match(c) and c.isspace() for c in ws) and len(ws) > 20
    for text in ("a" + "".join(f"{c}b{c}{c}" for c in ws) + " \t", "".join(ws), "  x  ", "x", "", "\u200bx\u00a0y"):
        assert _squeeze(text) == re.sub(r"\s+", " ", text).strip(), text


def test_alternatives_gather_by_opening_only_where_the_match_cannot_change() -> None:
    # "made|hit|making": "making" can begin only where "hit" cannot, so it joins "made" ("ma(?:de|king)");
    # "abx|\w+|ab": "ab" may not move before "\w+" (both can begin at an "a"), else "abc" would match "ab".
    from txt2sce_ros.text import fastre

    def top(pattern: str) -> int:
        tree = fastre._p.parse(pattern)
        fastre._merge_prefixes(tree)
        return len(tree.data[0][1][1]) if tree.data[0][0] is fastre._c.BRANCH else 1

    assert top("made|hit|making") == 2 and top(r"\bmade|\bhit|\bmaking|x") == 3 and top("made|hit|[m-z]aking") == 3
    assert top(r"abx|\w+|ab") == 3 and top("abx|(?:b|c)d|ab") == 2 and top("abx|(?:a|c)d|ab") == 3
    for pat, texts in ((r"(?:abx|\w+|ab)", ("abc ab abx", "ABX Ab")),
                       (r"\b(?:made|hit|making|mad|hits|[m-z]aking)\b", ("making mad hits made taking", "MAKING Hit")),
                       (r"(?:ab|c\w|a|cd|abc)+", ("abcdab cd ab abc", "CDABC"))):
        rx = re.compile(pat, re.I)
        cs = folded(rx)
        assert cs is not None, pat
        g = gate(rx)
        for t in texts:
            assert [m.span() for m in cs.finditer(t.lower())] == [m.span() for m in rx.finditer(t)], (pat, t)
            assert [m.span() for m in g.finditer(t)] == [m.span() for m in rx.finditer(t)], (pat, t)


def test_small_opening_classes_spelled_out_match_as_the_original() -> None:
    # "[,;]|\bwhen\b" -> ",|;|w(?<!\w.)hen\b": every alternative opens with a literal, so `re` skips to them in C;
    # the same spans, groups and pieces of a split as the original, on ASCII text and on any other.
    cases = ((r"[,;]|\bwhen\b|\bas\b|\bwhile\b", 0), (r"\b(?:[Aa]n?|[Tt]he)\s+([A-Z]\w*)", 0),
             (r"\b(?:Mt|[Aa]pprox|S|N|U\.S)\.", 0), (r"[2-5]\s*(lanes?)", 0), (r"([,;])|\b(?:when|as)\b", re.I),
             (r"\b(?:[Aa]n?|[Tt]he)\b", re.I))
    texts = ("When it stopped, as the car waited; while a truck passed: Approx. 5 mph", "an Apple the Zoox A the",
             "approx. 3 lanes, S. Main St. N. U.S. Mt. x_as as_ 2as _when", "THE when_ AN an, 9 lanes 3lane",
             "caf\u00e9 when \u212aelvin, as")
    for pat, flags in cases:
        rx = re.compile(pat, flags)
        g = gate(rx)
        assert isinstance(g, Gated) and g.cs is not None, pat
        for t in texts + tuple(t * 3 for t in texts):
            assert [(m.span(), m.groups()) for m in g.finditer(t)] == [(m.span(), m.groups()) for m in rx.finditer(t)]
            assert g.split(t) == rx.split(t) and g.sub("#", t) == rx.sub("#", t), (pat, t)


def test_wordcase_puts_exactly_the_letters_after_a_boundary_in_upper_case(texts: list[str]) -> None:
    def reference(low: str) -> str:
        return re.sub(r"\b[a-z]", lambda m: m.group(0).upper(), low)  # \b before a letter: it begins a word

    for t in texts[:400] + ["3rd st_x a1b2c _ab 4th-street don't x", "", "a", "1a", "_a", "a_a", "9 9a a9 a"]:
        if t.isascii():
            assert wordcase(t.lower()) == reference(t.lower()), t


def test_word_scanner_matches_as_the_original() -> None:
    # The word-cased scanner: letters after no word character in upper case, after one in lower case, either
    # where the pattern does not tell (an optional part, a repeat, a class); a \b before a capital dropped.
    cases = (r"\b(?:made|hit|making)\b", r"\b(?:the\s+)?(?:vehicle|car)\s*\(?1\)?(?=\W)", r"\bx?(?:ray|ran)\b",
             r"(?:\w+\s+){0,2}\b(?:lane|lanes)\b", r"\b(?:[Aa]n|[Tt]he)\s+(?:cruise|waymo)", r"\b(?:a|b)+c",
             r"\b(?:st|ave)\.(?=\s+[a-z0-9(,])", r"\bre-?enter(?:ed)?\b", r"\b(?:l[a-e]ft|ri[^x]ht)\b",
             r"\b(EGO|it|the\s+(?:car|van))(?:'s)?\b", r"\b(?:the\s+|an?\s+)?(?:(?:av|ego)\s+)?(?:driver|operator)s?\b",
             r"\b(?:x(?:yz)?)?(?:y|z)?(ab|c)")
    texts = ("Made it; making, hit THE car (1) vehicle1 the vehicle 1 Xray ran xran", "a b lanes lane_x 2lanes 3 lane",
             "An Cruise the waymo thecruise aabc bac c abc", "St. x Ave. 9 st.x re-entered reentered rE-ENTER",
             "left lxft LEFT right rixht riGHT", "EGO's it's the car's thecar the  van x_it it_")
    words = 0
    for pat in cases:
        rx = re.compile(pat, re.I)
        cs = word_scanner(rx)
        words += cs is not None
        g = gate(rx)
        for t in texts + tuple(t.upper() for t in texts) + tuple(t * 2 for t in texts):
            want = [m.span() for m in rx.finditer(t)]
            if cs is not None:
                assert [m.span() for m in cs.finditer(wordcase(t.lower()))] == want, (pat, t)
            assert [m.span() for m in g.finditer(t)] == want and g.sub("#", t) == rx.sub("#", t), (pat, t)
            assert [m.span() for m in g.finditer(t, 3)] == [m.span() for m in rx.finditer(t, 3)], (pat, t)
    assert words >= 5


def test_patterns_are_built_on_first_use_and_then_cost_nothing_extra() -> None:
    import subprocess
    import sys

    # A cold import builds none of the extractor's patterns (that was most of a cold `txt2sce extract`) ...
    code = ("import txt2sce_ros.text.extractor; from txt2sce_ros.text import fastre; "
            "live = list(fastre._LAZY); print(len(live), sum(p._built is not None for p in live))")
    made, built = map(int, subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                          check=True).stdout.split())
    assert made >= 200 and built == 0
    # ... every one of them compiles (a malformed pattern must not wait for the narrative that reaches it) ...
    assert build_all() >= 200
    # ... and once built, a lazy pattern's methods are the built pattern's own.
    lp = LazyPattern(r"\bstruck\s+the\s+(rear|side)\b", re.I)
    assert lp.groups == 1 and "search" in vars(lp)
    assert lp.search.__self__ is lp.built()  # type: ignore[attr-defined]
    m = lp.search("A car struck the rear bumper")
    assert m is not None and m.group(1) == "rear"
    assert lp.sub("X", "it struck the side") == "it X"
