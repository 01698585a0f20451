"""The review page (issue 18): narrative with evidence highlighted, sketch table, seed picture with fidelity —
checked as HTML and as rendered by a real headless Chromium."""

from __future__ import annotations

import itertools
import json
import re
from pathlib import Path

import numpy as np
import pytest

from txt2sce_ros.cli.main import main
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches

from .. import browser

REPORTS = shared_dir() / "data" / "reports"
FIRST = "dmvca-apollobaid-20230906-r524"
#: Phrases of FIRST's real narrative and the slots they are evidence for.
PHRASES = {"ego.actions": "was traveling westbound", "obstacles[0].category": "double-parked vehicle",
           "collision.type": "side-swiped"}
EGO_MARK = (0xBD, 0xE0, 0xFE)        # GROUP_COLOURS["ego"]
EGO_LINE = (0x1E, 0x88, 0xE5)        # the ego's path in trajectory_plot


def _narrative(rid: str) -> str:
    for line in (REPORTS / "dev.jsonl").open(encoding="utf-8"):
        row = json.loads(line)
        if row["id"] == rid:
            return str(row["text"])
    raise AssertionError(rid)


@pytest.fixture(scope="module")
def batch(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """Three real dev-gold sketches (the first with evidence spans found in its narrative, plus a refused one)
    and the seeds built from them."""
    from txt2sce_ros.seed import write_seeds

    root = tmp_path_factory.mktemp("review")
    gold = [s for s in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(s, Sketch)]
    first = next(s for s in gold if s.report_id == FIRST)
    refused = next(s for s in gold if s.missing)
    other = next(s for s in gold if s.npcs and not s.missing and s.report_id != FIRST)
    text = _narrative(FIRST)
    with_ev = first.to_dict()
    with_ev["evidence"] = {slot: [[text.index(p), text.index(p) + len(p)]] for slot, p in PHRASES.items()}
    with_ev["evidence"]["road.layout"] = [[len(text) + 5, len(text) + 9]]     # a span past the end: reported
    plain = first.to_dict()
    out = {}
    for name, first_row in (("with", with_ev), ("without", plain)):
        path = root / f"{name}.jsonl"
        rows = [first_row, other.to_dict(), refused.to_dict()]
        path.write_text("".join(json.dumps(r) + "\n" for r in rows), encoding="utf-8")
        out[name] = path
    write_seeds(itertools.islice(load_sketches(out["without"]), 3), root / "seeds", seed=0)
    out["seeds"] = root / "seeds"
    return out


def _page(batch: dict[str, Path], which: str, tmp: Path, *seeds: str) -> Path:
    page = tmp / f"{which}.html"
    args = ["review", str(batch[which]), "--reports", str(REPORTS / "dev.jsonl"), "--out", str(page)]
    if seeds:
        args += ["--seeds", str(batch["seeds"])]
    assert main(args) == 0
    return page


def test_page_shows_evidence_table_seed_picture_and_refusal(batch: dict[str, Path], tmp_path: Path) -> None:
    html = _page(batch, "with", tmp_path, "seeds").read_text(encoding="utf-8")
    # self-contained: every image inline, nothing fetched
    assert not re.search(r"(src|href)=['\"](https?:|//|/)", html) and "<script src" not in html and "<link" not in html
    assert html.count("src='data:image/png;base64,") == 2          # two buildable seeds, one picture each
    for slot, phrase in PHRASES.items():
        assert re.search(rf'<mark [^>]*title="{re.escape(slot)}">{re.escape(phrase)}</mark>', html)
        assert f"“{phrase}”" in html                                  # quoted in the table's "read from"
    assert "road.layout: span [" in html and "outside the narrative" in html
    assert "go straight, then stop" in html                           # ego.actions 'ah' in words
    assert "faithful: obs1 meets the AV" in html
    assert "no seed: " in html and "missing" in html                   # the refused sketch says why


def test_page_without_evidence_or_seeds_says_so(batch: dict[str, Path], tmp_path: Path) -> None:
    html = _page(batch, "without", tmp_path).read_text(encoding="utf-8")
    assert "<mark" not in html and "records no evidence" in html
    assert "no seeds given" in html and "data:image/png" not in html
    assert "double-parked vehicle" in html                            # the narrative is still there, plain


def test_bad_inputs_are_one_line_errors(batch: dict[str, Path], tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["review", str(tmp_path / "none.jsonl"), "--out", str(tmp_path / "p.html")]) == 2
    assert main(["review", str(batch["with"]), "--seeds", str(tmp_path), "--out", str(tmp_path / "p.html")]) == 2
    err = capsys.readouterr().err
    assert "no such sketch file" in err and "not a seed directory" in err and "Traceback" not in err


def _count(img: np.ndarray, rgb: tuple[int, int, int]) -> int:
    return int(np.all(img[:, :, :3] == np.array(rgb), axis=2).sum())


@pytest.mark.skipif(browser.chromium() is None, reason="chromium not installed (.ci/run installs it)")
def test_chromium_renders_highlights_and_the_seed_picture(batch: dict[str, Path], tmp_path: Path) -> None:
    from PIL import Image

    shots = {}
    for which in ("with", "without"):
        png = browser.screenshot(_page(batch, which, tmp_path, "seeds"), tmp_path / f"{which}.png")
        shots[which] = np.asarray(Image.open(png).convert("RGB"))
    img = shots["with"]
    assert img.shape[0] >= 1000 and img.shape[1] >= 1000 and img.std() > 20          # not blank
    left, right = img[:, : img.shape[1] // 2], img[:, img.shape[1] // 2:]
    # the ego's evidence is highlighted in the narrative (left column), far more than the table's small swatches
    assert _count(left, EGO_MARK) > 5 * max(1, _count(shots["without"][:, : img.shape[1] // 2], EGO_MARK))
    assert _count(right, EGO_LINE) > 200                                             # the seed picture's ego path
    dom = browser.dump_dom(tmp_path / "with.html")
    assert 'title="collision.type">side-swiped</mark>' in dom
