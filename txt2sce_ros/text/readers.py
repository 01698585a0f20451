"""Report inputs: plain text files, directories of .txt/.pdf, JSON Lines (`{id, text}`), OL 316 PDFs.

Every input row yields a `ReportInput` or an `ErrorRecord`; a bad row never stops the batch.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

from ..errors import InputError
from ..sketch import ErrorRecord, iter_jsonl
from .pdf import FormFields, read_ol316


@dataclass(frozen=True)
class ReportInput:
    report_id: str
    text: str
    source: str
    form: FormFields | None = None  # an OL 316 PDF's check boxes, when the input was the PDF


def _read_jsonl(p: Path) -> Iterator[ReportInput | ErrorRecord]:
    for lineno, row in iter_jsonl(p):
        src = f"{p}:{lineno}"
        if isinstance(row, InputError):
            yield ErrorRecord(f"{p.stem}-line{lineno}", str(row), src)
            continue
        if not isinstance(row, dict):
            yield ErrorRecord(f"{p.stem}-line{lineno}", f"{src}: a row must be an object {{id, text}}", src)
            continue
        rid = str(row.get("id") or row.get("report_id") or f"{p.stem}-line{lineno}")
        text = row.get("text")
        if not isinstance(text, str) or not text.strip():
            yield ErrorRecord(rid, f"{src}: <text>: missing or empty narrative", src)
            continue
        yield ReportInput(report_id=rid, text=text, source=src)


def _read_one(p: Path) -> Iterator[ReportInput | ErrorRecord]:
    suffix = p.suffix.lower()
    try:
        if suffix == ".jsonl":
            yield from _read_jsonl(p)
        elif suffix == ".pdf":
            doc = read_ol316(p)
            yield ReportInput(report_id=p.stem, text=doc.narrative, source=str(p), form=doc.form)
        else:
            text = p.read_text(encoding="utf-8", errors="replace")
            if not text.strip():
                raise InputError("empty narrative", source=str(p))
            yield ReportInput(report_id=p.stem, text=text, source=str(p))
    except InputError as exc:
        yield ErrorRecord(p.stem, str(exc), str(p))
    except OSError as exc:
        yield ErrorRecord(p.stem, f"{p}: cannot read: {exc.strerror}", str(p))


def iter_inputs(paths: Iterable[str | Path]) -> Iterator[ReportInput | ErrorRecord]:
    """Each report of each input path, in order; a directory contributes its .txt, .pdf and .jsonl files sorted
    by name."""
    for raw in paths:
        p = Path(raw)
        if p.is_dir():
            files = sorted(f for f in p.iterdir() if f.suffix.lower() in (".txt", ".pdf", ".jsonl") and f.is_file())
            if not files:
                yield ErrorRecord(p.name, f"{p}: directory holds no .txt, .pdf or .jsonl file", str(p))
            for f in files:
                yield from _read_one(f)
        elif p.exists():
            yield from _read_one(p)
        else:
            yield ErrorRecord(p.stem or str(p), f"{p}: file not found", str(p))


def count_inputs(paths: Iterable[str | Path]) -> int | None:
    """A cheap estimate of the number of reports (JSONL lines, files), for the progress bar; None if unknown."""
    n = 0
    for raw in paths:
        p = Path(raw)
        files = sorted(p.iterdir()) if p.is_dir() else [p]
        for f in files:
            if f.suffix.lower() == ".jsonl" and f.is_file():
                with open(f, "rb") as fh:
                    n += sum(1 for line in fh if line.strip())
            elif f.is_file():
                n += 1
    return n
