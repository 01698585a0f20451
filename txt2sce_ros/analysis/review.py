"""The review page: one self-contained HTML file on which a person checks a batch of sketches before building
from them. Per report: the narrative with each slot's evidence highlighted (the sketch's optional `evidence`
map; without it the narrative is shown plain and the page says so), the sketch as a table with its codes in
words, and — given the seeds built from the sketches — a top-down picture of the seed's start positions and
paths, run in the player with a storyboard-driven AV, with the fidelity result (does the reported party meet
the AV?).

    page = review_page(load_sketches("sketches.jsonl"), narratives={"id": "text"}, seed_dir=Path("seeds"))
    Path("review.html").write_text(page)

Nothing is fetched from elsewhere: styles are inline, pictures are PNG data URIs.
"""

from __future__ import annotations

import base64
import html
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping

from ..sketch import ErrorRecord, Sketch
from .legend import actions_text, legend_rows, position_text

#: Highlight colours, one per party or slot group (what a slot path starts with), light enough to read text on.
GROUP_COLOURS = {
    "road": "#d7e3fc", "environment": "#e2ece9", "signal_state": "#fde2e4", "ego": "#bde0fe",
    "collision": "#ffadad", "missing": "#eeeeee",
}
PARTY_COLOURS = ("#ffd6a5", "#caffbf", "#e4c1f9", "#fdffb6", "#a0c4ff", "#ffc6ff", "#9bf6ff", "#d0f4de")


@dataclass
class SeedView:
    """What the page shows of one report's seed: the picture and the fidelity verdict, or why there is none."""

    png: bytes | None = None
    fidelity: str = ""
    faithful: bool | None = None
    note: str = ""


@dataclass
class ReviewStats:
    reports: int = 0
    buildable: int = 0
    with_evidence: int = 0
    seeds: int = 0
    faithful: int = 0
    errors: list[str] = field(default_factory=list)


def group_of(slot: str) -> str:
    """`npcs[0].position` -> `npcs[0]`; `road.layout` -> `road`; `signal_state` -> `signal_state`."""
    return slot.split(".", 1)[0]


def colour_of(slot: str) -> str:
    g = group_of(slot)
    if g.startswith(("npcs[", "obstacles[")):
        k = int(g[g.index("[") + 1:g.index("]")]) + (4 if g.startswith("obstacles") else 0)
        return PARTY_COLOURS[k % len(PARTY_COLOURS)]
    return GROUP_COLOURS.get(g, "#eeeeee")


def sketch_slots(sketch: Sketch) -> list[tuple[str, Any]]:
    """The sketch's leaf slots as (path, value), in the order of the spec's table (evidence excluded)."""
    out: list[tuple[str, Any]] = []

    def walk(prefix: str, value: Any) -> None:
        if isinstance(value, dict):
            for k, v in value.items():
                walk(f"{prefix}.{k}" if prefix else k, v)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            for i, v in enumerate(value):
                walk(f"{prefix}[{i}]", v)
        else:
            out.append((prefix, value))

    d = sketch.to_dict()
    for key in ("schema", "report_id", "evidence"):
        d.pop(key, None)
    walk("", d)
    return out


def meaning(slot: str, value: Any) -> str:
    """A coded value in words (positions, action strings); '' when the value speaks for itself."""
    leaf = slot.rsplit(".", 1)[-1]
    if leaf == "position" and isinstance(value, str) and value:
        return position_text(value)
    if leaf == "actions" and isinstance(value, str):
        return actions_text(value)
    return ""


def highlight(text: str, evidence: Iterable[tuple[str, Iterable[tuple[int, int]]]]) -> tuple[str, list[str]]:
    """The narrative as HTML with every evidence span in a <mark> coloured by its slot's party (a stretch read
    for several slots carries all their names in its title), plus a note per span that does not fit the text."""
    bad: list[str] = []
    spans: list[tuple[int, int, str]] = []
    for slot, pairs in evidence:
        for start, end in pairs:
            if not 0 <= start < end <= len(text):
                bad.append(f"{slot}: span [{start}, {end}) is outside the narrative ({len(text)} characters)")
                continue
            spans.append((start, end, slot))
    cuts = sorted({0, len(text), *(s for s, _, _ in spans), *(e for _, e, _ in spans)})
    parts: list[str] = []
    for a, b in zip(cuts, cuts[1:]):
        covering = [slot for s, e, slot in spans if s <= a and b <= e]
        chunk = html.escape(text[a:b])
        if covering:
            parts.append(f'<mark style="background:{colour_of(covering[0])}" '
                         f'title="{html.escape(", ".join(covering))}">{chunk}</mark>')
        else:
            parts.append(chunk)
    return "".join(parts), bad


def _table(sketch: Sketch, text: str | None) -> str:
    rows = []
    for slot, value in sketch_slots(sketch):
        spans = sketch.evidence_for(slot)
        quotes = " … ".join(f"“{html.escape(text[s:e])}”" for s, e in spans if text and 0 <= s < e <= len(text))
        shown = json.dumps(value, ensure_ascii=False) if not isinstance(value, str) else value
        rows.append(f'<tr><td><span class="sw" style="background:{colour_of(slot)}"></span>{html.escape(slot)}</td>'
                    f"<td><b>{html.escape(shown)}</b></td><td>{html.escape(meaning(slot, value))}</td>"
                    f'<td class="q">{quotes or "–"}</td></tr>')
    return ("<table class='sk'><tr><th>slot</th><th>value</th><th>in words</th><th>read from</th></tr>"
            + "".join(rows) + "</table>")


def seed_view(seed_file: Path, target: str | None, report_id: str) -> SeedView:
    """Run the seed with a storyboard AV, judge fidelity and draw start positions and paths over the lanes."""
    import numpy as np

    from ..seed.fidelity import check_file
    from .plots import lane_borders_near, trajectory_plot

    res, traj = check_file(seed_file, target, report_id=report_id)
    if res.faithful:
        text = (f"faithful: {res.target} meets the AV ({'contact' if res.kind == 'contact' else 'TTC < 1.5 s'} "
                f"at {res.time:.1f} s)")
    elif res.kind == "error":
        text = f"not run: {res.note}"
    else:
        gap = f", closest gap {res.min_gap:.1f} m" if res.min_gap is not None else ""
        text = f"NOT faithful: {res.target or 'no reported party'} never meets the AV{gap}"
    if not traj:
        return SeedView(None, text, res.faithful, res.note)
    marks = []
    ego = traj.get("ego")
    if res.time is not None and ego is not None and len(ego):
        marks.append((float(np.interp(res.time, ego[:, 0], ego[:, 1])),
                      float(np.interp(res.time, ego[:, 0], ego[:, 2])), f"{res.kind} @ {res.time:.1f} s"))
    png = trajectory_plot(traj, lane_borders_near(seed_file, traj), f"{seed_file.name}: {text}", marks)
    return SeedView(png, text, res.faithful, res.note)


def _seed_index(seed_dir: Path | None) -> tuple[dict[str, dict[str, Any]], dict[str, str]]:
    """Built seeds by report id, and the refusal reason by report id, from the seed directory's manifest."""
    if seed_dir is None:
        return {}, {}
    from ..errors import InputError

    manifest = seed_dir / "manifest.json"
    try:
        data = json.loads(manifest.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read the seed manifest: {exc}", source=str(manifest)) from exc
    built = {str(e["report_id"]): e for e in data.get("built", []) if e.get("report_id")}
    refused = {str(e["report_id"]): str(e.get("error", "")) for e in data.get("refused", []) if e.get("report_id")}
    return built, refused


def _section(item: Sketch | ErrorRecord, text: str | None, seeds: Mapping[str, dict[str, Any]],
             refused: Mapping[str, str], seed_dir: Path | None, stats: ReviewStats) -> str:
    rid = item.report_id
    anchor = html.escape(rid)
    out = [f'<section id="{anchor}"><h2>{html.escape(rid)}</h2>']
    if isinstance(item, ErrorRecord):
        stats.errors.append(rid)
        out.append(f"<p class='bad'>no sketch: {html.escape(item.error)}</p>")
        if text:
            out.append(f"<div class='narr'>{html.escape(text)}</div>")
        return "".join(out) + "</section>"
    badges = []
    if item.is_buildable:
        stats.buildable += 1
        badges.append("<span class='ok'>buildable</span>")
    else:
        badges.append(f"<span class='bad'>refused: missing {html.escape(', '.join(item.missing))}</span>")
    if item.evidence:
        stats.with_evidence += 1
    out.append("<p>" + " ".join(badges) + "</p>")
    out.append("<div class='cols'><div class='col'>")
    out.append("<h3>Narrative</h3>")
    if text is None:
        out.append("<p class='note'>narrative not found: give the reports it came from with --reports</p>")
    else:
        body, bad = highlight(text, item.evidence)
        if not item.evidence:
            out.append("<p class='note'>this sketch records no evidence (no <code>evidence</code> field): the "
                       "narrative is shown without highlights</p>")
        out.append(f"<div class='narr'>{body}</div>")
        out += [f"<p class='bad'>{html.escape(b)}</p>" for b in bad]
    out.append("<h3>Sketch</h3>" + _table(item, text))
    out.append("</div><div class='col'><h3>Seed</h3>")
    if seed_dir is None:
        out.append("<p class='note'>no seeds given (--seeds DIR): no picture</p>")
    elif rid in seeds:
        entry = seeds[rid]
        view = seed_view(seed_dir / entry["file"], entry.get("fidelity_target"), rid)
        stats.seeds += 1
        stats.faithful += bool(view.faithful)
        cls = "ok" if view.faithful else "bad"
        out.append(f"<p class='{cls}'>{html.escape(view.fidelity)}</p>")
        out.append(f"<p class='note'>{html.escape(entry['file'])} on {html.escape(str(entry.get('map')))}; "
                   "circles = start, squares = end, ego in blue</p>")
        if view.png:
            uri = "data:image/png;base64," + base64.b64encode(view.png).decode()
            out.append(f"<img class='pic' alt='top-down view of {anchor}' src='{uri}'/>")
    else:
        why = refused.get(rid, "not in the seed manifest")
        out.append(f"<p class='bad'>no seed: {html.escape(why)}</p>")
    out.append("</div></div></section>")
    return "".join(out)


STYLE = ("body{font-family:sans-serif;max-width:1400px;margin:1em auto;color:#222;padding:0 1em}"
         "section{border-top:2px solid #888;margin-top:1.5em}"
         ".cols{display:flex;gap:1.5em;flex-wrap:wrap}.col{flex:1 1 560px;min-width:0}"
         ".narr{line-height:1.6;background:#fafafa;border:1px solid #ddd;padding:.6em;white-space:pre-wrap}"
         "mark{border-radius:3px;padding:0 1px}"
         "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px;"
         "vertical-align:top}th{background:#f0f0f0}.q{font-style:italic;color:#444}.sk td:first-child{white-space:nowrap}"
         ".sw{display:inline-block;width:10px;height:10px;margin-right:5px;border:1px solid #999}"
         ".ok{color:#1b5e20;font-weight:bold}.bad{color:#b71c1c;font-weight:bold}.note{color:#666;font-size:13px}"
         ".pic{max-width:100%;border:1px solid #ddd}")


def review_page(items: Iterable[Sketch | ErrorRecord], narratives: Mapping[str, str], *,
                seed_dir: Path | None = None, title: str = "txt2sce review") -> tuple[str, ReviewStats]:
    """The whole page and its counts."""
    seeds, refused = _seed_index(seed_dir)
    stats = ReviewStats()
    sections, toc = [], []
    for item in items:
        stats.reports += 1
        sections.append(_section(item, narratives.get(item.report_id), seeds, refused, seed_dir, stats))
        toc.append(f"<a href='#{html.escape(item.report_id)}'>{html.escape(item.report_id)}</a>")
    summary = (f"{stats.reports} reports: {stats.buildable} buildable, {len(stats.errors)} without a sketch, "
               f"{stats.with_evidence} with evidence spans")
    if seed_dir is not None:
        summary += f"; {stats.seeds} seeds run, {stats.faithful} faithful (reported party meets the AV)"
    legend = "".join(f"<tr><td><b>{html.escape(c)}</b></td><td>{html.escape(m)}</td></tr>" for c, m in legend_rows()
                     if ":" not in c)
    head = (f"<h1>{html.escape(title)}</h1><p id='summary'>{html.escape(summary)}</p>"
            "<details><summary>Codes: positions R1–R7 and actions a–m</summary>"
            f"<table>{legend}</table></details><p class='note'>{' · '.join(toc)}</p>")
    page = (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>"
            f"<style>{STYLE}</style></head><body>{head}{''.join(sections)}</body></html>\n")
    return page, stats
