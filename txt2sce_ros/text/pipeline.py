"""One report input -> a sketch or an error record, with the chosen backend; batches never stop on a bad row."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from functools import lru_cache, partial
from typing import TYPE_CHECKING, Literal

from ..errors import SimulationFault, Txt2SceError
from ..sketch import ErrorRecord, Sketch, validate_sketch_dict
from .extractor import extract, extract_weighed
from .forms import merge_form
from .readers import ReportInput

if TYPE_CHECKING:
    from .llm import LlmExtractor

Backend = Literal["offline", "llm", "hybrid"]
BACKENDS: tuple[str, ...] = ("offline", "llm", "hybrid")


@lru_cache(maxsize=1)
def default_llm() -> LlmExtractor:
    """The LLM client configured by `config/extract.yaml` and the environment (for callers that pass none)."""
    from ..config import load_config
    from .llm import LlmConfig, LlmExtractor

    return LlmExtractor.from_config(LlmConfig.from_settings(load_config("extract").get("llm")))


def sketch_report(inp: ReportInput, *, backend: Backend = "offline", llm: LlmExtractor | None = None,
                  validate: bool = True) -> Sketch | ErrorRecord:
    """Extract one report. Errors raised on purpose become an ErrorRecord naming the report; so does a sketch
    that fails the schema (a bug, reported rather than written)."""
    try:
        if backend == "offline":
            sk = extract(inp.text, inp.report_id)
        elif backend not in BACKENDS:
            return ErrorRecord(inp.report_id, f"unknown backend {backend!r} (one of {', '.join(BACKENDS)})",
                               inp.source)
        elif backend == "llm":
            llm = llm or default_llm()
            sk = llm.extract(inp.text, inp.report_id)
        else:
            rules, weak = extract_weighed(inp.text, inp.report_id)
            llm = llm or default_llm()
            try:
                sk = llm.refine(rules, inp.text, weak)
            except SimulationFault as exc:
                # The server failed, not the report: the rules' reading stands (the batch says so at its end).
                llm.not_consulted.append((inp.report_id, str(exc)))
                sk = rules
        sk = merge_form(sk, inp.form)
    except Txt2SceError as exc:
        return ErrorRecord(inp.report_id, str(exc), inp.source)
    if validate:
        problems = validate_sketch_dict(sk.to_dict())
        if problems:
            return ErrorRecord(inp.report_id, f"{inp.report_id}: produced an invalid sketch: {problems[0]}",
                               inp.source)
    return sk


#: Below this many reports a batch runs in this process: starting workers costs more than it saves.
PARALLEL_MIN_REPORTS = 200
#: Reports handed to a worker at a time (fewer round trips; small enough to keep both cores busy to the end).
_CHUNK = 16


def _one(inp: ReportInput | ErrorRecord, **kw: object) -> Sketch | ErrorRecord:
    return inp if isinstance(inp, ErrorRecord) else sketch_report(inp, **kw)  # type: ignore[arg-type]


def run_batch(inputs: Iterable[ReportInput | ErrorRecord], *, workers: int = 1,
              **kw: object) -> Iterator[Sketch | ErrorRecord]:
    """Sketches (or error records) for every input, in order. `workers` > 1 spreads an offline batch of at least
    `PARALLEL_MIN_REPORTS` over that many processes: each report is read alone, so the output is the same, in the
    same order, as one process gives. The LLM backends stay in this process (their requests are the cost)."""
    if workers > 1 and kw.get("backend", "offline") == "offline" and kw.get("llm") is None:
        items = list(inputs)
        if len(items) >= PARALLEL_MIN_REPORTS:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor

            # fork: the workers start with the extractor already imported and its patterns compiled (built here
            # first: they are compiled on first use, and each worker would otherwise build its own).
            from .fastre import build_all

            build_all()
            ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else None
            with ProcessPoolExecutor(max_workers=workers, mp_context=ctx) as pool:
                yield from pool.map(partial(_one, **kw), items, chunksize=_CHUNK)
            return
        inputs = items
    for inp in inputs:
        yield _one(inp, **kw)


def default_workers() -> int:
    """Processes for a large offline batch: the cores this process may use, at most 8."""
    import os

    try:
        n = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        n = os.cpu_count() or 1
    return max(1, min(8, n))


def echo_errors(items: Iterable[Sketch | ErrorRecord], prog: str, *, where: str, limit: int = 10,
                ) -> Iterator[Sketch | ErrorRecord]:
    """Pass `items` through, printing each error record's reason on stderr (the first `limit`, then a count): a
    report that could not be read must be visible on the console, not only in the output file `where`."""
    import sys

    errors = 0
    for item in items:
        if isinstance(item, ErrorRecord):
            errors += 1
            if errors <= limit:
                # The reason often names the report already (an InputError's source): say it once.
                reason = item.error.removeprefix(f"{item.report_id}: ")
                print(f"{prog}: error: {item.report_id}: {reason}", file=sys.stderr)
        yield item
    if errors > limit:
        print(f"{prog}: ... and {errors - limit} more errors (every one is in {where})", file=sys.stderr)
