"""Campaign report: Markdown and a self-contained HTML page (plots inlined as PNG data URIs)."""

from __future__ import annotations

import base64
import html
import json
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Mapping, Sequence

from .behaviours import Attribution, BehaviourRow, attribution, behaviour_table
from .derivation import TriggerCandidate, aggregate, trigger_candidates
from .features import elements_of_files
from .legend import explain, legend_rows
from .lift import LiftRow, lift_table
from . import plots


@dataclass
class CampaignResults:
    """What the report is made of: one entry per run plus the trees' manifests."""

    runs: list[dict[str, Any]]                       # scenario_id, tree, parent, verdict, categories, file, record
    trees: dict[str, dict[str, Mapping[str, Any]]] = field(default_factory=dict)   # tree -> node id -> node
    diversity: list[tuple[str, int, int]] = field(default_factory=list)            # level, abstract, variants
    unique_categories: int | None = None
    failure_plots: list[tuple[str, bytes]] = field(default_factory=list)           # caption, PNG
    tested: list[tuple[str, str]] = field(default_factory=list)   # what was tested: planner, faults, seeds, settings
    partial: str | None = None                                    # set when the campaign is not finished
    planner: dict[str, Any] | None = None            # the planner under test: name, version, settings
    baseline: dict[str, Any] | None = None           # the baseline planner of a differential campaign
    differential: dict[str, list[dict[str, Any]]] | None = None   # campaign.reporting.differential
    baseline_runs: list[dict[str, Any]] = field(default_factory=list)   # the baseline's runs, same scenarios
    # the judged runs' scenario elements, by file, when begun before the report (`features.ElementsReading`)
    elements: Callable[[], dict[str, frozenset[str]]] | None = None


@dataclass
class Analysis:
    behaviours: list[BehaviourRow]
    verdicts: dict[str, int]
    lift: dict[str, list[LiftRow]]
    triggers: list[TriggerCandidate]
    derivation: dict[str, list[tuple[str, int]]]
    attribution: Attribution | None = None


def analyse(res: CampaignResults, *, min_support: int = 3) -> Analysis:
    rows, verdicts = behaviour_table((r["verdict"], tuple(r["categories"])) for r in res.runs)
    judged = [r for r in res.runs if r["verdict"] in ("pass", "fail") and r.get("file")]
    elements = res.elements() if res.elements is not None else elements_of_files([r["file"] for r in judged])
    lift = lift_table(((elements[r["file"]], frozenset(r["categories"])) for r in judged), min_support=min_support)
    triggers: list[TriggerCandidate] = []
    for tree, nodes in sorted(res.trees.items()):
        results = {r["scenario_id"]: (r["verdict"], tuple(r["categories"])) for r in res.runs if r.get("tree") == tree}
        triggers.extend(trigger_candidates(nodes, results))
    who = attribution((r["verdict"], tuple(r["categories"]), r.get("record") or {}) for r in res.runs)
    return Analysis(rows, verdicts, lift, triggers, aggregate(triggers), who)


#: Rows of the table of failing runs labelled unavoidable by the scripted parties.
MAX_LABELLED = 20


def _labels(run: Mapping[str, Any]) -> list[dict[str, Any]]:
    """The run's `unavoidable` labels as stored in its record (none in records older than the label)."""
    return list(((run.get("record") or {}).get("details") or {}).get("unavoidable", []))


def _md_table(header: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out)


def markdown(res: CampaignResults, an: Analysis, *, title: str = "txt2sce campaign report",
             images: Mapping[str, str] | None = None) -> str:
    images = images or {}
    parts = [f"# {title}", ""]
    if res.partial:
        parts += [f"**{res.partial}**", ""]
    total = sum(an.verdicts.values())
    if res.planner:
        parts.append(_planner_line("Planner under test", res.planner))
        parts.append("")
    parts.append(f"{total} runs: " + ", ".join(f"{an.verdicts.get(v, 0)} {v}" for v in ("pass", "fail", "error")))
    parts += _speed_lines(res)
    if res.tested:
        parts += ["", "## What was tested", ""]
        parts.append(_md_table(["what", "value"], [(k, v.replace("|", "/")) for k, v in res.tested]))
    parts += ["", "## Unexpected behaviours (paper Table VI)", ""]
    top = {c: ", ".join(f"{r.element} ({r.lift:.2f}×, n={r.support})" for r in an.lift.get(c, [])[:3])
           for c in (b.category for b in an.behaviours)}
    who = an.attribution
    unavoidable = who.unavoidable if who else {}
    parts.append(_md_table(
        ["category", "count", "share of behaviours", "share of runs", "unavoidable by scripted parties",
         "top triggers (lift, support)"],
        [(b.category, b.count, f"{100 * b.share_of_behaviours:.1f}%", f"{100 * b.share_of_runs:.1f}%",
          unavoidable.get(b.category, 0), top.get(b.category) or "–") for b in an.behaviours]))
    if who is not None and who.failed:
        parts += ["", f"**{who.line()}.** A category is labelled unavoidable when the recorded scripted parties "
                      "still meet an ego that braked from its start, or from when the party's course first met its "
                      "path (Collisions: at the oracle's `unavoidable_decel`; Smooth: the smoothest stop the band "
                      "allows), or, for a goal not reached, when a moving party was on its path ahead at the end. "
                      "Those failures say nothing about the planner; the runs' labels are in analysis.json and each "
                      "run's record (`unavoidable`)."]
    labelled = [r for r in res.runs if r["verdict"] == "fail" and _labels(r)]
    if labelled:
        parts += ["", f"Failing runs with at least one category made unavoidable by the scripted parties "
                      f"({len(labelled)}; "
                      f"the first {min(len(labelled), MAX_LABELLED)}):", ""]
        parts.append(_md_table(["scenario", "verdict", "unavoidable", "why"], [
            (f"{r.get('tree') or ''} {r['scenario_id']}".strip(), "fail " + ", ".join(r["categories"]),
             ", ".join(u["category"] for u in _labels(r)), "; ".join(u["detail"] for u in _labels(r)))
            for r in labelled[:MAX_LABELLED]]))
    if "categories" in images:
        parts += ["", f"![categories]({images['categories']})"]
    parts += ["", "## Trigger conditions by lift", "",
              "lift = P(category given element) / P(category); confidence = P(category given element); "
              "support = runs with both. Element codes are explained in the legend at the end."]
    for cat, rows in an.lift.items():
        parts += ["", f"### {cat}", ""]
        parts.append(_md_table(["element", "meaning", "lift", "support", "runs with element", "confidence"],
                               [(r.element, explain(r.element), f"{r.lift:.2f}", r.support, r.with_element,
                                 f"{r.confidence:.2f}") for r in rows[:10]]))
    if "lift" in images:
        parts += ["", f"![lift]({images['lift']})"]
    parts += ["", "## Derivation triggers", "",
              "A failing node whose parent passed: the block its derivation added is the trigger candidate.", ""]
    if an.derivation:
        parts.append(_md_table(["category", "block kind / operator", "count"],
                               [(c, k, n) for c, kv in an.derivation.items() for k, n in kv[:5]]))
    else:
        parts.append("No parent-passed / child-failed pair in this campaign.")
    if res.differential is not None:
        parts += _differential_section(res)
    if res.diversity:
        parts += ["", "## Diversity (paper Table V)", ""]
        parts.append(_md_table(["abstraction level", "abstract representations", "variants generated"],
                               res.diversity))
        if res.unique_categories is not None:
            parts += ["", f"Unique scenario categories: {res.unique_categories}"]
    trees = sorted(k for k in images if k.startswith("tree:"))
    if trees:
        parts += ["", "## Scenario trees", "",
                  "Each dot is a scenario; the seed at the top, one row per block inserted (depth = blocks added); "
                  "green = pass, red = fail, grey = error, white = not run."]
        for key in trees:
            parts += ["", f"### Tree {key.split(':', 1)[1]}", "", f"![{key}]({images[key]})"]
    failures = sorted(k for k in images if k.startswith("failure:"))
    if failures:
        parts += ["", "## Trajectories of representative failures", "",
                  "One failing run per category, re-run to draw it (runs are deterministic): top-down view over the "
                  "map's lanes; the AV (ego) in blue; circles mark starts, squares ends; red crosses mark "
                  "violations, labelled beside the plot."]
        for key in failures:
            parts += ["", f"### {key.split(' ', 1)[1]}", "", f"![{key}]({images[key]})"]
    parts += ["", "## Legend: the codes in this report", "",
              "Positions are relative to the AV when the interaction begins (right-hand traffic); action strings "
              "list a party's manoeuvres in order, one letter each."]
    parts.append(_md_table(["code", "meaning"], legend_rows()))
    return "\n".join(parts) + "\n"


def _planner_line(label: str, p: Mapping[str, Any]) -> str:
    settings = ", ".join(f"{k}={v}" for k, v in sorted(p.get("settings", {}).items()))
    return f"{label}: **{p.get('name')}** {p.get('version', '')}" + (f" (settings: {settings})" if settings else "")


def _per_hour(runs: list[dict[str, Any]]) -> str | None:
    walls = [float(r["record"].get("wall_time", 0.0)) for r in runs if r.get("record")]
    if not walls or sum(walls) <= 0:
        return None
    return (f"{3600.0 * len(walls) / sum(walls):.0f} scenarios per hour of run wall time "
            f"(mean {sum(walls) / len(walls):.1f} s per run, one worker)")


def _speed_lines(res: CampaignResults) -> list[str]:
    """Scenarios per hour of wall time (beside the baseline's on the same scenarios, in the same campaign), and
    the planner's replanning cadence when it reported its cycles."""
    out: list[str] = []
    speed = _per_hour(res.runs)
    if speed:
        out += ["", f"Speed: {speed}."]
    base = _per_hour(res.baseline_runs)
    if speed and base:
        out += ["", f"Baseline speed ({(res.baseline or {}).get('name', 'baseline')}, in-process, same scenarios): "
                    f"{base}."]
    stats = [r["record"]["details"]["planner_stats"] for r in res.runs
             if r.get("record") and "planner_stats" in r["record"].get("details", {})]
    if stats:
        cycles = {k: sum(s["cycles"].get(k, 0) for s in stats) for k in stats[0]["cycles"]}
        sim = sum(float(r["record"].get("sim_time", 0.0)) for r in res.runs
                  if "planner_stats" in r.get("record", {}).get("details", {}))
        total = sum(cycles.values())
        mean = sum(s["plan_time_mean_s"] * sum(s["cycles"].values()) for s in stats) / max(1, total)
        worst = max(float(s.get("plan_time_max_s", 0.0)) for s in stats)
        out += ["", f"Replanning: {total} planning cycles over {sim:.0f} s of simulated time "
                    f"({total / max(sim, 1e-9):.2f} Hz); mean planning time {mean:.2f} s wall, longest "
                    f"{worst:.2f} s; outcomes: "
                + ", ".join(f"{k} {v}" for k, v in cycles.items())
                + f"; runs with a braking fallback: {sum(1 for s in stats if s.get('braking_steps'))}."]
    return out


def _differential_section(res: CampaignResults) -> list[str]:
    d = res.differential or {}
    name = (res.planner or {}).get("name", "planner")
    base = (res.baseline or {}).get("name", "baseline")
    parts = ["", "## Differential triage", "", _planner_line("Baseline", res.baseline or {}), ""]
    parts.append(_md_table(["outcome", "scenarios"], [
        (f"{name} fails, {base} passes (the planner's own failures)", len(d.get("own", []))),
        ("both fail (the scenario defeats both)", len(d.get("both", []))),
        (f"{base} fails, {name} passes", len(d.get("baseline_only", []))),
        ("both pass", len(d.get("both_pass", []))),
        ("an error on either side", len(d.get("error", []))),
    ]))
    for key, title in (("own", f"{name}'s own failures"), ("both", "failures of both")):
        cats: dict[str, int] = {}
        for r in d.get(key, []):
            for c in r["categories"]:
                cats[c] = cats.get(c, 0) + 1
        if cats:
            parts += ["", f"{title} by category: " + ", ".join(f"{c} {n}" for c, n in
                                                                sorted(cats.items(), key=lambda kv: -kv[1]))]
    return parts


def write_report(res: CampaignResults, out_dir: str | Path, *, title: str = "txt2sce campaign report",
                 min_support: int = 3) -> tuple[Path, Path]:
    """Write report.md (+ PNG files beside it) and a self-contained report.html; returns both paths."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    an = analyse(res, min_support=min_support)
    figs: dict[str, bytes] = {"categories": plots.category_bars(an.behaviours), "lift": plots.lift_bars(an.lift)}
    for tree, nodes in sorted(res.trees.items())[:3]:
        verdicts = {r["scenario_id"]: r["verdict"] for r in res.runs if r.get("tree") == tree}
        figs[f"tree:{tree}"] = plots.tree_view(nodes, verdicts, f"tree {tree}: depth = blocks added; failing nodes red")
    for i, (caption, png) in enumerate(res.failure_plots):
        figs[f"failure:{i:02d} {caption}"] = png
    names = {}
    for key, png in figs.items():
        fname = "fig_" + "".join(ch if ch.isalnum() else "_" for ch in key)[:60] + ".png"
        (out / fname).write_bytes(png)
        names[key] = fname
    md = markdown(res, an, title=title, images=names)
    (out / "report.md").write_text(md, encoding="utf-8")
    data_uris = {k: "data:image/png;base64," + base64.b64encode(v).decode() for k, v in figs.items()}
    page = _html(markdown(res, an, title=title, images=data_uris), title)
    (out / "report.html").write_text(page, encoding="utf-8")
    (out / "analysis.json").write_text(json.dumps({
        "verdicts": an.verdicts,
        "behaviours": [b.__dict__ for b in an.behaviours],
        "lift": {c: [r.__dict__ for r in rows[:20]] for c, rows in an.lift.items()},
        "derivation": an.derivation,
        "attribution": an.attribution.__dict__ if an.attribution else None,
        "unavoidable_runs": [{"scenario_id": r["scenario_id"], "tree": r.get("tree"), "categories": r["categories"],
                              "unavoidable": _labels(r)} for r in res.runs if _labels(r)],
    }, indent=1, sort_keys=True), encoding="utf-8")
    return out / "report.md", out / "report.html"


def _inline(text: str) -> str:
    """Escaped text with the Markdown `markdown()` uses inside a line: **bold** and `code`."""
    out = html.escape(text)
    out = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", out)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", out)


def _html(md: str, title: str) -> str:
    """A minimal Markdown-to-HTML rendering of what `markdown()` emits (headings, tables, images, paragraphs)."""
    body: list[str] = []
    lines = md.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("#"):
            level = len(line) - len(line.lstrip("#"))
            body.append(f"<h{level}>{html.escape(line[level:].strip())}</h{level}>")
        elif line.startswith("| "):
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                if not lines[i].startswith("|---"):
                    rows.append([c.strip() for c in lines[i].strip("|").split("|")])
                i += 1
            i -= 1
            head, *rest = rows
            body.append("<table><tr>" + "".join(f"<th>{_inline(c)}</th>" for c in head) + "</tr>"
                        + "".join("<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in r) + "</tr>" for r in rest)
                        + "</table>")
        elif line.startswith("!["):
            alt, src = line[2:].split("](", 1)
            body.append(f'<figure><img src="{src[:-1]}" alt="{html.escape(alt)}"/></figure>')
        elif line.startswith("**") and line.endswith("**"):
            body.append(f"<p class='banner'>{html.escape(line.strip('*'))}</p>")
        elif line.strip():
            body.append(f"<p>{_inline(line)}</p>")
        i += 1
    style = ("body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}"
             "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;font-size:13px}"
             "th{background:#f0f0f0}img{max-width:100%}"
             ".banner{background:#fff3cd;border:1px solid #e0a800;padding:.5em;font-weight:bold}")
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>"
            f"<style>{style}</style></head><body>{''.join(body)}</body></html>\n")
