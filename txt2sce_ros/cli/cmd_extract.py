"""`txt2sce extract INPUT... --out FILE.jsonl`: reports -> sketches, one JSONL line per report (sketch or error)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .argtypes import POSITIVE, count

#: Error reasons printed on the console; the rest are counted (all of them are in the output file).
MAX_ERRORS_SHOWN = 10

HELP = "read accident reports (.txt, dir, JSONL {id,text}, OL 316 PDF) into report sketches (JSONL)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("inputs", nargs="+", metavar="INPUT",
                        help="a .txt narrative, a directory of .txt/.pdf, a JSONL file of {id, text}, an OL 316 PDF")
    parser.add_argument("--out", "-o", required=True, help="output JSONL: one sketch or error record per report")
    parser.add_argument("--backend", choices=("offline", "llm", "hybrid"), default=None,
                        help="offline rules (default), an LLM dialogue, or rules + LLM for incomplete reports")
    parser.add_argument("--base-url", default=None, help="OpenAI-compatible server (default DeepSeek; env "
                                                          "TXT2SCE_LLM_BASE_URL)")
    parser.add_argument("--model", default=None, help="model name (default deepseek-chat; env TXT2SCE_LLM_MODEL)")
    parser.add_argument("--timeout", type=POSITIVE, default=None, help="LLM request timeout, s")
    parser.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")
    parser.add_argument("--workers", "-j", type=count(ge=1, le=64), default=None,
                        help="processes for an offline batch of 200+ reports (default: config `workers`, 'auto' = "
                             "the usable cores, at most 8); the output is the same whatever the count")


def run(args: argparse.Namespace) -> int:
    from ..config import load_config
    from ..sketch import ErrorRecord
    from ..text.pipeline import echo_errors, run_batch
    from ..text.readers import ReportInput, count_inputs, iter_inputs

    cfg = load_config("extract")
    backend = args.backend or cfg.get("backend", "offline")
    llm = None
    if backend != "offline":
        from ..text.llm import configured_llm

        llm = configured_llm(backend, cfg.get("llm"), base_url=args.base_url, model=args.model,
                             timeout_s=args.timeout)
    total = count_inputs(args.inputs)
    inputs = list(iter_inputs(args.inputs))  # kept: the PDFs' form readings are written beside the sketches
    out = Path(args.out)
    workers = args.workers or _config_workers(cfg.get("workers", "auto"))
    results = echo_errors(run_batch(inputs, backend=backend, llm=llm, workers=workers), "txt2sce extract",
                          where=str(out), limit=MAX_ERRORS_SHOWN)
    if not args.quiet and total and total >= int(cfg.get("progress_min_reports", 50)):
        from tqdm import tqdm

        results = tqdm(results, total=total, unit="report", file=sys.stderr, desc="extract")
    if out.parent and not out.parent.exists():
        out.parent.mkdir(parents=True, exist_ok=True)
    n = errors = incomplete = 0
    failed_pdfs: list[str] = []
    with open(out, "w", encoding="utf-8") as fh:
        for r in results:
            fh.write(r.to_json() + "\n")
            n += 1
            if isinstance(r, ErrorRecord):
                errors += 1
                if str(r.source or "").lower().endswith(".pdf"):
                    failed_pdfs.append(r.report_id)
            elif not r.is_buildable:
                incomplete += 1
    forms = [i for i in inputs if isinstance(i, ReportInput) and i.form is not None]
    if forms:
        _write_form_readings(out, forms)
    if not args.quiet:
        print(f"{n} reports -> {out}: {n - errors - incomplete} buildable sketches, {incomplete} incomplete "
              f"(missing facts), {errors} errors", file=sys.stderr)
        if forms:
            print(f"OL 316 form readings beside the sketches: {_forms_path(out)}", file=sys.stderr)
        if failed_pdfs:
            print(f"no narrative read from {len(failed_pdfs)} PDF(s): {', '.join(failed_pdfs)}", file=sys.stderr)
    if llm is not None and llm.not_consulted:
        ids = [rid for rid, _ in llm.not_consulted]
        print(f"txt2sce extract: warning: the LLM server failed for {len(ids)} report(s), whose offline rules' "
              f"sketch was kept ({', '.join(ids[:MAX_ERRORS_SHOWN])}{' ...' if len(ids) > MAX_ERRORS_SHOWN else ''}; "
              f"last: {llm.not_consulted[-1][1]})", file=sys.stderr)
    # A batch carries on past bad rows (each has its error record): 1 when some failed (a PDF whose narrative
    # could not be read counts: its sketch would be empty; so does a hybrid report the server did not answer),
    # 2 when nothing at all was usable.
    if errors and errors == n:
        return 2
    return 1 if errors or failed_pdfs or (llm is not None and llm.not_consulted) else 0


def _config_workers(value: object) -> int:
    from ..errors import InputError
    from ..text.pipeline import default_workers

    if value in (None, "auto"):
        return default_workers()
    if isinstance(value, int) and not isinstance(value, bool) and value >= 1:
        return value
    raise InputError(f"config/extract.yaml: workers must be 'auto' or a whole number >= 1, not {value!r}")


def _forms_path(out: Path) -> Path:
    return out.with_name(f"{out.stem}.ol316.jsonl")


def _write_form_readings(out: Path, inputs: list) -> None:
    """Beside the sketches: each OL 316 PDF's own reading (its boxes, the company's collision type and movements,
    how it was read) and where it disagrees with the narrative, which decided."""
    import json

    from ..sketch import Sketch, load_sketches
    from ..text.forms import form_disagreements, form_sketch_fields

    sketches = {s.report_id: s for s in load_sketches(out) if isinstance(s, Sketch)}
    with open(_forms_path(out), "w", encoding="utf-8") as fh:
        for inp in inputs:
            sk = sketches.get(inp.report_id)
            notes = list(inp.form.notes) + (form_disagreements(sk, inp.form) if sk else [])
            fh.write(json.dumps({"report_id": inp.report_id, "source": inp.source, "read_as": inp.form.read_as,
                                 "form": inp.form.to_dict(), "form_reading": form_sketch_fields(inp.form),
                                 "notes": notes}, ensure_ascii=False) + "\n")
