#!/usr/bin/env python3
"""Mutation self-test: does the suite notice when the shaders or the comparison code break?

Applies one small mutation at a time (ci/mutate_ops.py: flipped comparisons, min/max swaps,
+/- swaps, off-by-one integers, changed float constants, deleted statements, conditions
replaced by true/false) to the shaders and to the harness's comparison code, rebuilds the
given build folder incrementally, runs the suite and sorts the mutant into

  caught      the suite failed: `taa-harness run cases --fail-fast` exited non-zero, or (for a
              harness mutant) a unit test of the mutated folder failed;
  no-change   the suite passed and every case's frame hashes and verdicts equal the
              unmutated run's: an equivalent mutant, or a change no case drives the code
              into. ci/mutate-equivalent.json holds the ones judged equivalent (with why);
              the others count as escapes;
  survived    the suite passed although an output changed;
  stillborn   it does not build (not counted).

score = caught / (caught + survived + escapes). Every file is restored byte for byte after
each mutant, on Ctrl-C and on SIGTERM too; a run killed harder leaves a backup that the next
run restores first. See docs/mutation.md.

  ci/mutate.py build --list                    # the seeded sample: id, line, before -> after
  nice -n 15 ci/mutate.py build --out out/mutate > out/mutate.log 2>&1 &
  ci/mutate.py build --only 'shaders/cas.comp:minmax:3'
"""

import argparse
import json
import signal
import sys
import time
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import mutate_ops as ops  # noqa: E402
from mutate_report import load_judged, summarize, write_reports  # noqa: E402
from mutate_runner import Runner, log  # noqa: E402

ROOT = ops.repo_root()


class Interrupted(Exception):
    pass


def _on_signal(signum, _frame):
    # Once: the restore and the rebuild that follow must not be cut short by a second signal.
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    raise Interrupted(f"signal {signum}")


def backup_path(out):
    return out / "restore-backup.json"


def restore_leftover(out):
    """A run killed with SIGKILL leaves its backup: put that file back first."""
    b = backup_path(out)
    if b.exists():
        data = json.loads(b.read_text())
        (ROOT / data["file"]).write_bytes(bytes.fromhex(data["original"]))
        b.unlink()
        log(f"restored {data['file']} left mutated by an interrupted run")
        return True
    return False


def resumed(out, chosen):
    """id -> the stored record of each chosen mutant an earlier run of OUT judged, where the
    mutated line's text is still what it was (a changed line is judged again)."""
    f = out / "mutation.json"
    if not f.is_file():
        return {}
    stored = {r["id"]: r for r in json.loads(f.read_text()).get("mutants", [])}
    keep = {}
    for m in chosen:
        r = stored.get(m.id)
        if r and r.get("before") == m.before and r.get("after") == m.after:
            keep[m.id] = r
    return keep


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("build", help="an existing CMake build folder (rebuilt incrementally)")
    p.add_argument("--list", action="store_true", help="print the selected mutants and exit")
    p.add_argument("--all", action="store_true", help="with --list: every site, not the sample")
    p.add_argument("--only", action="append", default=[], metavar="ID",
                   help="run these mutants (repeatable), whatever the sample")
    p.add_argument("--also", action="append", default=[], metavar="ID",
                   help="add these mutants to the sample (repeatable)")
    p.add_argument("--whole-tree", action="store_true",
                   help="mutate every file with logic (renderer/, harness/, core/, the user "
                        "headers' sources) with the key/size/prev-cur operators too (issue 46); "
                        "without it, the files and operators of the 200-mutant sample")
    p.add_argument("--max", type=int, default=60, help="sample size (default 60)")
    p.add_argument("--seed", type=int, default=12, help="sample seed (default 12)")
    p.add_argument("--harness-share", type=float, default=0.3,
                   help="share of the sample from the harness's comparison code (default 0.3)")
    p.add_argument("--jobs", type=int, default=2,
                   help="workers of each mutant's `taa-harness run -j N` (default 2)")
    p.add_argument("--cases", default=str(ROOT / "cases"), help="case folder (default cases/)")
    p.add_argument("--out", default=str(ROOT / "out" / "mutate"), help="report folder")
    p.add_argument("--fresh-baseline", action="store_true", help="rerun the unmutated suite")
    p.add_argument("--unit-timeout", type=int, default=900)
    p.add_argument("--resume", action="store_true",
                   help="keep the verdicts of OUT's mutation.json for mutants of this sample "
                        "whose text is unchanged, and run only the others")
    p.add_argument("--rejudge", action="store_true",
                   help="rewrite OUT's report from its mutation.json with the current "
                        "ci/mutate-equivalent.json, running nothing")
    args = p.parse_args()
    if args.rejudge:
        report = Path(args.out).resolve()
        if not (report / "mutation.json").is_file():
            print(f"mutate: {report / 'mutation.json'} does not exist: --rejudge rewrites the report "
                  "of an earlier run; pass that run's --out", file=sys.stderr)
            return 2
        stored = json.loads((report / "mutation.json").read_text())
        summary = summarize(stored["mutants"], load_judged(), args)
        summary.update(seed=stored["seed"], max=stored["max"],
                       whole_tree=stored.get("whole_tree", False))
        write_reports(report, summary)
        print(f"{report / 'mutation.md'}: " + ", ".join(f"{k} {v}" for k, v in sorted(summary["counts"].items())))
        return 0

    every = ops.all_mutants(ROOT, args.whole_tree)
    by_id = {m.id: m for m in every}
    unknown = [i for i in args.only + args.also if i not in by_id]
    if unknown:
        sys.exit(f"mutate: no mutant {', '.join(unknown)} (see --list --all)")
    if args.only:
        chosen = [by_id[i] for i in args.only]
    else:
        chosen = every if args.all else ops.select(every, args.seed, args.max, args.harness_share)
        chosen += [by_id[i] for i in args.also if by_id[i] not in chosen]
    # Shader mutants built into a copy first: they need only the SPIR-V rebuilt. Those edited
    # in the tree (harness, shared.h) last, each rebuilding the build folder from the tree.
    chosen.sort(key=lambda m: (bool(ops.tree_targets(m)), m.kind != "shader"))
    if args.list:
        for m in chosen:
            print(f"{m.id}\tline {m.line}\t{m.before}  ->  {m.after}")
        return 0

    out = Path(args.out).resolve()
    (out / "work").mkdir(parents=True, exist_ok=True)
    leftover = restore_leftover(out)
    signal.signal(signal.SIGTERM, _on_signal)
    signal.signal(signal.SIGINT, _on_signal)
    runner = Runner(args)
    if leftover and not runner.ninja(ops.TREE_TARGETS, out / "work" / "restore-build.log"):
        sys.exit(f"mutate: the restored tree does not build (see {out}/work/restore-build.log)")
    base_outputs, ordered, total = runner.baseline()
    log(f"baseline: {len(base_outputs)} cases, {total:.0f} s; {len(chosen)} mutants")
    records, judged = [], load_judged()
    done = resumed(out, chosen) if args.resume else {}
    if done:
        log(f"resume: {len(done)} verdicts kept from {out / 'mutation.json'}")
    try:
        for n, m in enumerate(chosen, 1):
            if m.id in done:
                records.append(done[m.id])
                continue
            start = time.monotonic()
            if not ops.tree_targets(m):
                status, detail = runner.judge(m, base_outputs, ordered, total)
            else:
                original = (ROOT / m.file).read_bytes()
                backup_path(out).write_text(json.dumps({"file": m.file, "original": original.hex()}))
                try:
                    ops.apply(ROOT, m)
                    status, detail = runner.judge(m, base_outputs, ordered, total)
                finally:
                    ops.restore(ROOT, m, original)
                    backup_path(out).unlink()
                    # The build folder now holds the mutant: the next build restores it.
                    runner.stale |= set(ops.tree_targets(m))
            rec = dict(m.as_json(), status=status, detail=detail,
                       seconds=round(time.monotonic() - start, 1))
            records.append(rec)
            log(f"[{n}/{len(chosen)}] {status:9} {m.id} ({rec['seconds']} s): {detail}")
            # The verdicts kept from OUT that lie further on go in too: a run that stops here
            # (a crash, kill -9) must not lose what it has not reached yet.
            ahead = [done[c.id] for c in chosen[n:] if c.id in done]
            write_reports(out, summarize(records + ahead, judged, args))
    except Interrupted as e:
        log(f"interrupted ({e}): every file restored; partial report in {out}")
        return 130
    finally:
        # Leave the build folder matching the restored sources.
        rebuilt = sorted({t for m in chosen for t in ops.tree_targets(m)})
        if rebuilt:
            runner.ninja(rebuilt, out / "work" / "final-build.log")
    summary = summarize(records, judged, args)
    write_reports(out, summary)
    c = summary["counts"]
    log("done: " + ", ".join(f"{k} {v}" for k, v in sorted(c.items())) +
        (f"; score {100 * summary['score']:.1f}%" if summary["score"] is not None else ""))
    log(f"report: {out / 'mutation.md'}, {out / 'mutation.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
