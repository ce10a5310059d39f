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
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(HERE, "..", "support"))
from selfcheck import SelfCheck  # noqa: E402

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

check = SelfCheck("run_shard_selftest", verbose=True)


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
    check(status != 0, "a shard with a failing test exits non-zero", str(status))
    rc, text = suite(out, "Alpha")
    check(rc != 0, "the failing suite's test fails", text)
    check("Expected 1, was 2" in text and "[  FAILED  ] Alpha.Bad" in text, "with the failure's text", text)
    rc, text = suite(out, "Beta")
    check(rc == 0 and "[  PASSED  ] 1 tests." in text, "an instantiated parameterized suite passes under its own name", text)
    rc, text = suite(out, "Gamma")
    check(rc == 0 and "[  PASSED  ] 0 tests" in text, "an all-skipped suite prints what ctest reads as skipped", text)
    rc, text = suite(out, "Delta")
    check(rc == 0 and "alone Delta.*:*/Delta.*" in text, "a suite the shard did not report runs alone", text)
    rc, text = suite(out, "Delta", alone_exit=1)
    check(rc != 0, "and fails when it fails alone", text)

    status, out = shard(tmp, "crash", ["Alpha"])
    check(status != 0, "a shard that died fails", str(status))
    check(not os.path.exists(os.path.join(out, "Alpha.txt")), "and leaves no verdict")
    rc, text = suite(out, "Alpha")
    check("alone Alpha" in text, "so its suites run alone", text)

    status, out = shard(tmp, report, ["Beta"])
    check(status == 0, "a shard of passing suites passes", str(status))
    check(not os.path.exists(os.path.join(out, "Alpha.txt")), "and writes no verdict of a suite it was not given")

check.finish()
