"""Report -> sketch: the text side of txt2sce (paper §III-B.1), offline by default.

Public API:
- `extractor.extract(text, report_id) -> Sketch`: the rule-based offline extractor (deterministic, no network).
- `readers.iter_inputs(paths)`: .txt files, directories, JSONL `{id, text}`, OL 316 PDFs -> `ReportInput` or
  `ErrorRecord`; `pdf.read_ol316(path)`: section 5 narrative + check boxes, read by `ol316/` (text layer, form
  fields, Tesseract OCR for scans; boxes by geometry); `ol316.score`: the reader against `forms.jsonl`.
- `pipeline.sketch_report(inp, backend=...)` / `pipeline.run_batch(inputs, ...)`: one sketch or error per input,
  backends `offline`, `llm`, `hybrid`; OL 316 boxes merged by `forms.merge_form`.
- `llm.LlmExtractor` / `llm.LlmConfig`: the multi-turn dialogue over any OpenAI-compatible server (prompts in
  `prompts/`, answers cached on disk by model + prompt hash; the API key only from the environment).
- `evaluate.evaluate(gold, predicted)` / `evaluate.format_table(...)`: Table IV and the extra slots;
  `forms.form_agreement(...)`: agreement with the company-filed labels.

CLI: `txt2sce extract`, `txt2sce eval-extract`, `txt2sce eval-pdf`, `txt2sce bench extract`. Record types live in `txt2sce_ros.sketch`.
"""
