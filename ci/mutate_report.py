"""The mutation self-test's verdicts and reports: sorting no-change mutants into judged
equivalents and escapes (ci/mutate-equivalent.json), the score, and mutation.md/json."""

import json
from pathlib import Path

JUDGED = Path(__file__).resolve().parent / "mutate-equivalent.json"


def load_judged():
    return json.loads(JUDGED.read_text()) if JUDGED.exists() else {}


def classify(record, judged):
    """no-change mutants become `equivalent` when judged so for the same line, else `escape`."""
    if record["status"] != "no-change":
        return record["status"]
    j = judged.get(record["id"])
    if j and j.get("before") == record["before"]:
        record["why"] = j["why"]
        return "equivalent"
    return "escape"


def summarize(records, judged, args):
    counts = {}
    for r in records:
        r["verdict"] = classify(r, judged)
        counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
    caught = counts.get("caught", 0)
    scored = caught + counts.get("survived", 0) + counts.get("escape", 0)
    score = caught / scored if scored else None
    return {"seed": args.seed, "max": args.max,
            "whole_tree": bool(getattr(args, "whole_tree", False)), "counts": counts,
            "scored": scored, "score": score, "mutants": records}


def write_reports(out, summary):
    (out / "mutation.json").write_text(json.dumps(summary, indent=1) + "\n")
    c = summary["counts"]
    lines = ["# Mutation self-test", "",
             f"seed {summary['seed']}{', --whole-tree' if summary.get('whole_tree') else ''}, "
             f"{len(summary['mutants'])} mutants: "
             + ", ".join(f"{k} {v}" for k, v in sorted(c.items())), ""]
    if summary["score"] is not None:
        lines += [f"**score: {c.get('caught', 0)} / {summary['scored']} = "
                  f"{100 * summary['score']:.1f}%** (caught / (caught + survived + escapes))", ""]
    lines += ["| verdict | id | line | mutation | detail |", "|---|---|---|---|---|"]
    for r in summary["mutants"]:
        detail = r.get("why") or r["detail"]
        lines.append(f"| {r['verdict']} | `{r['id']}` | {r['line']} | `{r['before']}` -> "
                     f"`{r['after']}` | {detail.replace('|', '/')} |")
    (out / "mutation.md").write_text("\n".join(lines) + "\n")
