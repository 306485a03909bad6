#!/usr/bin/env python3
"""The largest source files and classes of the program, to see where one piece does too much.

  scripts/code_size.py [REV]   (default: the working tree; REV: a commit, read through git)

Files: lines of each .h/.cpp under app/ sim/ render/ gl/ tools/. Classes: for each class or
struct with a body in a header there, its public member functions (declarations and inline
definitions in its public sections) and its data members (names ending in _, the project's
rule for members). A reading of the text, not a compiler's: good for ranking, not for counting
to the last one."""
import re
import subprocess
import sys

rev = sys.argv[1] if len(sys.argv) > 1 else None
roots = ("app/", "sim/", "render/", "gl/", "tools/")


def files():
    if rev:
        out = subprocess.check_output(["git", "ls-tree", "-r", "--name-only", rev], text=True)
    else:
        out = subprocess.check_output(["git", "ls-files", "--cached", "--others",
                                       "--exclude-standard"], text=True)
    return [f for f in out.split() if f.startswith(roots) and f.endswith((".h", ".cpp"))]


def text(path):
    if rev:
        return subprocess.check_output(["git", "show", f"{rev}:{path}"], text=True)
    return open(path).read()


def classes(src):
    out = []
    for m in re.finditer(r"^(class|struct) (\w+)[^;{]*\{", src, re.M):
        depth, i = 1, m.end()
        while depth and i < len(src):
            depth += {"{": 1, "}": -1}.get(src[i], 0)
            i += 1
        body = src[m.end():i - 1]
        access = "public" if m.group(1) == "struct" else "private"
        methods = members = 0
        level = 0
        for line in body.split("\n"):
            s = line.strip()
            if level == 0:
                a = re.match(r"(public|private|protected):", s)
                if a:
                    access = a.group(1)
                elif not s.startswith("//"):
                    if access == "public" and re.match(r"[\w:<>,~&*\s]*\b(operator\S*|~?\w+)\s*\(", s) \
                            and not s.startswith(("return", "using", "friend")):
                        methods += 1
                    if re.match(r"[\w:<>,\s*&\[\]]+\b\w+_(\s*[={][^;]*)?;", s) or \
                            re.match(r"[\w:<>,\s*&\[\]]+\b\w+_\{", s):
                        members += 1
            level += line.count("{") - line.count("}")
            level = max(level, 0)
        out.append((m.group(2), methods, members))
    return out


sizes, found = [], []
for f in files():
    t = text(f)
    sizes.append((t.count("\n"), f))
    if f.endswith(".h"):
        found += [(name, methods, members, f) for name, methods, members in classes(t)]
print("largest files (lines):")
for n, f in sorted(sizes, reverse=True)[:12]:
    print(f"  {n:5d}  {f}")
print("largest classes (public member functions, data members):")
for name, methods, members, f in sorted(found, key=lambda c: -(c[1] + c[2]))[:12]:
    print(f"  {methods:3d} {members:3d}  {name} ({f})")
