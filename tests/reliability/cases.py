"""The catalogue: bad inputs, bad arguments and faults for every command, grouped by class of fault.

Each case damages a copy of a good fixture (tests/reliability/workspace.py) the way a careless user, a broken disk
or a hostile file would, and says what a clean outcome is: the exit status (0 all good, 1 some items failed and
were recorded, 2 unusable input or arguments), one line that must appear, and which good items must survive.
"""

from __future__ import annotations

import json
import math
import os
import re
import shutil
import signal
import sqlite3
import time
from pathlib import Path

import numpy as np

from .runner import Case, txt2sce_argv as T
from .workspace import copy_bag, data_dir, esmini, good_seed, mcap_of, seed_ids

XXE_DOCTYPE = '<?xml version="1.0"?>\n<!DOCTYPE r [<!ENTITY % ext SYSTEM "file:///etc/passwd"> %ext;]>\n'
LAUGHS = ('<?xml version="1.0"?>\n<!DOCTYPE lolz [<!ENTITY lol "lol">'
          + "".join(f'<!ENTITY lol{i} "{("&lol" + (str(i - 1) if i > 1 else "") + ";") * 10}">' for i in range(1, 10))
          + ']>\n')


# -- helpers that build bad inputs ------------------------------------------------------------------------------

def _write(d: Path, name: str, data: str | bytes) -> Path:
    p = d / name
    p.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(data, bytes):
        p.write_bytes(data)
    else:
        p.write_text(data, encoding="utf-8")
    return p


def _lines(p: Path) -> list[bytes]:
    return [ln for ln in p.read_bytes().splitlines() if ln.strip()]


def _with_bad_row(src: Path, d: Path, bad: bytes, at: int = 1) -> Path:
    """`src` with `bad` inserted as row `at` (between good rows)."""
    rows = _lines(src)
    rows.insert(at, bad)
    return _write(d, src.name, b"\n".join(rows) + b"\n")


def _non_utf8_row(src: Path) -> bytes:
    """A real row with one byte that is not UTF-8 inside its text (a Latin-1 'é' as old exports write it)."""
    row = _lines(src)[0]
    obj = json.loads(row)
    key = "id" if "id" in obj else "report_id"
    obj[key] = str(obj[key]) + "-latin1"
    return json.dumps(obj).replace(": ", ":", 1).encode().replace(b"a", b"\xe9", 1)


def _doctype(src: Path, d: Path, prolog: str = XXE_DOCTYPE) -> Path:
    text = src.read_text(encoding="utf-8")
    text = re.sub(r"^<\?xml[^>]*\?>\s*", "", text)
    return _write(d, src.name, prolog + text)


def _replace_attr(src: Path, d: Path, pattern: str, repl: str, name: str | None = None, count: int = 1) -> Path:
    text = src.read_text(encoding="utf-8")
    new, n = re.subn(pattern, repl, text, count=count)
    assert n, f"{pattern} not in {src}"
    return _write(d, name or src.name, new)


def _seed_copy(ws: Path, d: Path) -> Path:
    """The good seed directory copied into `d/seeds` (so a case can damage one file and keep the rest)."""
    shutil.copytree(ws / "seeds", d / "seeds")
    return d / "seeds"


def _flip(path: Path, seed: int, n: int = 8) -> None:
    """Flip `n` bytes at seeded positions in the middle 80 % of the file (what a bad disk or transfer does)."""
    data = bytearray(path.read_bytes())
    rng = np.random.default_rng(seed)
    for pos in rng.integers(len(data) // 10, len(data) * 9 // 10, size=n):
        data[int(pos)] ^= 0xFF
    path.write_bytes(bytes(data))


def _config_dir(d: Path, name: str, edit) -> Path:
    from txt2sce_ros.paths import REPO_ROOT

    cfg = d / "config"
    shutil.copytree(REPO_ROOT / "config", cfg)
    p = cfg / f"{name}.yaml"
    p.write_text(edit(p.read_text(encoding="utf-8")), encoding="utf-8")
    return cfg


def _sketch_with(ws: Path, d: Path, change) -> Path:
    obj = json.loads(_lines(ws / "sketches.jsonl")[0])
    change(obj)
    rows = [json.dumps(obj).encode()] + _lines(ws / "sketches.jsonl")[1:]
    return _write(d, "sketches.jsonl", b"\n".join(rows) + b"\n")


# -- checks that good items were kept ---------------------------------------------------------------------------

def _ids_in_jsonl(p: Path) -> set[str]:
    if not p.is_file():
        return set()
    out = set()
    for ln in _lines(p):
        obj = json.loads(ln)
        out.add(str(obj.get("report_id") or obj.get("id")))
    return out


def kept_reports(out_name: str = "out.jsonl"):
    def check(ws: Path, d: Path, stdout: str) -> str:
        want = {json.loads(r)["id"] for r in _lines(ws / "reports.jsonl")}
        have = _ids_in_jsonl(d / out_name)
        missing = want - have
        return f"good reports lost: {sorted(missing)}" if missing else ""
    return check


def kept_seeds(out_dir: str = "out"):
    def check(ws: Path, d: Path, stdout: str) -> str:
        want = set(seed_ids(ws))
        have = {p.stem for p in (d / out_dir).glob("*.xosc")}
        missing = want - have
        return f"good seeds lost: {sorted(missing)}" if missing else ""
    return check


def kept_lines(*patterns: str):
    """Every pattern matches some stdout line (e.g. the good bag's verdict after a damaged one)."""
    def check(ws: Path, d: Path, stdout: str) -> str:
        for pat in patterns:
            pat = pat.format(seed=good_seed(ws).stem)
            if not re.search(pat, stdout, re.MULTILINE):
                return f"no output line matches /{pat}/"
        return ""
    return check


def no_leak(text: str):
    def check(ws: Path, d: Path, stdout: str) -> str:
        both = stdout + (d / "stderr.txt").read_text(errors="replace")
        return f"output leaks {text!r}" if text in both else ""
    return check


def kept_runs(n_min: int):
    def check(ws: Path, d: Path, stdout: str) -> str:
        db = d / "camp" / "results.sqlite"
        if not db.is_file():
            return "no results.sqlite"
        with sqlite3.connect(db) as con:
            (n,) = con.execute("select count(*) from runs").fetchone()
        return "" if n >= n_min else f"{n} runs stored, expected >= {n_min}"
    return check


def all_of(*checks):
    def check(ws: Path, d: Path, stdout: str) -> str:
        for c in checks:
            lost = c(ws, d, stdout)
            if lost:
                return lost
        return ""
    return check


# -- fault injection into a running process tree ---------------------------------------------------------------

def _descendants(root: int) -> list[tuple[int, str]]:
    children: dict[int, list[int]] = {}
    cmd: dict[int, str] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            stat = Path(f"/proc/{entry}/stat").read_text()
            cmd[int(entry)] = Path(f"/proc/{entry}/cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        ppid = int(stat.rsplit(")", 1)[1].split()[1])
        children.setdefault(ppid, []).append(int(entry))
    out, todo = [], [root]
    while todo:
        p = todo.pop()
        for c in children.get(p, []):
            out.append((c, cmd.get(c, "")))
            todo.append(c)
    return out


def kill_node(name: str, times: int = 3, sig: int = signal.SIGKILL):
    """Kill every `name` process the command starts (up to `times`: each retry starts a new one)."""
    def during(pid: int, d: Path) -> None:
        killed: set[int] = set()
        deadline = time.monotonic() + 240
        while len(killed) < times and time.monotonic() < deadline:
            for child, cmdline in _descendants(pid):
                if name in cmdline and child not in killed:
                    time.sleep(1.0)              # let it start and match its peers first
                    try:
                        os.kill(child, sig)
                    except ProcessLookupError:
                        pass
                    killed.add(child)
            time.sleep(0.2)
            if not Path(f"/proc/{pid}").exists():
                return
    return during


# -- the catalogue ------------------------------------------------------------------------------------------------

REPORTS = lambda ws: ws / "reports.jsonl"        # noqa: E731
SKETCHES = lambda ws: ws / "sketches.jsonl"      # noqa: E731
ONE_LINE = r"error: .+"


def cases() -> list[Case]:
    c: list[Case] = []
    add = c.append

    # ---- extract: rows, files, arguments --------------------------------------------------------------------
    add(Case("extract-non-utf8-row", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, _non_utf8_row(REPORTS(ws)))), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-invalid-json-row", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, b'{"id": "x", "text": "unterminated')), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-row-not-object", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, b'[1, 2, 3]')), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-row-text-not-string", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, b'{"id": "n", "text": {"a": 1}}')), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-deeply-nested-row", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, b"[" * 100000 + b"]" * 100000)), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-nul-bytes-row", lambda ws, d: T("extract", str(_with_bad_row(REPORTS(ws), d, b"\x00\x00\x00\xff\xfe")), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-missing-file-beside-good", lambda ws, d: T("extract", str(REPORTS(ws)), str(d / "nope.jsonl"), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-only-missing-file", lambda ws, d: T("extract", str(d / "nope.txt"), "--out", "out.jsonl"),
             exit=(2,), message=r"nope\.txt.*(not found|no such)"))
    add(Case("extract-empty-txt", lambda ws, d: T("extract", str(_write(d, "empty.txt", "   \n")), "--out", "out.jsonl"),
             exit=(2,), message=r"empty"))
    add(Case("extract-fake-pdf", lambda ws, d: T("extract", str(REPORTS(ws)), str(_write(d, "r.pdf", b"%PDF-1.4 garbage\x00\x01")), "--out", "out.jsonl"),
             exit=(1,), message=r"1 errors", kept=kept_reports()))
    add(Case("extract-out-is-directory", lambda ws, d: T("extract", str(REPORTS(ws)), "--out", str(d)),
             message=r"error: .*is a directory"))
    add(Case("extract-out-unwritable", lambda ws, d: T("extract", str(REPORTS(ws)), "--out", str(_write(d, "afile", "x") / "sub" / "o.jsonl")),
             message=r"error: .*(not a directory|cannot write)"))
    add(Case("extract-huge-narrative", lambda ws, d: T("extract", str(_write(d, "huge.txt", ("The AV was traveling north on Main Street when a vehicle made a left turn. " * 70000))), "--out", "out.jsonl"),
             exit=(2,), message=r"(narrative|text).*(longer|limit|too long)", timeout=60.0))
    add(Case("extract-llm-unreachable", lambda ws, d: T("extract", str(REPORTS(ws)), "--out", "out.jsonl", "--backend", "llm", "--base-url", "http://127.0.0.1:9", "--timeout", "2"),
             exit=(1, 2), message=r"(connect|refused|unreachable|LLM)", env={"TXT2SCE_LLM_API_KEY": "k"}, timeout=120))
    add(Case("extract-llm-timeout-nan", lambda ws, d: T("extract", str(REPORTS(ws)), "--out", "out.jsonl", "--backend", "llm", "--timeout", "nan"),
             message=r"timeout"))
    add(Case("extract-llm-base-url-not-http", lambda ws, d: T("extract", str(REPORTS(ws)), "--out", "out.jsonl", "--backend", "llm", "--base-url", "file:///etc/passwd"),
             message=r"base.url", env={"TXT2SCE_LLM_API_KEY": "k"}))

    # ---- seed: sketches ---------------------------------------------------------------------------------------
    add(Case("seed-non-utf8-row", lambda ws, d: T("seed", str(_with_bad_row(SKETCHES(ws), d, _non_utf8_row(SKETCHES(ws)))), "--out", "out"),
             exit=(1,), message=r"not UTF-8", kept=kept_seeds()))
    add(Case("seed-duplicate-report-id", lambda ws, d: T("seed", str(_with_bad_row(SKETCHES(ws), d, _lines(SKETCHES(ws))[0], at=2)), "--out", "out"),
             exit=(1,), message=r"duplicate", kept=all_of(kept_seeds(), _no_overwrite)))
    add(Case("seed-2000-parties", lambda ws, d: T("seed", str(_sketch_with(ws, d, _many_parties)), "--out", "out"),
             exit=(1,), message=r"(parties|npcs).*(limit|at most|more than)", timeout=60))
    add(Case("seed-speed-nan", lambda ws, d: T("seed", str(_sketch_with(ws, d, lambda o: o["ego"].__setitem__("speed_kmh", float("nan")))), "--out", "out"),
             exit=(0, 1), message=r"seed\(s\) written"))
    add(Case("seed-schema-wrong-types", lambda ws, d: T("seed", str(_sketch_with(ws, d, lambda o: o.__setitem__("npcs", "many"))), "--out", "out"),
             exit=(1,), message=r"refused", kept=lambda ws, d, s: "" if len(list((d / "out").glob("*.xosc"))) >= 1 else "good seeds lost"))
    add(Case("seed-missing-file", lambda ws, d: T("seed", str(d / "none.jsonl"), "--out", "out"),
             message=r"none\.jsonl.*(cannot read|no such|not found)"))
    add(Case("seed-out-is-file", lambda ws, d: T("seed", str(SKETCHES(ws)), "--out", str(_write(d, "afile", "x"))),
             message=r"error: .*(not a directory|exists)"))
    add(Case("seed-maps-missing-dir", lambda ws, d: T("seed", str(SKETCHES(ws)), "--out", "out", "--maps", str(d / "nomaps")),
             message=r"nomaps"))
    add(Case("seed-qc-doctype-refused", lambda ws, d: T("xosc", "validate", str(_doctype(good_seed(ws), d))),
             exit=(1,), message=r"DOCTYPE", kept=no_leak("root:x:0")))

    # ---- play: arguments and scenario files -------------------------------------------------------------------
    for v in ("0", "-1", "nan", "inf", "5"):
        add(Case(f"play-dt-{v}", lambda ws, d, v=v: T("play", str(good_seed(ws)), "--dt", v), message=r"dt", timeout=30))
    for v in ("-5", "0", "nan", "inf", "1e9"):
        add(Case(f"play-time-limit-{v}", lambda ws, d, v=v: T("play", str(good_seed(ws)), "--time-limit", v),
                 message=r"time.limit", timeout=30))
    add(Case("play-doctype-xxe", lambda ws, d: T("play", str(_doctype(good_seed(ws), d))), message=r"DOCTYPE",
             kept=no_leak("root:x:0")))
    add(Case("play-billion-laughs", lambda ws, d: T("play", str(_doctype(good_seed(ws), d, LAUGHS))), message=r"DOCTYPE",
             timeout=30))
    add(Case("play-not-xml", lambda ws, d: T("play", str(_write(d, "x.xosc", b"\x89PNG\r\n\x1a\n garbage"))), message=r"x\.xosc"))
    add(Case("play-truncated", lambda ws, d: T("play", str(_write(d, "t.xosc", good_seed(ws).read_bytes()[:700]))), message=r"t\.xosc"))
    add(Case("play-non-utf8", lambda ws, d: T("play", str(_write(d, "u.xosc", good_seed(ws).read_bytes().replace(b"name=\"ego\"", b"name=\"eg\xe9\"", 1)))),
             exit=(0, 2), message=r"(u\.xosc|finished)"))
    add(Case("play-missing-file", lambda ws, d: T("play", str(d / "none.xosc")), message=r"none\.xosc"))
    add(Case("play-missing-map", lambda ws, d: T("play", str(_replace_attr(good_seed(ws), d, r'filepath="[^"]*\.xodr"', 'filepath="nowhere.xodr"'))),
             message=r"nowhere\.xodr"))
    add(Case("play-csv-is-directory", lambda ws, d: T("play", str(good_seed(ws)), "--csv", str(d)), message=r"error: .*directory"))
    add(Case("play-10000-entities", lambda ws, d: T("play", str(_many_entities(ws, d, 10000))), message=r"entities", timeout=60))
    add(Case("play-map-road-length-1e300", lambda ws, d: T("play", str(esmini("xosc", "straight_500m.xosc")), "--ego-mode", "storyboard", "--map", str(_road_length(d, "1e300"))),
             message=r"length"))
    add(Case("play-nan-speed-in-scenario", lambda ws, d: T("play", str(_replace_attr(good_seed(ws), d, r'(<AbsoluteTargetSpeed value=")[^"]*"', r'\g<1>NaN"'))),
             message=r"(finite|NaN|nan)"))

    # ---- maps: OpenDRIVE files ------------------------------------------------------------------------------
    add(Case("maps-info-road-length-1e300", lambda ws, d: T("maps", "info", str(_road_length(d, "1e300"))), message=r"length"))
    add(Case("maps-info-road-length-nan", lambda ws, d: T("maps", "info", str(_road_length(d, "nan"))), message=r"length"))
    add(Case("maps-check-agrees-on-absurd-road", lambda ws, d: T("maps", "check", str(_road_length(d, "1e300").parent), "--reference", str(esmini("reference"))),
             exit=(1,), message=r"FAIL .*length"))
    add(Case("maps-info-doctype", lambda ws, d: T("maps", "info", str(_doctype(esmini("xodr", "straight_500m.xodr"), d))), message=r"DOCTYPE",
             kept=no_leak("root:x:0")))
    add(Case("maps-info-geometry-nan", lambda ws, d: T("maps", "info", str(_replace_attr(esmini("xodr", "curves.xodr"), d, r'(<geometry[^>]* x=")[^"]*"', r'\g<1>nan"'))),
             message=r"(finite|nan)"))
    add(Case("maps-info-missing", lambda ws, d: T("maps", "info", str(d / "none.xodr")), message=r"none\.xodr"))
    add(Case("maps-info-empty-file", lambda ws, d: T("maps", "info", str(_write(d, "e.xodr", b""))), message=r"e\.xodr"))
    add(Case("maps-locate-nan", lambda ws, d: T("maps", "locate", str(esmini("xodr", "straight_500m.xodr")), "nan", "0"), message=r"(finite|x)"))
    add(Case("maps-check-missing-dir", lambda ws, d: T("maps", "check", str(d / "nodir"), "--reference", str(esmini("reference"))), message=r"nodir"))

    # ---- conformance ------------------------------------------------------------------------------------------
    add(Case("conformance-missing-dir", lambda ws, d: T("conformance", str(d / "nodir"), "--reference", str(esmini("reference"))), message=r"nodir"))
    add(Case("conformance-missing-reference", lambda ws, d: T("conformance", str(esmini("xosc")), "--reference", str(d / "noref")), message=r"noref"))
    add(Case("conformance-one-corrupt-file", lambda ws, d: T("conformance", str(_conformance_dir(d)), "--reference", str(esmini("reference")), "--brief"),
             exit=(1,), message=r"straight_500m\.xosc\s+no", kept=kept_lines(r"^cut-in_simple\.xosc\s+yes")))

    # ---- judge / replay: recordings and oracle configs ------------------------------------------------------
    for k in range(1, 5):
        add(Case(f"judge-flipped-bytes-{k}-then-good-bag", lambda ws, d, k=k: T("judge", str(_flipped_bag(ws, d, k)), str(ws / "bags" / "good")),
                 exit=(1, 2), message=r"(error|damaged|flip|broken|cannot)", kept=kept_lines(r"bags/good\t")))
    add(Case("judge-garbage-mcap-then-good-bag", lambda ws, d: T("judge", str(_write(d, "junk/j.mcap", b"not an mcap")), str(ws / "bags" / "good")),
             message=r"nothing readable", kept=kept_lines(r"bags/good\t")))
    add(Case("judge-missing-bag-then-good-bag", lambda ws, d: T("judge", str(d / "nobag"), str(ws / "bags" / "good")),
             message=r"nobag", kept=kept_lines(r"bags/good\t")))
    add(Case("judge-truncated-metadata", lambda ws, d: T("judge", str(_bad_metadata(ws, d)), str(ws / "bags" / "good")),
             exit=(0, 1, 2), message=r"bags/good\t", kept=kept_lines(r"bags/good\t")))
    add(Case("judge-config-unknown-section", lambda ws, d: T("judge", str(ws / "bags" / "good"), "--config", str(_oracle_cfg(d, lambda t: t.replace("smoothness:", "smothness:", 1)))),
             message=r"smothness"))
    add(Case("judge-config-nan-threshold", lambda ws, d: T("judge", str(ws / "bags" / "good"), "--config", str(_oracle_cfg(d, lambda t: re.sub(r"(jerk_threshold:\s*)[0-9.]+", r"\g<1>.nan", t, count=1)))),
             message=r"(finite|nan)"))
    add(Case("judge-config-negative-threshold", lambda ws, d: T("judge", str(ws / "bags" / "good"), "--config", str(_oracle_cfg(d, lambda t: re.sub(r"(jerk_threshold:\s*)([0-9.]+)", r"\g<1>-\g<2>", t, count=1)))),
             message=r"(negative|> ?0|>= ?0|range)"))
    add(Case("judge-config-not-yaml", lambda ws, d: T("judge", str(ws / "bags" / "good"), "--config", str(_write(d, "o.yaml", "safety: [unclosed\n"))),
             message=r"o\.yaml"))
    add(Case("judge-config-missing", lambda ws, d: T("judge", str(ws / "bags" / "good"), "--config", str(d / "none.yaml")),
             message=r"none\.yaml"))
    add(Case("replay-rate-zero", lambda ws, d: T("replay", str(ws / "bags" / "good"), "--rate", "0"), message=r"rate"))
    add(Case("replay-rate-nan", lambda ws, d: T("replay", str(ws / "bags" / "good"), "--rate", "nan"), message=r"rate"))
    add(Case("replay-garbage-mcap", lambda ws, d: T("replay", str(_write(d, "j.mcap", b"not an mcap"))),
             message=r"j\.mcap: not an MCAP file", env={"ROS_DOMAIN_ID": "37", "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}))
    add(Case("bag-plot-garbage-mcap", lambda ws, d: T("bag-plot", str(_write(d, "j.mcap", b"not an mcap")), "--out", str(d / "p.png")),
             message=r"j\.mcap: not an MCAP file"))
    add(Case("replay-missing-bag", lambda ws, d: T("replay", str(d / "nobag")), message=r"nobag",
             env={"ROS_DOMAIN_ID": "37", "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}))

    # ---- tree / xosc / eval-extract / fidelity --------------------------------------------------------------
    add(Case("tree-one-corrupt-seed", lambda ws, d: T("tree", str(_corrupt_one_seed(ws, d)), "--out", "trees", "--max-nodes", "6", "--jobs", "1"),
             exit=(1,), message=r"(broken|error|FAIL|refused)", timeout=120,
             kept=lambda ws, d, s: "" if len(list((d / "trees").glob("*/manifest.json"))) >= len(seed_ids(ws)) - 1 else "good trees lost"))
    add(Case("tree-missing-input", lambda ws, d: T("tree", str(d / "noseeds"), "--out", "trees"), message=r"noseeds"))
    add(Case("tree-prune-nan", lambda ws, d: T("tree", str(ws / "seeds"), "--out", "trees", "--prune", "nan"), message=r"prune"))
    add(Case("tree-mutations-negative", lambda ws, d: T("tree", str(ws / "seeds"), "--out", "trees", "--mutations", "-3"), message=r"mutations"))
    add(Case("xosc-validate-garbage-beside-good", lambda ws, d: T("xosc", "validate", "--no-qc", str(_write(d, "g.xosc", "<<<")), str(good_seed(ws))),
             exit=(1,), message=r"g\.xosc", kept=kept_lines(r"\.xosc: ok")))
    add(Case("xosc-validate-billion-laughs", lambda ws, d: T("xosc", "validate", str(_doctype(good_seed(ws), d, LAUGHS))),
             exit=(1,), message=r"DOCTYPE", timeout=30))
    add(Case("eval-extract-missing-gold", lambda ws, d: T("eval-extract", "--gold", str(d / "nogold.jsonl"), "--pred", str(SKETCHES(ws))),
             message=r"nogold"))
    add(Case("eval-extract-non-utf8-pred", lambda ws, d: T("eval-extract", "--gold", str(SKETCHES(ws)), "--pred", str(_with_bad_row(SKETCHES(ws), d, _non_utf8_row(SKETCHES(ws))))),
             exit=(0,), message=r"\d"))
    add(Case("fidelity-non-utf8-row", lambda ws, d: T("fidelity", str(_with_bad_row(SKETCHES(ws), d, _non_utf8_row(SKETCHES(ws))))),
             exit=(1,), message=r"not UTF-8", timeout=120))
    add(Case("fidelity-dt-zero", lambda ws, d: T("fidelity", str(SKETCHES(ws)), "--dt", "0"), message=r"dt"))

    # ---- configuration files (TXT2SCE_CONFIG) -------------------------------------------------------------
    add(_cfg_case("config-player-unknown-key", "player", lambda t: t.replace("  dt: 0.05", "  dtt: 0.05"), r"dtt"))
    add(_cfg_case("config-player-dt-nan", "player", lambda t: t.replace("  dt: 0.05", "  dt: .nan"), r"dt"))
    add(_cfg_case("config-player-not-mapping", "player", lambda t: "- a\n- b\n", r"player\.yaml"))
    add(_cfg_case("config-planner-unknown-section", "planner", lambda t: "bogus_section: {a: 1}\n" + t, r"bogus_section", cmd="campaign"))

    # ---- campaign -------------------------------------------------------------------------------------------
    add(Case("campaign-non-utf8-report-row", lambda ws, d: T("campaign", str(_with_bad_row(REPORTS(ws), d, _non_utf8_row(REPORTS(ws)))), "--out", "camp",
                                                                "--max-seeds", "1", "--max-nodes", "4", "--executor", "serial", "--no-progress", "--no-report"),
             exit=(1,), message=r"not UTF-8", timeout=240, kept=kept_runs(1)))
    add(Case("campaign-time-limit-negative", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", "camp", "--time-limit", "-5"), message=r"time.limit"))
    add(Case("campaign-time-limit-nan", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", "camp", "--time-limit", "nan"), message=r"time.limit"))
    add(Case("campaign-workers-zero", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", "camp", "--workers", "0"), message=r"workers"))
    add(Case("campaign-prune-out-of-range", lambda ws, d: T("campaign", str(ws / "seeds"), "--out", "camp", "--prune", "1.5"), message=r"prune"))
    add(Case("campaign-unknown-fault", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", "camp", "--fault", "no_such_fault"), message=r"no_such_fault"))
    add(Case("campaign-out-is-file", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", str(_write(d, "afile", "x"))), message=r"error: .*(not a directory|exists)"))
    add(Case("campaign-corrupt-results-sqlite", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", str(_corrupt_store(d)), "--executor", "serial", "--no-progress"),
             message=r"results\.sqlite"))
    add(Case("campaign-mixed-inputs", lambda ws, d: T("campaign", str(good_seed(ws)), str(REPORTS(ws)), "--out", "camp"), message=r"mix"))
    add(Case("campaign-bad-manifest", lambda ws, d: T("campaign", str(_bad_manifest(ws, d)), "--out", "camp"), message=r"manifest"))
    add(Case("campaign-ros-planner-killed", lambda ws, d: T("campaign", str(good_seed(ws)), "--out", "camp", "--ros", "--executor", "serial", "--no-progress", "--no-report"),
             exit=(1,), message=r"planner process (exit status|killed by)", timeout=300, during=kill_node("planner_node", times=3),
             kept=kept_runs(1)))
    return c


def _cfg_case(name: str, cfg: str, edit, message: str, cmd: str = "play") -> Case:
    def argv(ws: Path, d: Path) -> list[str]:
        _config_dir(d, cfg, edit)
        if cmd == "campaign":
            return T("campaign", str(good_seed(ws)), "--out", "camp", "--executor", "serial", "--no-progress")
        return T("play", str(good_seed(ws)))
    # the config directory is made inside the case directory; the runner starts the command there
    return Case(name, argv, message=message, env={"TXT2SCE_CONFIG": "config"})


def _many_parties(obj: dict) -> None:
    template = {"id": "npc1", "category": "car", "position": "R1", "actions": "a"}
    obj["npcs"] = [dict(template, id=f"npc{i}") for i in range(1, 2001)]


def _no_overwrite(ws: Path, d: Path, stdout: str) -> str:
    manifest = json.loads((d / "out" / "manifest.json").read_text())
    files = [b["file"] for b in manifest["built"]]
    if len(files) != len(set(files)):
        return f"two manifest entries share a file: {files}"
    on_disk = {p.name for p in (d / "out").glob("*.xosc")}
    missing = set(files) - on_disk
    return f"manifest names files not on disk: {missing}" if missing else ""


def _many_entities(ws: Path, d: Path, n: int) -> Path:
    text = good_seed(ws).read_text(encoding="utf-8")
    m = re.search(r"<ScenarioObject name=\"([^\"]+)\">.*?</ScenarioObject>", text, re.S)
    assert m
    block = m.group(0)
    extra = "".join(block.replace(f'name="{m.group(1)}"', f'name="extra{i}"', 1) for i in range(n))
    return _write(d, "many.xosc", text.replace("</Entities>", extra + "</Entities>", 1))


def _road_length(d: Path, value: str) -> Path:
    src = esmini("xodr", "straight_500m.xodr")
    return _replace_attr(src, d / "maps", r'(<road[^>]*length=")[^"]*"', rf'\g<1>{value}"', name="straight_500m.xodr")


def _conformance_dir(d: Path) -> Path:
    out = d / "xosc"
    out.mkdir()
    for name in ("cut-in_simple.xosc", "straight_500m.xosc"):
        shutil.copy(esmini("xosc", name), out / name)
    shutil.copytree(esmini("xosc", "Catalogs"), out / "Catalogs")
    (out / "straight_500m.xosc").write_bytes((out / "straight_500m.xosc").read_bytes()[:900])
    # the scenarios name their maps relative to themselves: ../xodr
    shutil.copytree(esmini("xodr"), d / "xodr")
    return out


def _flipped_bag(ws: Path, d: Path, seed: int) -> Path:
    bag = copy_bag(ws, d / "flipped")
    _flip(mcap_of(bag), seed)
    return bag


def _bad_metadata(ws: Path, d: Path) -> Path:
    bag = copy_bag(ws, d / "meta")
    (bag / "metadata.yaml").write_text("rosbag2_bagfile_information:\n  version: [", encoding="utf-8")
    return bag


def _oracle_cfg(d: Path, edit) -> Path:
    from txt2sce_ros.paths import REPO_ROOT

    return _write(d, "oracle.yaml", edit((REPO_ROOT / "config" / "oracle.yaml").read_text(encoding="utf-8")))


def _corrupt_one_seed(ws: Path, d: Path) -> Path:
    seeds = _seed_copy(ws, d)
    victim = seeds / json.loads((seeds / "manifest.json").read_text())["built"][-1]["file"]
    victim.write_bytes(victim.read_bytes()[: len(victim.read_bytes()) // 2])
    return seeds


def _corrupt_store(d: Path) -> Path:
    camp = d / "camp"
    camp.mkdir()
    (camp / "results.sqlite").write_bytes(b"SQLite format 3\x00" + os.urandom(0) + b"\x13" * 4000)
    return camp


def _bad_manifest(ws: Path, d: Path) -> Path:
    seeds = _seed_copy(ws, d)
    (seeds / "manifest.json").write_text('{"built": [{"nofile": 1}]', encoding="utf-8")
    return seeds
