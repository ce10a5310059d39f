"""Mutation operators and the seeded, reproducible choice of mutants (used by ci/mutate.py).

Every operator is a pattern over one source line, never a line number: a mutant's id is
FILE:OPERATOR:K, the K-th site of that operator in that file (code only: comments, string
literals and preprocessor lines other than `#define NAME NUMBER` are skipped). Renaming an
identifier or editing a comment keeps every id; adding a site before another renumbers that
file's sites of the same operator only.
"""

import hashlib
import random
import re
from dataclasses import dataclass
from pathlib import Path

SHADER_GLOBS = ["shaders/**/*.comp", "shaders/**/*.glsl", "shaders/**/*.frag",
                "shaders/**/*.vert", "shaders/common/shared.h"]
HARNESS_GLOBS = ["harness/compare/metrics.cpp", "harness/compare/tolerance.cpp",
                 "harness/compare/flip*.cpp", "harness/golden/*.cpp", "harness/invariants/*.cpp",
                 "harness/run/golden_check.cpp", "harness/run/invariant_run.cpp",
                 "harness/case/case_validate.cpp", "harness/case/validate_*.cpp"]
# --whole-tree (issue 46): every C++ file with logic, and the sources of the generated user
# headers. The two lists above stay as they were, so the 200-mutant sample of issue 29 lists
# the same ids without the flag.
WHOLE_TREE_GLOBS = ["renderer/**/*.cpp", "harness/**/*.cpp", "core/*.cpp",
                    "shaders/user/*.in", "shaders/user/taa_user_header.cpp"]

# Binary operators are matched with a space on each side (clang-format's layout), which
# keeps templates (vector<int>), shifts, arrows and unary minus out.
_CMP_NEGATE = {"<": ">=", ">": "<=", "<=": ">", ">=": "<", "==": "!=", "!=": "=="}
_CMP_BOUND = {"<": "<=", "<=": "<", ">": ">=", ">=": ">"}
_CMP = re.compile(r"(?<=\s)(<=|>=|==|!=|<|>)(?=\s)")
_MINMAX = re.compile(r"\b(std::)?(f?)(min|max)(?=\s*\()")
_ARITH = re.compile(r"(?<=\s)(\+|-)(=?)(?=\s)")
_FLOAT = re.compile(r"(?<![\w.])(\d+\.\d*|\.\d+|\d+(?=[eE]))([eE][+-]?\d+)?(f?)(?![\w.])")
_INT = re.compile(r"(?<![\w.])(\d+)(u?)(?![\w.])")
_IF = re.compile(r"\bif\s*\(")
_ASSIGN = re.compile(r"^\s*[A-Za-z_][\w.]*(\[[^\]]*\])?(\.\w+)?\s*([-+*/]?=)\s*[^=].*;\s*$")
_CALL = re.compile(r"^\s*[A-Za-z_][\w:.]*(\.[A-Za-z_]\w*)*\s*\(.*\)\s*;\s*$")
_DEFINE_NUMBER = re.compile(r"^\s*#define\s+\w+\s+\(?-?[\d.]")
_SKIP_LINE = re.compile(r"\bstatic_assert\b|\blayout\s*\(")
_KEYWORD_STATEMENT = re.compile(r"^\s*(return|break|continue|case|default|if|for|while|else)\b")
# --whole-tree operators (issue 46), never offered without the flag (WHOLE_TREE_OPS):
# `key` drops one line feeding a hash, digest or cache key (h.update(...), add(...),
# key += ...), a field left out of a key; `size` doubles a sizeof or widens a stride by one;
# `prev-cur` swaps a previous-frame name for the current-frame one on one line or back.
_KEY_FEED = re.compile(r"^\s*(\w+\s*(\.|->)\s*)?(update|add|combine|mix)\s*\(|"
                       r"^\s*[\w.]*(key|Key|hash|Hash|digest|Digest|signature|Signature)\w*\s*(\+=|\^=|<<)")
_SIZEOF = re.compile(r"\bsizeof\s*\(")
_CAPACITY_CALL = re.compile(r"\b(snprintf|to_chars|read|getaffinity|sched_getaffinity)\s*\(")
_STRIDE = re.compile(r"(?<=[-*+/(,=]\s)(?<![\w.])([a-z]\w*[sS]tride\w*|stride\w*)\b(?!\s*[=(])")
_IDENT = re.compile(r"(?<![\w#])[a-z_]\w*")
_PREV = re.compile(r"^(prev|previous)(_?)(\w*)$")
_CUR = re.compile(r"^(cur|current)(_?)(\w*)$")
# A name right after a type is being declared (vec2 uv, const auto& prev): renaming it
# only moves the declaration, which does not build or shadows nothing.
_DECLARED = re.compile(r"\b(\w+)(\s+|[&*]\s*)$")
_NOT_A_TYPE = {"return", "case", "else", "co_return", "throw"}
WHOLE_TREE_OPS = {"key", "size", "prev-cur"}


# Shader files the C++ side includes too (its structs, bindings and mask values): a mutant
# of one must reach both sides, as a real edit would, so it is edited in the tree and the
# SPIR-V, the harness and the tests are rebuilt from it.
HOST_SHARED = {"shaders/common/shared.h"}


TREE_TARGETS = ["taa_shaders", "taa-harness", "taa_tests"]
# The generated user headers: their sources rebuild the two headers (the tool first, for
# taa_user_header.cpp). User shaders include them at run time, and the SPIR-V cache checks
# each include's bytes, so nothing else needs building.
USER_HEADER_TARGETS = ["taa_user_h"]
# Other C++ (harness/, renderer/, core/): the harness and the tests that link it; ninja
# recompiles only the mutated file's unity batch and relinks. No SPIR-V reads these files.
CPP_TARGETS = ["taa-harness", "taa_tests"]


def tree_targets(mutant):
    """The build targets a mutant edited in the tree rebuilds, or [] for a shader mutant
    built into a private copy of the SPIR-V (the tree and the build folder untouched).
    shared.h is read by both sides: all three. ci/mutate.py also rebuilds the previous tree
    mutant's targets, so the build folder matches the restored tree before the next runs."""
    if mutant.file in HOST_SHARED:
        return TREE_TARGETS
    if mutant.kind != "harness":
        return []
    if mutant.file.startswith("shaders/user/"):
        return USER_HEADER_TARGETS
    return CPP_TARGETS


def build_targets(mutant, previous):
    """What to build before judging a tree mutant: its own targets and `previous`, those
    of the tree mutants restored since the last build that succeeded: a restored user header
    reaches the build folder only through taa_user_h, which a C++ mutant's targets do not
    include, and a stillborn shared.h mutant's build may stop before the SPIR-V."""
    own = tree_targets(mutant)
    return sorted(set(own) | set(previous)) if own else []


@dataclass
class Mutant:
    id: str
    file: str  # relative to the repository root
    kind: str  # "shader" or "harness"
    op: str
    line: int  # 1-based, for humans only: the id does not depend on it
    before: str
    after: str

    def as_json(self):
        return {"id": self.id, "file": self.file, "kind": self.kind, "op": self.op,
                "line": self.line, "before": self.before, "after": self.after}


def _code_mask(line, in_block):
    """The line with comments and string literals blanked (same length), and whether a
    block comment is still open at its end."""
    out, i, n = [], 0, len(line)
    while i < n:
        if in_block:
            end = line.find("*/", i)
            if end < 0:
                out.append(" " * (n - i))
                return "".join(out), True
            out.append(" " * (end + 2 - i))
            i, in_block = end + 2, False
        elif line.startswith("//", i):
            out.append(" " * (n - i))
            break
        elif line.startswith("/*", i):
            in_block = True
        elif line[i] in "\"'":
            quote, j = line[i], i + 1
            while j < n and line[j] != quote:
                j += 2 if line[j] == "\\" else 1
            out.append(line[i] + " " * (min(j, n) - i - 1) + (quote if j < n else ""))
            i = j + 1
        else:
            out.append(line[i])
            i += 1
    return "".join(out), in_block


def _format_float(value):
    text = repr(float(f"{value:.6g}"))
    if "e" in text or "E" in text:
        mantissa, exponent = text.split("e")
        return (mantissa if "." in mantissa else mantissa + ".0") + "e" + exponent
    return text


def _counterparts(name, fits):
    """The current-frame names of a previous-frame name, and back: prevRenderSize ->
    renderSize, curRenderSize; previous -> current; renderSize -> prevRenderSize. Only those
    `fits` accepts (a name the code has where this one stands), so most such mutants build."""
    def cap(rest, sep):
        return rest if sep else rest[:1].upper() + rest[1:]
    out = []
    for pattern, others in ((_PREV, ("cur", "current")), (_CUR, ("prev", "previous"))):
        m = pattern.match(name)
        if m:
            _, sep, rest = m.groups()
            if rest:
                out.append(rest[:1].lower() + rest[1:] if not sep else rest)
            out.extend(o + sep + cap(rest, sep) for o in others)
    if not _PREV.match(name) and not _CUR.match(name):
        out.extend(o + name[:1].upper() + name[1:] for o in ("prev", "previous"))
        out.extend(o + "_" + name for o in ("prev", "previous"))
    return [o for o in dict.fromkeys(out) if o != name and fits(o)]


class _Names:
    """Where a file's code uses each identifier: as a member (after `.` or `->`, in the file
    or its header), bare in its header (a class's fields), or bare on a line of the file. A
    swapped name must be a member where a member stands, and otherwise declared in the
    header or used bare in the 60 lines above (most often the same function): a local of
    another function does not build. Member names are not checked against the member's
    type, so a few mutants still do not build (stillborn, not counted)."""
    WINDOW = 60

    def __init__(self, text, header_text):
        self.members, self.header, self.lines, self._near = set(), set(), [], {}
        for source, is_header in ((text, False), (header_text, True)):
            in_block = False
            for raw in source.split("\n"):
                code, in_block = _code_mask(raw, in_block)
                self.members.update(re.findall(r"(?:\.|->)\s*([A-Za-z_]\w*)", code))
                bare = set(re.findall(r"(?<![\w.>])[A-Za-z_]\w*", code))
                if is_header:
                    self.header |= bare
                else:
                    self.lines.append(bare)

    def fits(self, number, is_member):
        if is_member:
            return lambda o: o in self.members
        near = self._near.get(number)
        if near is None:  # a line with several identifiers asks for its window once
            near = self._near[number] = set().union(*self.lines[max(0, number - self.WINDOW):number])
        return lambda o: o in self.header or o in near


def _whole_tree_sites(code, raw, names, number, prev_code):
    """The --whole-tree operators' sites of one code line (WHOLE_TREE_OPS)."""
    sites = []
    stripped = code.strip()
    # A string with a space in it is a message (add(key, "has no effect ...")), not a key.
    strings = re.findall(r'"([^"\\]*(?:\\.[^"\\]*)*)"', raw)
    if (_KEY_FEED.match(code) and stripped.endswith(";") and not any(" " in t for t in strings)
            and (not prev_code.strip() or prev_code.rstrip()[-1] in ";{}")):
        indent = len(raw) - len(raw.lstrip())
        sites.append(("key", indent, len(raw.rstrip()), ""))
    # A buffer's capacity handed to a formatter or read() only matters past a bound the
    # text never reaches: a doubled capacity there is undefined behaviour no run can show.
    for m in ([] if _CAPACITY_CALL.search(code) else _SIZEOF.finditer(code)):
        close = _matching_paren(code, m.end() - 1)
        if close is not None:
            sites.append(("size", m.start(), close + 1, "(" + raw[m.start():close + 1] + " * 2)"))
    for m in _STRIDE.finditer(code):
        sites.append(("size", m.start(1), m.end(1), "(" + m.group(1) + " + 1)"))
    for m in _IDENT.finditer(code):
        declared = _DECLARED.search(code[:m.start()])
        if declared and declared.group(1) not in _NOT_A_TYPE:
            continue
        is_member = bool(re.search(r"(\.|->)\s*$", code[:m.start()]))
        for other in _counterparts(m.group(0), names.fits(number, is_member)):
            sites.append(("prev-cur", m.start(), m.end(), other))
    return sites


def _line_sites(code, raw):
    """(op, start, end, replacement) for every mutation site of one code line."""
    sites = []
    for m in _CMP.finditer(code):
        sites.append(("cmp", m.start(), m.end(), _CMP_NEGATE[m.group(1)]))
        if m.group(1) in _CMP_BOUND:
            sites.append(("bound", m.start(), m.end(), _CMP_BOUND[m.group(1)]))
    for m in _MINMAX.finditer(code):
        other = "max" if m.group(3) == "min" else "min"
        s = m.start(3)
        sites.append(("minmax", s, s + 3, other))
    for m in _ARITH.finditer(code):
        sites.append(("arith", m.start(1), m.end(1), "-" if m.group(1) == "+" else "+"))
    for m in _FLOAT.finditer(code):
        text = raw[m.start():m.end() - len(m.group(3))]
        value = float(text)
        new = "1.0" if value == 0 else _format_float(value * 1.5)
        sites.append(("float", m.start(), m.end() - len(m.group(3)), new))
    for m in _INT.finditer(code):
        if _FLOAT.match(code, m.start()):
            continue
        sites.append(("int", m.start(1), m.end(1), str(int(m.group(1)) + 1)))
    for m in _IF.finditer(code):
        close = _matching_paren(code, m.end() - 1)
        if close is not None:
            sites.append(("cond-true", m.end(), close, "true"))
            sites.append(("cond-false", m.end(), close, "false"))
    return sites


def _matching_paren(code, open_at):
    depth = 0
    for i in range(open_at, len(code)):
        depth += {"(": 1, ")": -1}.get(code[i], 0)
        if depth == 0:
            return i
    return None  # the condition goes on to the next line: not a site


def _deletable(code, prev_code):
    """A whole single-line statement: an assignment to an existing name or a call."""
    if not code.strip().endswith(";") or _KEYWORD_STATEMENT.match(code):
        return False
    if prev_code.strip() and prev_code.rstrip()[-1] not in ";{}":
        return False  # continues a statement from the line before
    return bool(_ASSIGN.match(code) or _CALL.match(code))


_scanned = {}


def file_mutants(root, rel, kind):
    """Every site of every operator, WHOLE_TREE_OPS included (all_mutants filters them):
    adding those never renumbers another operator's ids."""
    text = (root / rel).read_text()
    # A member renamed to its previous-frame twin is often declared in the header beside.
    header = (root / rel).with_suffix(".h")
    header_text = header.read_text() if header.is_file() else ""
    # A process that lists twice (the selftest, --whole-tree beside the default) scans a file
    # once for the same bytes; an edited file is scanned again.
    key = (rel, kind, text, header_text)
    if key not in _scanned:
        _scanned[key] = _scan(rel, kind, text, header_text)
    return list(_scanned[key])


def _scan(rel, kind, text, header_text):
    lines = text.split("\n")
    names = _Names(text, header_text)
    # prev_code: the last code line the older operators looked at (lines with a string left
    # out, as they always were, so their ids stay); prev_any: the last code line at all.
    counters, mutants, in_block, prev_code, prev_any = {}, [], False, "", ""
    for number, raw in enumerate(lines, 1):
        code, in_block = _code_mask(raw, in_block)
        stripped = code.strip()
        if stripped.startswith("#") and not _DEFINE_NUMBER.match(code):
            continue
        if _SKIP_LINE.search(code):
            continue  # compile-time checks
        whole = (_whole_tree_sites(code, raw, names, number, prev_any)
                 if not stripped.startswith("#") else [])
        if stripped:
            prev_any = code
        if kind == "harness" and '"' in code:
            # Message text is not what the harness compares, but a key string is.
            for op, start, end, new in (w for w in whole if w[0] == "key"):
                k = counters.get(op, 0)
                counters[op] = k + 1
                mutants.append(Mutant(f"{rel}:{op}:{k}", rel, kind, op, number, raw.strip(),
                                      (raw[:start] + new + raw[end:]).strip()))
            continue
        if stripped.startswith("#"):  # `#define NAME NUMBER`: only the value mutates
            name = re.match(r"\s*#define\s+\w+", code)
            code = " " * name.end() + code[name.end():]
        sites = _line_sites(code, raw)
        if not stripped.startswith("#") and _deletable(code, prev_code):
            indent = len(raw) - len(raw.lstrip())
            sites.append(("delete", indent, len(raw.rstrip()), ""))
        sites += whole
        for op, start, end, new in sites:
            after = raw[:start] + new + raw[end:]
            k = counters.get(op, 0)
            counters[op] = k + 1
            mutants.append(Mutant(f"{rel}:{op}:{k}", rel, kind, op, number, raw.strip(),
                                  after.strip()))
        if stripped:
            prev_code = code
    return mutants


def target_files(root, whole_tree=False):
    files = []
    groups = [("shader", SHADER_GLOBS), ("harness", HARNESS_GLOBS)]
    if whole_tree:
        groups.append(("harness", WHOLE_TREE_GLOBS))  # edited in the tree, as the harness's
    for kind, globs in groups:
        for pattern in globs:
            for p in sorted(root.glob(pattern)):
                rel = p.relative_to(root).as_posix()
                if rel not in [f for f, _ in files]:
                    files.append((rel, kind))
    return files


def all_mutants(root, whole_tree=False):
    out = []
    for rel, kind in target_files(root, whole_tree):
        out.extend(m for m in file_mutants(root, rel, kind)
                   if whole_tree or m.op not in WHOLE_TREE_OPS)
    return out


def _stable_rng(seed, name):
    digest = hashlib.sha256(f"{seed}:{name}".encode()).digest()
    return random.Random(int.from_bytes(digest[:8], "big"))


def select(mutants, seed, count, harness_share):
    """A deterministic sample: `harness_share` of `count` from the harness files, the rest
    from the shaders; within each group files take turns (in a seeded order), and each file
    offers its sites in a seeded order that alternates operators, so every file and
    operator is represented before any repeats."""
    chosen = []
    for kind, quota in (("harness", round(count * harness_share)),
                        ("shader", count - round(count * harness_share))):
        by_file = {}
        for m in mutants:
            if m.kind == kind:
                by_file.setdefault(m.file, []).append(m)
        queues = {}
        for f, ms in by_file.items():
            rng = _stable_rng(seed, f)
            by_op = {}
            for m in ms:
                by_op.setdefault(m.op, []).append(m)
            ops = sorted(by_op)
            rng.shuffle(ops)
            # The --whole-tree operators lead a file's turn where it has their sites: they
            # are the bug classes issue 46 asks about, and rare (a file's first pick would
            # otherwise seldom be one). A stable sort: without them the order is as it was.
            ops.sort(key=lambda op: op not in WHOLE_TREE_OPS)
            for op in ops:
                rng.shuffle(by_op[op])
            queue = []
            while any(by_op.values()):
                for op in ops:
                    if by_op[op]:
                        queue.append(by_op[op].pop())
            queues[f] = queue
        files = sorted(queues)
        _stable_rng(seed, kind).shuffle(files)
        picked = []
        while len(picked) < quota and any(queues[f] for f in files):
            for f in files:
                if queues[f] and len(picked) < quota:
                    picked.append(queues[f].pop(0))
        chosen.extend(picked)
    return chosen


def apply(root, mutant):
    """Writes the mutant into its file; returns the original bytes for restore()."""
    path = root / mutant.file
    original = path.read_bytes()
    fresh = {m.id: m for m in file_mutants(root, mutant.file, mutant.kind)}
    current = fresh.get(mutant.id)
    if current is None or current.before != mutant.before:
        raise RuntimeError(f"{mutant.id}: the file changed since the list was made")
    lines = original.decode().split("\n")
    raw = lines[current.line - 1]
    indent = raw[:len(raw) - len(raw.lstrip())]
    lines[current.line - 1] = indent + current.after + raw[len(raw.rstrip()):]
    path.write_bytes("\n".join(lines).encode())
    return original


def restore(root, mutant, original):
    (root / mutant.file).write_bytes(original)


def repo_root():
    return Path(__file__).resolve().parent.parent
