"""`txt2sce extract INPUT... --out FILE.jsonl`: reports -> sketches, one JSONL line per report (sketch or error)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

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
    parser.add_argument("--timeout", type=float, default=None, help="LLM request timeout, s")
    parser.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")


def run(args: argparse.Namespace) -> int:
    from ..config import load_config
    from ..sketch import ErrorRecord
    from ..text.pipeline import run_batch
    from ..text.readers import count_inputs, iter_inputs

    cfg = load_config("extract")
    backend = args.backend or cfg.get("backend", "offline")
    llm = None
    if backend != "offline":
        from ..text.llm import LlmConfig, LlmExtractor

        llm = LlmExtractor.from_config(LlmConfig.from_settings(cfg.get("llm"), base_url=args.base_url,
                                                               model=args.model, timeout_s=args.timeout))
    total = count_inputs(args.inputs)
    results = run_batch(iter_inputs(args.inputs), backend=backend, llm=llm)
    if not args.quiet and total and total >= int(cfg.get("progress_min_reports", 50)):
        from tqdm import tqdm

        results = tqdm(results, total=total, unit="report", file=sys.stderr, desc="extract")
    out = Path(args.out)
    if out.parent and not out.parent.exists():
        out.parent.mkdir(parents=True, exist_ok=True)
    n = errors = incomplete = 0
    with open(out, "w", encoding="utf-8") as fh:
        for r in results:
            fh.write(r.to_json() + "\n")
            n += 1
            if isinstance(r, ErrorRecord):
                errors += 1
                # the reason belongs on the console, not only in the output file (quiet or not: it is an error)
                if errors <= MAX_ERRORS_SHOWN:
                    print(f"txt2sce extract: error: {r.report_id}: {r.error}", file=sys.stderr)
            elif not r.is_buildable:
                incomplete += 1
    if errors > MAX_ERRORS_SHOWN:
        print(f"txt2sce extract: ... and {errors - MAX_ERRORS_SHOWN} more errors (every one is in {out})",
              file=sys.stderr)
    if not args.quiet:
        print(f"{n} reports -> {out}: {n - errors - incomplete} buildable sketches, {incomplete} incomplete "
              f"(missing facts), {errors} errors", file=sys.stderr)
    # A batch carries on past bad rows (each has its error record), but a batch where nothing could be read is
    # a failure the caller should see in the exit status.
    return 1 if n and errors == n else 0
