"""The mutation self-test's runner: builds a mutant (the shaders into a private copy, the
harness in place), runs the unit suites of the mutated folder and the case suite, and
compares every case's outputs with the unmutated run's."""

import json
import os
import re
import shutil
import signal
import sys
import subprocess
import time
from pathlib import Path

import mutate_ops as ops

ROOT = ops.repo_root()
# Unit tests per mutated folder: the suites of the matching tests/ folder (run first: cheap).
UNIT_TEST_DIRS = {"harness/compare": ["tests/compare"],
                  "harness/golden": ["tests/golden", "tests/harness"],
                  "harness/invariants": ["tests/invariants"],
                  "harness/run": ["tests/harness", "tests/golden"],
                  "harness/case": ["tests/case", "tests/audit"],
                  # --whole-tree (issue 46): each folder's own tests/ twin, the CLI and run
                  # tests (tests/harness) for the harness's other folders.
                  "harness/cli": ["tests/harness"],
                  "harness/lanes": ["tests/harness"],
                  "harness/score": ["tests/harness"],
                  "harness/sweep": ["tests/harness"],
                  "harness/report": ["tests/report", "tests/harness"],
                  "core": ["tests/core"],
                  "renderer/scene": ["tests/scene"],
                  "renderer/script": ["tests/script"],
                  "renderer/user": ["tests/user"],
                  "shaders/user": ["tests/user"],
                  "renderer/passes": ["tests/renderer", "tests/effects"],
                  "renderer/frame": ["tests/renderer", "tests/effects"],
                  "renderer/api": ["tests/renderer"],
                  "renderer/vk": ["tests/renderer"]}
VOLATILE_KEYS = ("seconds", "timings", "date", "ms")  # wall and GPU times


def log(*parts):
    print(time.strftime("%H:%M:%S"), *parts, flush=True)


# Shader folders whose tests are named after the pass that uses them: shaders/trace/ is the
# adaptive pass's tracer, and its tests (adaptive_shading_test.cpp's traced vertex colours)
# say adaptive, not trace.
# Likewise shaders/taa/ is the resolve pass, and its GPU tests in tests/renderer say resolve
# (resolve_tone_weight_test.cpp checks the history clamp of taa/color_space.glsl).
PASS_ALIASES = {"trace": ("adaptive",), "taa": ("resolve",)}


def pass_word(rel):
    """The pass a shader file belongs to, as run logs and tests name it: cas.comp -> cas,
    tscmaa/zshape.glsl -> tscmaa, taa/rectify.glsl -> taa, motion_blur.comp -> motion."""
    path = Path(rel)
    word = path.parent.name if path.parent.name not in ("shaders", "common") else path.stem
    return word.split("_")[0]


def test_sources(rel):
    """Harness files: the tests of the matching tests/ folder. Shader files: the GPU tests
    (tests/renderer, tests/effects) whose file name holds the pass's or the file's name."""
    if rel.startswith("shaders/"):
        words = (pass_word(rel), Path(rel).stem) + PASS_ALIASES.get(pass_word(rel), ())
        return [src for d in ("tests/renderer", "tests/effects")
                for src in sorted((ROOT / d).glob("*_test.cpp"))
                if any(src.name.startswith(w + "_") or "_" + w + "_" in src.name for w in words)]
    return [src for d in UNIT_TEST_DIRS.get(str(Path(rel).parent), [])
            for src in sorted((ROOT / d).glob("*_test.cpp"))]


def unit_suites(rel):
    suites = []
    for src in test_sources(rel):
        for line in src.read_text().splitlines():
            if line.startswith(("TEST(", "TEST_F(", "TEST_P(")):
                suite = line.split("(", 1)[1].split(",", 1)[0].strip()
                if suite not in suites:
                    suites.append(suite)
    return suites


def strip_volatile(value):
    if isinstance(value, dict):
        return {k: strip_volatile(v) for k, v in value.items()
                if not any(k == key or k.endswith("_" + key) for key in VOLATILE_KEYS)}
    if isinstance(value, list):
        return [strip_volatile(v) for v in value]
    return value


# Where a user shader's SPIR-V came from (glslang or the cache) depends on what ran before, not
# on the code: the baseline compiles it and every mutant's run finds it cached.
SPIRV_PROVENANCE = re.compile(r"SPIR-V (from the cache|compiled by glslang: no cache entry|"
                              r"recompiled by glslang: [^)]*)")


def case_outputs(run_dir):
    """name -> the case's results without timings and with the output folder written as <out>
    (frame hashes, status, metrics, invariants), from one run's results.json."""
    f = run_dir / "results.json"
    if not f.exists():
        return {}
    text = f.read_text().replace(str(run_dir), "<out>")
    text = SPIRV_PROVENANCE.sub("SPIR-V <provenance>", text)
    return {c["name"]: strip_volatile(c) for c in json.loads(text).get("cases", [])}


class Runner:
    def __init__(self, args):
        self.args = args
        self.build = Path(args.build).resolve()
        self.out = Path(args.out).resolve()
        self.harness = self.build / "harness" / "taa-harness"
        self.tests = self.build / "tests" / "taa_tests"
        self.cases = sorted(Path(args.cases).resolve().glob("*.json"))
        self.env = dict(os.environ, CI="false")  # a missing golden is a skip, as locally
        # Targets the build folder holds from a restored tree mutant, until a build succeeds:
        # one that failed (a stillborn mutant) may have stopped before it rebuilt them.
        self.stale = set()

    def ninja(self, targets, log_file):
        with open(log_file, "w") as f:
            return subprocess.run(["ninja", "-C", str(self.build), *targets], stdout=f,
                                  stderr=subprocess.STDOUT).returncode == 0

    def run_cases(self, ordered, out_dir, fail_fast, timeout):
        """Runs the cases in one `taa-harness run -j N` (N = --jobs): N workers, each on its
        own device, the results in case order; with fail_fast the first failing case stops
        the run."""
        shutil.rmtree(out_dir, ignore_errors=True)
        out_dir.mkdir(parents=True)
        jobs = max(1, min(self.args.jobs, len(ordered)))
        cmd = [str(self.harness), "run", *map(str, ordered), "-j", str(jobs), "--out", str(out_dir)]
        if fail_fast:
            cmd.append("--fail-fast")
        with open(out_dir / "run.log", "w") as log_f:
            proc = subprocess.Popen(cmd, stdout=log_f, stderr=subprocess.STDOUT, env=self.env,
                                    start_new_session=True)
            try:
                rc = proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                return "timeout", out_dir
            finally:
                if proc.poll() is None:
                    os.killpg(proc.pid, signal.SIGTERM)
                    proc.wait()
        return rc, out_dir

    def baseline(self):
        """The unmutated suite's outputs, and its cases ordered fastest first (so that
        fail-fast meets a cheap failing case early)."""
        base_dir = self.out / "baseline"
        results = sorted(base_dir.glob("results.json"))
        if not results or self.args.fresh_baseline:
            log("baseline: building and running the unmutated suite")
            if not self.ninja(["taa-harness"], self.out / "baseline-build.log"):
                sys.exit(f"mutate: the unmutated tree does not build (see {self.out}/baseline-build.log)")
            start = time.monotonic()
            rc, _ = self.run_cases(self.cases, base_dir, False, 24 * 3600)
            (self.out / "baseline-seconds").write_text(f"{time.monotonic() - start:.1f}\n")
            if rc != 0:
                sys.exit(f"mutate: the unmutated suite fails (exit {rc}, see {base_dir}): fix that first")
            results = sorted(base_dir.glob("results.json"))
        outputs = case_outputs(base_dir)
        seconds = {}
        for f in results:
            for c in json.loads(f.read_text())["cases"]:
                seconds[c["name"]] = c.get("seconds", 0.0)
        ordered = sorted(self.cases, key=lambda p: (seconds.get(p.stem, 1e9), p.stem))
        self.logs, self.shaders = {}, {}
        for f in results:
            for c in json.loads(f.read_text())["cases"]:
                self.logs[c["name"]] = [ln for ln in c.get("log", []) if ln.startswith("pass ")]
                # The SPIR-V files the case's renderers loaded (the run log's "shaders:" line).
                used = [ln.split()[1:] for ln in c.get("log", []) if ln.startswith("shaders:")]
                if used:
                    self.shaders[c["name"]] = set(used[0])
        total = float((self.out / "baseline-seconds").read_text()) if (
            self.out / "baseline-seconds").exists() else sum(seconds.values())
        return outputs, ordered, total

    def order_for(self, mutant, ordered):
        """Cases whose run log names the mutated file's pass first ("pass cas" for cas.comp,
        "pass tscmaa" for tscmaa/*.glsl): an order only, every case still runs when none fails."""
        word = "pass " + pass_word(mutant.file)
        uses = [c for c in ordered if any(ln.startswith(word) for ln in self.logs.get(c.stem, []))]
        return uses + [c for c in ordered if c not in uses]

    def shader_commands(self):
        """The build's glslang command per SPIR-V file, and the shader files each one reads
        (its source and every file it includes, transitively)."""
        text = subprocess.run(["ninja", "-C", str(self.build), "-t", "commands", "taa_shaders"],
                              capture_output=True, text=True, check=True).stdout
        commands = [ln for ln in text.splitlines() if "glslangValidator" in ln]
        shaders = ROOT / "shaders"

        def reads(f, seen):
            if f in seen or not f.exists():
                return seen
            seen.add(f)
            for line in f.read_text().splitlines():
                m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
                if m:
                    for base in (f.parent, shaders):
                        if (base / m.group(1)).exists():
                            reads((base / m.group(1)).resolve(), seen)
                            break
            return seen

        return [(c, {p.relative_to(ROOT).as_posix() for p in reads(Path(c.split()[-1]).resolve(), set())})
                for c in commands]

    def build_shader_mutant(self, mutant, work):
        """Shader mutants never touch the tree or the build folder: the mutation goes into a
        copy of shaders/, the SPIR-V it changes into a copy of the build's, which the harness
        loads through TAA_SHADER_DIR. (shared.h, which C++ includes too, is edited in the
        tree instead: mutate_ops.tree_targets.)"""
        src, spv = work / "src", work / "spv"
        for d in (src, spv):
            shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(ROOT / "shaders", src / "shaders")
        shutil.copytree(self.build / "shaders", spv, ignore=shutil.ignore_patterns("CMakeFiles"))
        ops.apply(src, mutant)
        if not hasattr(self, "_shader_commands"):
            self._shader_commands = self.shader_commands()
        self.rebuilt = set()
        with open(work / "build.log", "w") as log_f:
            for command, reads in self._shader_commands:
                if mutant.file not in reads:
                    continue
                out = command.split(" -o ", 1)[1].split()[0] if " -o " in command else ""
                if out.endswith(".spv"):
                    self.rebuilt.add(os.path.relpath(out, self.build / "shaders")[:-len(".spv")])
                command = command.replace(str(self.build / "shaders"), str(spv))
                command = command.replace(str(ROOT / "shaders"), str(src / "shaders"))
                log_f.write(command + "\n")
                log_f.flush()
                if subprocess.run(command, shell=True, stdout=log_f, stderr=subprocess.STDOUT).returncode:
                    return False
        return True

    def unit_tests(self, mutant, work):
        suites = unit_suites(mutant.file)
        if not suites:
            return None
        flt = ":".join(f"{s}.*:*/{s}.*" for s in suites)
        with open(work / "unit.log", "w") as f:
            try:
                rc = subprocess.run([str(self.tests), f"--gtest_filter={flt}"], stdout=f,
                                    stderr=subprocess.STDOUT, env=self.env,
                                    timeout=self.args.unit_timeout).returncode
            except subprocess.TimeoutExpired:
                return "caught", "unit tests timed out (a hang)"
        if rc == 0:
            return None
        failed = [ln.split("]", 1)[1].strip() for ln in (work / "unit.log").read_text()
                  .splitlines() if ln.startswith("[  FAILED  ]") and "." in ln]
        return "caught", "unit test " + (failed[0] if failed else f"exit {rc}")

    def affected(self, ordered):
        """The cases that load a rebuilt SPIR-V file: the others run none of the mutated code,
        so their every frame is the baseline's by construction. All cases where the baseline
        predates the "shaders:" line."""
        if len(self.shaders) < len(ordered):
            return ordered
        return [c for c in ordered if self.shaders.get(c.stem, set()) & self.rebuilt]

    def judge(self, mutant, base_outputs, ordered, total_seconds):
        ordered = self.order_for(mutant, ordered) if mutant.kind == "shader" else ordered
        work = self.out / "work"
        targets = ops.build_targets(mutant, self.stale)
        if not targets:
            self.env["TAA_SHADER_DIR"] = str(work / "spv")
            if not self.build_shader_mutant(mutant, work):
                return "stillborn", "does not compile"
            ordered = self.affected(ordered)
            names = {c.stem for c in ordered}
            base_outputs = {n: o for n, o in base_outputs.items() if n in names}
            if not ordered:
                verdict = self.unit_tests(mutant, work)
                return verdict or ("no-change", "no case loads the rebuilt SPIR-V (" +
                                   ", ".join(sorted(self.rebuilt)) + ")")
        else:
            # Edited in the tree (ci/mutate.py restores it): the build's own SPIR-V, which
            # the rebuild replaced where it reads the file, and the C++ side alike.
            self.env.pop("TAA_SHADER_DIR", None)
            if not self.ninja(targets, work / "build.log"):
                return "stillborn", "does not build"
            self.stale = set()
        if mutant.kind == "harness":
            verdict = self.unit_tests(mutant, work)
            if verdict:
                return verdict
        rc, run_dir = self.run_cases(ordered, work / "run", True, max(600.0, 4 * total_seconds))
        if rc == "timeout":
            return "caught", "the suite timed out (a hang)"
        if rc != 0:
            first = next((line[:160] for line in (run_dir / "run.log").read_text().splitlines()
                          if line.startswith(("FAIL ", "ERROR "))), "")
            return "caught", f"run exit {rc}" + (f": {first}" if first else "")
        if mutant.kind == "shader" and self.tests.exists():
            # The cases passed: the GPU unit tests of the mutated pass get their say (they
            # check what no image shows, such as TSCMAA's dispatch sizes).
            verdict = self.unit_tests(mutant, work)
            if verdict:
                return verdict
        outputs = case_outputs(run_dir)
        changed = [n for n in base_outputs if outputs.get(n) != base_outputs[n]]
        if changed:
            first = changed[0]
            keys = sorted(k for k in set(outputs.get(first, {})) | set(base_outputs[first])
                          if outputs.get(first, {}).get(k) != base_outputs[first].get(k))
            return "survived", (f"outputs changed but passed: {', '.join(changed[:5])} "
                                f"({first}: {', '.join(keys)})")
        return "no-change", (f"every frame hash and verdict of the {len(base_outputs)} cases that "
                             "load the rebuilt SPIR-V equal the unmutated run's")
