#!/usr/bin/env python3
"""Which unit shard runs each GoogleTest suite (tests/CMakeLists.txt), so that the shards take
about the same time.

    shard_plan.py plan COSTS SHARDS TESTS_DIR FILE...     prints "SHARD SUITE" for every suite
    shard_plan.py measure COSTS TESTS_DIR REPORT...        rewrites COSTS from gtest JSON reports

The unit of placement is a group of test files: files that share a suite (a fixture used in
several files) must run in one process, since a shard runs a suite whole. Groups go, most
expensive first, to the shard with the least time so far (longest processing time first). A
group's time is the sum of its files' seconds in COSTS; a file COSTS does not list (a new one)
counts as the median file. Stale or missing costs only make the shards less even: every suite
is placed whatever COSTS says.
"""
import json
import os
import re
import statistics
import sys

SUITE = re.compile(r"^(?:TEST|TEST_F|TEST_P)\(([A-Za-z0-9_]+),", re.M)


def suites_of(path):
    with open(path, encoding="utf-8") as f:
        return sorted(set(SUITE.findall(f.read())))


def read_costs(path):
    costs = {}
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            parts = line.split()
            try:
                if len(parts) != 2 or float(parts[1]) < 0:
                    raise ValueError
                costs[parts[0]] = float(parts[1])
            except ValueError:
                sys.exit(f"{path}:{n}: expected 'FILE SECONDS', got {line!r}; regenerate it with "
                         f"`{os.path.basename(__file__)} measure` (see its first lines)")
    return costs


def groups_of(files):
    """Files joined by a shared suite, each group as (files, suites), in the files' order."""
    owner = {}  # suite -> group index
    groups = []
    for path, suites in files:
        joined = sorted({owner[s] for s in suites if s in owner})
        if not joined:
            groups.append(([path], set(suites)))
            index = len(groups) - 1
        else:
            index = joined[0]
            for other in reversed(joined[1:]):  # merge later groups into the first
                groups[index][0].extend(groups[other][0])
                groups[index][1].update(groups[other][1])
                groups[other] = ([], set())
            groups[index][0].append(path)
            groups[index][1].update(suites)
        for s in groups[index][1]:
            owner[s] = index
    return [g for g in groups if g[0]]


def plan(costs, shards, tests_dir, paths):
    files = []
    for p in paths:
        suites = suites_of(p)
        if suites:
            files.append((os.path.relpath(p, tests_dir), suites))
    default = statistics.median(costs.values()) if costs else 1.0
    weighed = []
    for names, suites in groups_of(files):
        weighed.append((sum(costs.get(n, default) for n in names), min(names), suites))
    weighed.sort(key=lambda g: (-g[0], g[1]))
    load = [0.0] * shards
    placed = []
    for seconds, _, suites in weighed:
        shard = min(range(shards), key=lambda i: (load[i], i))
        load[shard] += seconds
        placed += [(s, shard + 1) for s in suites]
    return sorted(placed), load


def measure(costs_path, tests_dir, reports):
    seconds = {}
    for report in reports:
        with open(report, encoding="utf-8") as f:
            for suite in json.load(f)["testsuites"]:
                for t in suite["testsuite"]:
                    name = os.path.relpath(t["file"], tests_dir)
                    seconds[name] = seconds.get(name, 0.0) + float(t["time"].rstrip("s"))
    with open(costs_path + ".tmp", "w", encoding="utf-8") as f:
        f.write("# Seconds each test file's tests took in the unit shards of one `ctest -j2` run right\n"
                "# after the main job, both caches empty first (tests/unit/shard_plan.py places the\n"
                "# suites by them). Regenerate after such a run:\n"
                "#   python3 tests/unit/shard_plan.py measure tests/unit/shard_costs.txt tests \\\n"
                "#       build/ctest-out/unit-shards/*/gtest.json\n")
        for name in sorted(seconds):
            f.write(f"{name} {seconds[name]:.2f}\n")
    os.replace(costs_path + ".tmp", costs_path)


def main(argv):
    if len(argv) >= 5 and argv[1] == "plan":
        placed, load = plan(read_costs(argv[2]), int(argv[3]), argv[4], argv[5:])
        for suite, shard in placed:
            print(shard, suite)
        print("shard seconds (from the costs): " + ", ".join(f"{s:.1f}" for s in load), file=sys.stderr)
        return 0
    if len(argv) >= 5 and argv[1] == "measure":
        measure(argv[2], argv[3], argv[4:])
        return 0
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
