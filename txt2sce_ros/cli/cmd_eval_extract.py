"""`txt2sce eval-extract --gold FILE [--pred FILE | --input FILE]`: Table IV and the extra slots, with counts and
the worst slots' confusions; `--form-labels FILE` adds agreement with the company-filed labels."""

from __future__ import annotations

import argparse

from .argtypes import count

HELP = "measure extraction against gold sketches (paper's Table IV) and/or company form labels"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--gold", help="gold sketches (JSONL), e.g. ../shared/data/reports/dev_gold.jsonl")
    src = parser.add_mutually_exclusive_group(required=True)
    src.add_argument("--pred", help="predicted sketches (JSONL written by `txt2sce extract`)")
    src.add_argument("--input", help="reports to extract now (JSONL {id, text}, .txt, dir, PDF)")
    parser.add_argument("--form-labels", help="company-filed labels (dev_form_labels.jsonl): agreement, separately")
    parser.add_argument("--worst", type=count(ge=0), default=4, help="slots in the confusion listing (default 4)")
    parser.add_argument("--hybrid-ceiling", action="store_true",
                        help="with --input: also score `hybrid` with a perfect model answering each question it "
                             "asks (the most a model can add there; no model is run)")
    parser.add_argument("--check-targets", action="store_true",
                        help="exit 1 when a slot with a target (issue 3) falls below it")


def run(args: argparse.Namespace) -> int:
    from ..errors import InputError
    from ..sketch import Sketch, load_sketches
    from ..text.evaluate import TARGETS, evaluate, evaluate_by_source, format_diagnostics, format_table
    from ..text.forms import form_agreement, format_agreement, load_form_labels

    if not args.gold and not args.form_labels:
        raise InputError("give --gold and/or --form-labels", element="--gold")
    if args.hybrid_ceiling and not (args.gold and args.input):
        raise InputError("--hybrid-ceiling needs --gold and --input (the rules' weak flags are read as they "
                         "extract)", element="--hybrid-ceiling")
    if args.pred:
        results = list(load_sketches(args.pred))
    else:
        from ..text.pipeline import run_batch
        from ..text.readers import iter_inputs

        results = list(run_batch(iter_inputs([args.input])))
    preds = {s.report_id: s for s in results if isinstance(s, Sketch)}
    seen = {s.report_id for s in results}  # error records count: as wrong, not as absent
    status = 0
    if args.gold:
        gold = []
        for g in load_sketches(args.gold):
            if not isinstance(g, Sketch):
                raise InputError(f"bad gold line: {g.error}", source=args.gold)
            gold.append(g)
        scored = [g for g in gold if g.report_id in seen]
        if not scored:
            raise InputError("no gold report id occurs in the predictions", source=args.pred or args.input)
        ev = evaluate(scored, preds)
        if len(scored) < len(gold):
            print(f"({len(gold) - len(scored)} gold reports not among the predictions: left out)")
        print(format_table(ev, worst=args.worst))
        print()
        print(format_diagnostics(ev, evaluate_by_source(scored, preds)))
        if args.hybrid_ceiling:
            from ..text.ceiling import PerfectModel, format_ceiling
            from ..text.pipeline import run_batch
            from ..text.readers import iter_inputs

            model = PerfectModel({g.report_id: g for g in scored})
            ceiling = {s.report_id: s for s in run_batch(iter_inputs([args.input]), backend="hybrid", llm=model)
                       if isinstance(s, Sketch)}
            print()
            print(format_ceiling(ev, evaluate(scored, ceiling), model))
        if args.check_targets and any(ev.accuracy(k) < v for k, v in TARGETS.items()):
            status = 1
    if args.form_labels:
        if args.gold:
            print()
        print(format_agreement(form_agreement(load_form_labels(args.form_labels), preds)))
    return status
