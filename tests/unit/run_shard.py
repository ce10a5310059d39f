#!/usr/bin/env python3
"""Runs a shard of the GoogleTest suites in one taa_tests process, for ctest (tests/CMakeLists.txt),
and writes each suite's verdict to OUT/SUITE.txt, which that suite's own ctest test then reports
(tests/unit/suite.cmake). A suite whose file is missing (the process crashed before gtest wrote
its report, or the suite ran no test) runs by itself there instead.

    run_shard.py TAA_TESTS OUT SUITE...
"""
import json
import os
import subprocess
import sys


def suite_of(name):
    # "Suite", or "Prefix/Suite" for an instantiation of a value-parameterized suite.
    return name.split("/")[1] if "/" in name else name


def verdict(tests):
    lines, failed, ran = [], False, 0
    for t in tests:
        name = f"{t['classname']}.{t['name']}"
        if t.get("failures"):
            failed = True
            lines.append(f"[  FAILED  ] {name} ({t['time']})")
            lines += [f["failure"] for f in t["failures"]]
        elif t.get("result") == "SKIPPED":
            lines.append(f"[  SKIPPED ] {name}")
        else:
            ran += 1
            lines.append(f"[       OK ] {name} ({t['time']})")
    # "[  PASSED  ] 0 tests" is what a run of the suite alone prints when every test skipped:
    # the suite's ctest test shows as skipped on it (SKIP_REGULAR_EXPRESSION).
    if not failed:
        lines.append(f"[  PASSED  ] {ran} tests.")
    return "\n".join(["failed" if failed else "passed"] + lines) + "\n"


def main():
    binary, out, suites = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(out, exist_ok=True)
    report = os.path.join(out, "gtest.json")
    # A verdict from an earlier run of this shard must not stand for this one.
    for stale in [report] + [os.path.join(out, s + ".txt") for s in suites]:
        if os.path.exists(stale):
            os.remove(stale)
    pattern = ":".join(f"{s}.*:*/{s}.*" for s in suites)
    status = subprocess.call([binary, f"--gtest_filter={pattern}", f"--gtest_output=json:{report}"])
    if not os.path.exists(report):
        print(f"run_shard: {binary} wrote no report (exit {status}); its suites run by themselves")
        return status or 1
    with open(report) as f:
        ran = json.load(f)["testsuites"]
    by_suite = {}
    for s in ran:
        by_suite.setdefault(suite_of(s["name"]), []).extend(s["testsuite"])
    for suite, tests in by_suite.items():
        if suite in suites:
            with open(os.path.join(out, suite + ".txt"), "w") as f:
                f.write(verdict(tests))
    return status


if __name__ == "__main__":
    sys.exit(main())
