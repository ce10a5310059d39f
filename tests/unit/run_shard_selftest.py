#!/usr/bin/env python3
"""Checks tests/unit/run_shard.py and suite.cmake with a stand-in for taa_tests: a failure, a
parameterized suite, an all-skipped suite, a suite that ran nothing, and a process that died
before writing its report each reach the suite's ctest test as running the suite alone would.

    run_shard_selftest.py CMAKE
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
CMAKE = sys.argv[1]

# A stand-in test binary: writes the gtest JSON report of the tests in $FAKE_REPORT (a Python
# literal), or dies without one when it is "crash"; run with a filter alone, prints it.
FAKE = r'''#!/usr/bin/env python3
import json, os, sys
args = dict(a.split("=", 1) for a in sys.argv[1:])
if "--gtest_output" not in args:
    print("alone " + args["--gtest_filter"])
    sys.exit(int(os.environ.get("FAKE_ALONE_EXIT", "0")))
spec = os.environ["FAKE_REPORT"]
if spec == "crash":
    sys.exit(134)
wanted = {p.split("/")[-1][:-2] for p in args["--gtest_filter"].split(":")}
suites = []
for name, tests in eval(spec).items():
    if name.split("/")[-1] in wanted:
        suites.append({"name": name, "testsuite": [dict(classname=name, time="0.1s", **t) for t in tests]})
with open(args["--gtest_output"][len("json:"):], "w") as f:
    json.dump({"testsuites": suites}, f)
sys.exit(1 if any(t.get("failures") for s in suites for t in s["testsuite"]) else 0)
'''

failures = 0


def check(what, ok, detail=""):
    global failures
    print(("ok   " if ok else "FAIL ") + what + ("" if ok else ": " + detail))
    failures += 0 if ok else 1


def shard(tmp, report, suites):
    out = os.path.join(tmp, "out")
    env = dict(os.environ, FAKE_REPORT=report)
    r = subprocess.run([sys.executable, os.path.join(HERE, "run_shard.py"), fake, out] + suites,
                       env=env, capture_output=True, text=True)
    return r.returncode, out


def suite(out, name, alone_exit=0):
    env = dict(os.environ, FAKE_ALONE_EXIT=str(alone_exit))
    r = subprocess.run([CMAKE, f"-DTEST_BINARY={fake}", f"-DSUITE={name}",
                        f"-DVERDICT={os.path.join(out, name + '.txt')}", "-DSHARD=unit.shard1", "-P",
                        os.path.join(HERE, "suite.cmake")], env=env, capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


with tempfile.TemporaryDirectory() as tmp:
    fake = os.path.join(tmp, "fake_tests")
    with open(fake, "w") as f:
        f.write(FAKE)
    os.chmod(fake, 0o755)

    report = repr({
        "Alpha": [{"name": "Good"}, {"name": "Bad", "failures": [{"failure": "a_test.cpp:7\nExpected 1, was 2"}]}],
        "Paths/Beta": [{"name": "Each/0"}],
        "Gamma": [{"name": "Skips", "result": "SKIPPED"}],
    })
    status, out = shard(tmp, report, ["Alpha", "Beta", "Gamma", "Delta"])
    check("a shard with a failing test exits non-zero", status != 0, str(status))
    rc, text = suite(out, "Alpha")
    check("the failing suite's test fails", rc != 0, text)
    check("with the failure's text", "Expected 1, was 2" in text and "[  FAILED  ] Alpha.Bad" in text, text)
    rc, text = suite(out, "Beta")
    check("an instantiated parameterized suite passes under its own name", rc == 0 and "[  PASSED  ] 1 tests." in text, text)
    rc, text = suite(out, "Gamma")
    check("an all-skipped suite prints what ctest reads as skipped", rc == 0 and "[  PASSED  ] 0 tests" in text, text)
    rc, text = suite(out, "Delta")
    check("a suite the shard did not report runs alone", rc == 0 and "alone Delta.*:*/Delta.*" in text, text)
    rc, text = suite(out, "Delta", alone_exit=1)
    check("and fails when it fails alone", rc != 0, text)

    status, out = shard(tmp, "crash", ["Alpha"])
    check("a shard that died fails", status != 0, str(status))
    check("and leaves no verdict", not os.path.exists(os.path.join(out, "Alpha.txt")))
    rc, text = suite(out, "Alpha")
    check("so its suites run alone", "alone Alpha" in text, text)

    status, out = shard(tmp, report, ["Beta"])
    check("a shard of passing suites passes", status == 0, str(status))
    check("and writes no verdict of a suite it was not given", not os.path.exists(os.path.join(out, "Alpha.txt")))

sys.exit(1 if failures else 0)
