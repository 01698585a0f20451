"""The literal prefilter must never change a result: checked against the raw regex on every dev sentence."""

from __future__ import annotations

import importlib
import json
import re

import pytest

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.text.fastre import Gated, factors_of, folded, gate
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

    original = re.compile(r"((?:[\w'-]+\s+){1,6})(?:of|on|to)\s+EGO\b")
    found = 0
    for s in texts + ["the rear  driver-side\tof EGO", "x of of EGO", "- -  on EGO's", "a b c d e f g h to EGO",
                      "the rear driver's side of EGO", "' ' of EGO"]:
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


def test_patterns_anchored_at_the_start_scan_without_a_prefilter() -> None:
    # A pattern anchored at the text's start is tried at one position; a factor prefilter would search the whole
    # text for every factor first (~10x the scan). Such a pattern keeps its folded scan, not a prefilter, and
    # matches as the raw regex does; one anchored per line, or only in one branch, keeps the prefilter.
    rx = re.compile(r"^\s*(?:lanes?|racks?|stops?|paths?|signals?)\b(?!-)", re.I)
    g = gate(rx)
    assert isinstance(g, Gated) and g.factors == () and g.cs is not None
    for s in (" Lane of the street ahead", "lane-splitting", "the lane", " SIGNALS were red and the stop", "stops"):
        assert (g.search(s) and g.search(s).span()) == (rx.search(s) and rx.search(s).span()), s
    assert factors_of(re.compile(r"\Alanes?\b", re.I)) is None
    assert factors_of(re.compile(r"^\s*(?:lanes?|racks?)\b", re.I | re.M)) is not None
    assert factors_of(re.compile(r"^lanes?\b|\bracks?\b", re.I)) is not None
