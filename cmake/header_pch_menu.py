#!/usr/bin/env python3
"""Chooses precompiled headers for the header check (cmake/HeaderCheck.cmake).

Each header of ours is compiled alone. Most of that CPU parses the same standard,
third-party and widely included headers of ours again and again, so headers that share them
may start from a precompiled header (PCH) of them, as long as the check stays exact:

- A header H may use a PCH only of names it includes itself, directly or through our
  headers, unconditionally (outside any #if): its compile alone would include every one of
  them anyway, so the PCH adds nothing H would not see. Our own headers among them are
  named by absolute path; each is checked by its own unit, whose PCH never holds it.
- The names arrive earlier than in H's compile alone. That can only hide a header X that
  uses a name before it includes it; every header's own check catches X's mistake, provided
  X's includes come before its code. A header with an #include after code (or a #define
  before an include) gets no PCH, so its own check stays the plain one.
- A quoted name that could resolve to two files of the tree, or an angled one that the
  tree holds, is not followed: the header gets no PCH.

Which PCHs to build is a trade: each costs one compile and a load per use. A greedy choice
by the bytes each name pulls in (from the compiler's -M list; one of ours weighs its own
bytes) picks up to --max of them.
The choice changes no verdict, only how fast it comes.

Usage: header_pch_menu.py --root DIR --compiler CXX [--compiler-id ID] [--flag F]... --cache FILE
                          [--max N] HEADER...
Prints one line per PCH, "name,name,...|header,header,...", then the headers that get none
as a line starting with "|" (commas, not CMake's semicolons, so each line is one list item).
"""
import argparse
import functools
import json
import os
import re
import subprocess
import sys

INCLUDE = re.compile(r'\s*#\s*include\s*([<"])([^>"]+)[>"]')
# Preprocessor lines that are not code: an include may follow them.
NOT_CODE = re.compile(r'\s*#\s*(include|pragma|if|ifdef|ifndef|elif|else|endif)\b')
# Per compiler (CMAKE_CXX_COMPILER_ID): a PCH's load, and its build, against parsing its names.
# GCC 12 reads a whole .gch (0.59 s for 70 MB against 1.79 s to parse its names; 4.2 s to build
# it); clang 14 reads a PCH lazily (0.14 s for 19 MB against 1.7 s; 2.35 s to build it). Other
# compilers are priced as GCC.
COSTS = {"GNU": (0.35, 2.3), "Clang": (0.08, 1.4)}


@functools.lru_cache(maxsize=None)
def lines_without_comments(path):
    """The file's lines with comments blanked, so code is told apart from prose."""
    text = open(path, encoding="utf-8", errors="replace").read()
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return [re.sub(r"//.*", "", line) for line in text.split("\n")]


class Tree:
    def __init__(self, root):
        self.root = os.path.realpath(root)
        self.files = self.tracked()
        if self.files is None:  # not a git checkout: every file, less build trees
            self.files = []
            for d, dirs, names in os.walk(self.root):
                if "CMakeCache.txt" in names:
                    dirs[:] = []
                    continue
                dirs[:] = [x for x in dirs if not x.startswith(".")]
                self.files += [os.path.join(d, n) for n in names]
        self.memo = {}

    def tracked(self):
        """The checkout's files, new ones included, less what .gitignore leaves out (build
        trees, out/ and the copies of the sources the mutation loop keeps there)."""
        try:
            r = subprocess.run(["git", "-C", self.root, "ls-files", "-z", "--cached", "--others",
                                "--exclude-standard"], capture_output=True)
        except OSError:
            return None
        if r.returncode != 0:
            return None
        return [os.path.join(self.root, f) for f in r.stdout.decode().split("\0") if f]

    def in_tree(self, name):
        return [f for f in self.files if f.endswith("/" + name)]

    def resolve_quoted(self, name, includer):
        beside = os.path.join(os.path.dirname(includer), name)
        if os.path.isfile(beside):
            return os.path.realpath(beside)
        found = self.in_tree(name)
        return os.path.realpath(found[0]) if len(found) == 1 else None

    def external(self, path):
        """The names `path` reaches unconditionally through our headers, or None when the
        header cannot take a PCH (an include after code, a name not resolved alone): angled
        names as written, and our own headers (with #pragma once) as absolute paths. Each of
        ours is checked alone by its own unit, which never lists itself, so having it in an
        includer's PCH hides nothing."""
        if path in self.memo:
            return self.memo[path]
        self.memo[path] = None  # an include cycle gets no PCH
        names, depth, code = set(), 0, False
        for line in lines_without_comments(path):
            s = line.strip()
            if not s:
                continue
            if re.match(r"#\s*if", s):
                depth += 1
            elif re.match(r"#\s*endif", s):
                depth -= 1
            m = INCLUDE.match(line)
            if m and code and not self.is_list(m, path):
                return None
            if m and not code and depth == 0:
                if m.group(1) == "<":
                    if self.in_tree(m.group(2)):
                        return None
                    names.add(m.group(2))
                else:
                    target = self.resolve_quoted(m.group(2), path)
                    inner = self.external(target) if target else None
                    if inner is None:
                        return None
                    names |= inner
                    if self.once(target):
                        names.add(target)
            elif not NOT_CODE.match(line):
                code = True
        self.memo[path] = frozenset(names)
        return self.memo[path]

    @staticmethod
    def once(path):
        """Whether cmake/HeaderCheck.cmake checks `path` alone: the same test it makes."""
        return any(l.startswith("#pragma once") for l in lines_without_comments(path))

    def is_list(self, m, includer):
        """A quoted list without #pragma once and without includes, expanded inside code."""
        if m.group(1) != '"':
            return False
        target = self.resolve_quoted(m.group(2), includer)
        if not target:
            return False
        body = lines_without_comments(target)
        return not self.once(target) and not any(INCLUDE.match(l) for l in body)


def weights(names, compiler, flags, cache_path):
    """Bytes of the files each name pulls in, from the compiler's own -M list (cached)."""
    cache = {}
    if os.path.exists(cache_path):
        try:
            cache = json.load(open(cache_path))
        except ValueError:
            cache = {}
    key = compiler + " " + " ".join(flags)
    files = cache.setdefault(key, {})
    for name in sorted(names):
        if not os.path.isabs(name) and name not in files:
            r = subprocess.run([compiler, *flags, "-M", "-x", "c++", "-"], input=f"#include <{name}>\n",
                               capture_output=True, text=True)
            deps = r.stdout.replace("\\\n", " ").split()[1:] if r.returncode == 0 else []
            files[name] = sorted(d for d in deps if d != "-")
    tmp = cache_path + ".tmp"
    with open(tmp, "w") as out:
        json.dump(cache, out)
    os.replace(tmp, cache_path)
    sizes = {}

    def cost(group):
        union = set()
        for n in group:
            # One of ours weighs its own bytes: the names it reaches are in the group too.
            union.update([n] if os.path.isabs(n) else files[n])
        return sum(sizes.setdefault(f, os.path.getsize(f)) for f in union if os.path.exists(f))
    return cost


def choose(reach, cost, most, load, build):
    sets = sorted(set(s for s in reach.values() if s), key=sorted)
    pool = set(sets)
    for i, a in enumerate(sets):
        for b in sets[i + 1:]:
            if a & b:
                pool.add(a & b)
    pool = sorted(pool, key=sorted)
    price = {c: cost(c) for c in pool}
    saved = {h: 0.0 for h in reach}
    menu = []

    def gain(c):
        g = -build * price[c]
        for h, s in reach.items():
            if s and c <= s:
                g += max(0.0, price[c] * (1 - load) - saved[h])
        return g
    while len(menu) < most and pool:
        best = max(pool, key=gain)
        if gain(best) <= 0:
            break
        menu.append(best)
        pool.remove(best)
        for h, s in reach.items():
            if s and best <= s:
                saved[h] = max(saved[h], price[best] * (1 - load))
    return menu, price


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", required=True)
    ap.add_argument("--compiler", required=True)
    ap.add_argument("--compiler-id", default="GNU")
    ap.add_argument("--flag", action="append", default=[])
    ap.add_argument("--cache", required=True)
    ap.add_argument("--max", type=int, default=6)
    ap.add_argument("headers", nargs="+")
    args = ap.parse_args()
    tree = Tree(args.root)
    reach = {h: tree.external(os.path.realpath(h)) for h in args.headers}
    names = set().union(*[s for s in reach.values() if s])
    cost = weights(names, args.compiler, args.flag, args.cache)
    menu, price = choose(reach, cost, args.max, *COSTS.get(args.compiler_id, COSTS["GNU"]))
    users = {c: [] for c in menu}
    alone = []
    for h in args.headers:
        s = reach[h]
        fits = [c for c in menu if s and c <= s]
        if fits:
            users[max(fits, key=lambda c: (price[c], sorted(c)))].append(h)
        else:
            alone.append(h)
    for c in menu:
        if users[c]:
            print(",".join(sorted(c)) + "|" + ",".join(users[c]))
    print("|" + ",".join(alone))


if __name__ == "__main__":
    sys.exit(main())
