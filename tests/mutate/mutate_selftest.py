#!/usr/bin/env python3
"""Cheap checks of ci/mutate.py (the mutation loop itself never runs in ctest): the sample is
reproducible and covers both groups and every operator; ids survive a rename; every operator's
mutant changes exactly its line and restoring leaves the file byte-identical. Works on a copy
of the sources, never the tree. Exit 0 pass, 1 fail."""

import contextlib
import io
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "ci"))
sys.path.insert(0, str(ROOT / "tests" / "support"))
import mutate  # noqa: E402
import mutate_ops as ops  # noqa: E402
from selfcheck import SelfCheck  # noqa: E402

check = SelfCheck("mutate selftest")


def listing(*extra, own_process=False):
    """`mutate.py build --list EXTRA`'s lines: in a process of its own, or here, where the
    files are scanned once for all the listings (each process scans the whole tree)."""
    if own_process:
        r = subprocess.run([sys.executable, str(ROOT / "ci" / "mutate.py"), "build", "--list", *extra],
                           capture_output=True, text=True)
        code, out, err = r.returncode, r.stdout, r.stderr
    else:
        out_buf, err_buf, argv = io.StringIO(), io.StringIO(), sys.argv
        sys.argv = ["mutate.py", "build", "--list", *extra]
        try:
            with contextlib.redirect_stdout(out_buf), contextlib.redirect_stderr(err_buf):
                code = mutate.main()
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else 1
        finally:
            sys.argv = argv
        out, err = out_buf.getvalue(), err_buf.getvalue()
    check(code == 0, f"--list {' '.join(extra)} exits 0: {err}")
    return out.splitlines()


# Two processes: a sample that hung on the process (hash seeds, set order) would differ here.
first = listing("--seed", "7", "--max", "40", own_process=True)
second = listing("--seed", "7", "--max", "40", own_process=True)
check(len(first) == 40, f"--max 40 lists 40 mutants (got {len(first)})")
check(first == second, "--list is the same twice")
check(first != listing("--seed", "8", "--max", "40"), "another seed picks another sample")
ids = [line.split("\t")[0] for line in first]
check(len(set(ids)) == len(ids), "ids are unique")
check(any(i.startswith("shaders/") for i in ids) and any(i.startswith("harness/") for i in ids),
      "the sample covers shaders and harness code")
only = listing("--only", ids[3])
check(len(only) == 1 and only[0] == first[3], "--only ID lists that mutant")

with tempfile.TemporaryDirectory() as tmp:
    copy = Path(tmp)
    for folder in ("shaders", "harness/compare", "harness/golden", "harness/invariants"):
        shutil.copytree(ROOT / folder, copy / folder)
    every = ops.all_mutants(copy)
    by_op = {}
    for m in every:
        by_op.setdefault(m.op, m)
    expected_ops = {"cmp", "bound", "minmax", "arith", "float", "int", "delete", "cond-true",
                    "cond-false"}
    check(set(by_op) == expected_ops, f"every operator has sites (got {sorted(by_op)})")
    for op, m in sorted(by_op.items()):
        path = copy / m.file
        before = path.read_bytes()
        original = ops.apply(copy, m)
        mutated = path.read_bytes()
        old_lines, new_lines = before.decode().split("\n"), mutated.decode().split("\n")
        diff = [i for i, (a, b) in enumerate(zip(old_lines, new_lines)) if a != b]
        check(len(old_lines) == len(new_lines) and diff == [m.line - 1],
              f"{m.id}: changes exactly line {m.line}")
        check(new_lines[m.line - 1].strip() == m.after, f"{m.id}: writes the listed mutation")
        ops.restore(copy, m, original)
        check(path.read_bytes() == before, f"{m.id}: restore leaves the file byte-identical")

    # A rename (what a refactor of shader constants does) keeps every id of the file.
    cas = copy / "shaders" / "cas.comp"
    ids_before = [m.id for m in ops.file_mutants(copy, "shaders/cas.comp", "shader")]
    cas.write_text(cas.read_text().replace("crossMin", "crossLowest").replace("boxMax", "hiBox"))
    ids_after = [m.id for m in ops.file_mutants(copy, "shaders/cas.comp", "shader")]
    check(ids_before and ids_before == ids_after, "renaming identifiers keeps the mutant ids")

    # Comments, strings and #include lines are never mutated.
    probe = copy / "harness" / "compare" / "probe_fixture.cpp"
    probe.write_text('#include <vector>\n// a < b + 1\nconst char* s = "x < 2";\n/* if (a) */\n')
    check(ops.file_mutants(copy, "harness/compare/probe_fixture.cpp", "harness") == [],
          "no sites in comments, strings or includes")

# --resume keeps a stored verdict only for a mutant whose line still reads as it did.
import json  # noqa: E402
import mutate_runner  # noqa: E402

with tempfile.TemporaryDirectory() as tmp:
    out = Path(tmp)
    sample = [m for m in ops.all_mutants(ROOT) if m.kind == "shader"][:3]
    stored = [dict(m.as_json(), status="caught", detail="x", seconds=1.0) for m in sample[:2]]
    stored[1]["before"] = "a line as it read before an edit"
    (out / "mutation.json").write_text(json.dumps({"mutants": stored}))
    kept = mutate.resumed(out, sample)
    check(list(kept) == [sample[0].id], f"--resume keeps exactly the unchanged judged mutant (got {list(kept)})")

    # Where a user shader's SPIR-V came from is not an output: cached or compiled, the same.
    def results(provenance, workgroup="8x8"):
        run = out / "run"
        run.mkdir(exist_ok=True)
        log = [f"pass user_resolve u.comp (glsl, SPIR-V {provenance}) workgroup {workgroup}", "frame 0"]
        (run / "results.json").write_text(json.dumps({"cases": [{"name": "u", "log": log}]}))
        return mutate_runner.case_outputs(run)
    cold, warm = results("compiled by glslang: no cache entry"), results("from the cache")
    check(cold == warm, "a user shader's SPIR-V provenance does not make a case's outputs differ")
    check(cold != results("from the cache", "4x4"), "the rest of the line still counts")

# shared.h is C++ too: its mutant is edited in the tree and rebuilds the SPIR-V and the harness
# (a copy of the GLSL side alone left the C++ side reading the old value: a false survivor).
# Other shader mutants stay in their private copy; harness mutants rebuild the same targets.
every = ops.all_mutants(ROOT)
shared = next(m for m in every if m.file == "shaders/common/shared.h")
shader = next(m for m in every if m.kind == "shader" and m.file.endswith(".comp"))
harness = next(m for m in every if m.kind == "harness")
check({"taa_shaders", "taa-harness", "taa_tests"} <= set(ops.tree_targets(shared)),
      f"{shared.id} rebuilds the SPIR-V, the harness and the tests (got {ops.tree_targets(shared)})")
check(ops.tree_targets(harness) == ["taa-harness", "taa_tests"],
      f"{harness.id} rebuilds the harness and the tests, no SPIR-V (got {ops.tree_targets(harness)})")
check(ops.tree_targets(shader) == [], f"{shader.id} is built into a copy, the tree untouched")
order = [line.split("\t")[0] for line in listing("--max", "200")]
in_tree = [i for i in order if i.startswith("harness/") or i.startswith("shaders/common/shared.h")]
check(in_tree and order[-len(in_tree):] == in_tree,
      "mutants edited in the tree run after every mutant built into a copy")

# --whole-tree (issue 46): every file with logic and three more operators, leaving the
# default listing (the 200-mutant sample's) exactly as it was.
whole = ops.all_mutants(ROOT, whole_tree=True)
whole_files = {m.file for m in whole}
for folder in ("renderer/user/", "renderer/scene/", "renderer/frame/", "renderer/passes/",
               "renderer/script/", "harness/run/", "harness/lanes/", "harness/score/",
               "harness/sweep/", "harness/report/", "harness/cli/", "core/", "shaders/user/"):
    check(any(f.startswith(folder) for f in whole_files), f"--whole-tree mutates {folder}")
check("shaders/user/taa_user_header.cpp" in whole_files, "--whole-tree mutates the header tool")
check({"key", "size", "prev-cur"} <= {m.op for m in whole}, "--whole-tree has the three new operators")
default_all = listing("--all")
check(not any(f":{op}:" in line.split("\t")[0] for line in default_all
              for op in ops.WHOLE_TREE_OPS), "without --whole-tree no new operator is listed")
check(not any(line.startswith(("renderer/", "core/", "shaders/user/")) for line in default_all),
      "without --whole-tree the files are the 200-mutant sample's")
check(set(default_all) <= {f"{m.id}\tline {m.line}\t{m.before}  ->  {m.after}" for m in whole},
      "--whole-tree keeps every id the default listing has, on the same line")
sample = [line.split("\t")[0] for line in listing("--whole-tree", "--max", "300", "--seed", "46",
                                                  "--harness-share", "0.8")]
check(len(sample) == 300 and any(i.startswith("renderer/") for i in sample),
      "the 300-sample of issue 46 lists 300 mutants over the renderer too")
check({"key", "size", "prev-cur"} <= {i.split(":")[1] for i in sample},
      "the 300-sample draws each new operator")

with tempfile.TemporaryDirectory() as tmp:
    copy = Path(tmp)
    (copy / "renderer" / "frame").mkdir(parents=True)
    probe = copy / "renderer" / "frame" / "probe.cpp"
    probe.write_text("\n".join([
        "void f(const State& s, Uniforms& u, Hasher& h, std::string& key, int stride) {",
        "  h.update(name.data(), name.size());",
        '  key += "mode=" + mode;',
        '  add(key, "has no effect unless set");',
        "  u.viewProj = s.prevCamera.viewProjection;",
        "  glm::vec2 camera = s.camera.size;",
        "  std::memcpy(dst, src, n * sizeof(float));",
        "  std::snprintf(buf, sizeof(buf), fmt, v);",
        "  const int at = y * stride + x;",
        "  return prevCamera;",
        "}", ""]))
    found = {(m.op, m.after) for m in ops.file_mutants(copy, "renderer/frame/probe.cpp", "harness")
             if m.op in ops.WHOLE_TREE_OPS}
    for op, after in (("key", ""), ("key", ""),
                      ("prev-cur", "u.viewProj = s.camera.viewProjection;"),
                      ("size", "std::memcpy(dst, src, n * (sizeof(float) * 2));"),
                      ("size", "const int at = y * (stride + 1) + x;"),
                      ("prev-cur", "return camera;")):
        check((op, after) in found, f"{op} site: {after or '(line deleted)'}")
    mutants = ops.file_mutants(copy, "renderer/frame/probe.cpp", "harness")
    keys = [m.before for m in mutants if m.op == "key"]
    check(keys == ["h.update(name.data(), name.size());", 'key += "mode=" + mode;'],
          f"key drops hash and key-string feeds, not a message (got {keys})")
    check(not any(m.op == "size" and "snprintf" in m.before for m in mutants),
          "no size site in a buffer capacity handed to a formatter")
    check(not any(m.op == "prev-cur" and m.before.startswith("glm::vec2 camera") and
                  m.after.startswith("glm::vec2 prevCamera") for m in mutants),
          "a declared name is not renamed")
    for m in (m for m in mutants if m.op in ops.WHOLE_TREE_OPS):
        before = probe.read_bytes()
        original = ops.apply(copy, m)
        lines = probe.read_text().split("\n")
        check(lines[m.line - 1].strip() == m.after and len(lines) == len(before.decode().split("\n")),
              f"{m.id}: writes the listed mutation on its line")
        ops.restore(copy, m, original)
        check(probe.read_bytes() == before, f"{m.id}: restore leaves the file byte-identical")

# Per-file rebuilds: C++ rebuilds the harness and the tests, a user header's source only the
# headers; the mutant after a user header's rebuilds the headers too, so the restored one
# reaches the build folder before it runs.
by_file = {}
for m in whole:
    by_file.setdefault(m.file, m)
cpp = [by_file[f] for f in sorted(by_file) if f.startswith(("renderer/", "core/"))]
check(cpp and all(ops.tree_targets(m) == ["taa-harness", "taa_tests"] for m in cpp),
      "renderer/ and core/ mutants rebuild the harness and the tests")
header = by_file["shaders/user/taa_user.h.in"]
check(ops.tree_targets(header) == ["taa_user_h"], f"{header.id} rebuilds the user headers only")
check(ops.build_targets(cpp[0], ops.tree_targets(header)) == ["taa-harness", "taa_tests", "taa_user_h"],
      "after a user header's mutant the next mutant rebuilds the restored headers too")
check(ops.build_targets(shader, ops.tree_targets(header)) == [],
      "a shader mutant built into a copy builds nothing in the tree")

# A shader mutant meets the GPU tests of its pass under the names they use: the tracer's are
# adaptive_*, the resolve's (shaders/taa/) resolve_* (the history clamp's firefly test).
check(any(src.name == "resolve_tone_weight_test.cpp"
          for src in mutate_runner.test_sources("shaders/taa/color_space.glsl")),
      "a shaders/taa/ mutant runs tests/renderer/resolve_*_test.cpp")

check.finish()
