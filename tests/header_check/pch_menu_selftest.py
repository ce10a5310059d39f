#!/usr/bin/env python3
"""Checks of cmake/header_pch_menu.py, which picks the header check's precompiled headers. A
header may only be given a PCH of names its own compile would include anyway, or the check
stops being exact; these build small trees where that rule has a way to go wrong.
Usage: pch_menu_selftest.py CXX. Exit 0 pass, 1 fail."""

import atexit
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MENU = ROOT / "cmake" / "header_pch_menu.py"
sys.dont_write_bytecode = True
sys.path.insert(0, str(ROOT / "cmake"))
sys.path.insert(0, str(ROOT / "tests" / "support"))
import header_pch_menu as menu  # noqa: E402
from selfcheck import SelfCheck  # noqa: E402

check = SelfCheck("pch_menu_selftest")


def tree(files):
    root = Path(tempfile.mkdtemp(prefix="pch-menu-"))
    atexit.register(shutil.rmtree, root, ignore_errors=True)
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text("#pragma once\n" + text if name.endswith(".h") else text)
    return root


# The names a header reaches: through our headers, not inside #if, and none at all for a header
# with an include after code or a quoted name two files of the tree could be.
root = tree({
    "a/base.h": "#include <vector>\n#include <string>\nstruct Base { std::vector<std::string> v; };\n",
    "a/user.h": '#include "base.h"\n#include <map>\nstruct User { Base b; std::map<int, int> m; };\n',
    "a/cond.h": "#ifdef WANT_SET\n#include <set>\n#endif\n#include <vector>\n",
    "a/late.h": "#include <vector>\nint f();\n#include <string>\n",
    "a/define_first.h": "#define GLM_FORCE_RADIANS\n#include <vector>\n",
    "a/list.inc": "X(one)\nX(two)\n",
    "a/expands.h": '#include <vector>\nenum E {\n#define X(n) n,\n#include "list.inc"\n};\n',
    "a/twice.h": '#include "dup.h"\n',
    "b/dup.h": "#include <vector>\n",
    "c/dup.h": "#include <string>\n",
    "a/angled_ours.h": "#include <a/base.h>\n",
    "a/commented.h": "/* a comment\n   over lines */\n// another\n#include <vector>\n",
    "a/plain.inc": "#include <set>\n",
    "a/uses_plain.h": '#include "plain.inc"\n',
})
t = menu.Tree(str(root))


def reach(name):
    return t.external(str((root / name).resolve()))



def ours(name):
    return str((root / name).resolve())


check(reach("a/user.h") == {"vector", "string", "map", ours("a/base.h")},
      f"user.h reaches base.h and its names: {reach('a/user.h')}")
check(reach("a/uses_plain.h") == {"set"}, f"only our headers with #pragma once are names: {reach('a/uses_plain.h')}")
check(reach("a/cond.h") == {"vector"}, f"a name inside #if is not counted: {reach('a/cond.h')}")
check(reach("a/late.h") is None, "an include after code: no PCH")
check(reach("a/define_first.h") is None, "a #define before an include: no PCH")
check(reach("a/expands.h") == {"vector"}, f"a list expanded inside code is allowed: {reach('a/expands.h')}")
check(reach("a/twice.h") is None, "a quoted name two files could be: no PCH")
check(reach("a/angled_ours.h") is None, "an angled name the tree holds: no PCH")
check(reach("a/commented.h") == {"vector"}, f"comments are not code: {reach('a/commented.h')}")

# In a git checkout, what .gitignore leaves out (a copy of the sources under out/) does not
# make a name ambiguous; untracked new headers still count.
root = tree({"a/user.h": '#include "base.h"\n', "b/base.h": "#include <vector>\n",
             "out/copy/b/base.h": "#include <map>\n", ".gitignore": "out/\n"})
subprocess.run(["git", "init", "-q", str(root)], check=True)
t = menu.Tree(str(root))
check(t.external(str(root / "a/user.h")) == {"vector", str((root / "b/base.h").resolve())},
      "ignored files are not the tree's")

# The whole script: every PCH's names lie within what each of its headers reaches.
cxx = sys.argv[1] if len(sys.argv) > 1 else "c++"
many = {f"m/h{i}.h": "#include <vector>\n#include <string>\n#include <map>\n" + ("#include <set>\n" if i % 2 else "")
        for i in range(8)}
# Two headers share only <vector>: worth a PCH where its load is cheap (clang), not under GCC.
many.update({f"m/v{i}.h": "#include <vector>\n" for i in range(2)})
# Headers of ours that include a large one of ours: it may be in their PCH, never in its own.
many["m/big.h"] = "#include <vector>\n" + "".join(f"int big{i}(int);\n" for i in range(100000))
many.update({f"m/u{i}.h": '#include "big.h"\n' for i in range(4)})
many["m/late.h"] = "#include <vector>\nint g();\n#include <string>\n#include <map>\n"
root = tree(many)
headers = sorted(str(p) for p in root.glob("m/*.h"))
t = menu.Tree(str(root))


def menu_for(compiler_id):
    """The script's choice for `compiler_id`'s costs: header -> the names of its PCH."""
    r = subprocess.run([sys.executable, str(MENU), "--root", str(root), "--compiler", cxx,
                        "--compiler-id", compiler_id, "--flag=-std=c++20",
                        "--cache", str(root / "weights.json"), *headers], capture_output=True, text=True)
    check(r.returncode == 0, f"the script runs for {compiler_id}: {r.stderr}")
    given = {}
    for line in r.stdout.splitlines():
        names, _, members = line.partition("|")
        for h in filter(None, members.split(",")):
            check(h not in given, f"{compiler_id}: {h} is listed once")
            given[h] = set(filter(None, names.split(",")))
    check(sorted(given) == headers, f"{compiler_id}: every header is listed")
    check(any(given.values()), f"{compiler_id}: some header gets a PCH: {r.stdout}")
    for h, names in given.items():
        check(names <= (t.external(h) or set()),
              f"{compiler_id}: {Path(h).name}: PCH {sorted(names)} within what it reaches")
        check(str(Path(h).resolve()) not in names, f"{compiler_id}: {Path(h).name} is not in its own PCH")
    check(given.get(str(root / "m/late.h")) == set(), f"{compiler_id}: the header with a late include gets none")
    return given


# Clang loads a PCH for a fraction of what GCC pays, so the choice may differ, never the rule.
gnu, clang = menu_for("GNU"), menu_for("Clang")
check(menu_for("Intel") == gnu, "a compiler without costs of its own is priced as GCC")
check(any(ours("m/big.h") in names for names in clang.values()), f"a header of ours is precompiled: {clang}")
check(sum(map(len, clang.values())) > sum(map(len, gnu.values())),
      f"a cheaper load precompiles more: GNU {gnu}, Clang {clang}")

check.finish()
