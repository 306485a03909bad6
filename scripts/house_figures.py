#!/usr/bin/env python3
"""How wide the code's doors are: the figures of the interfaces between the layers, for a tree or a
commit, so that two can be put side by side (docs/BENCHMARKS.md, "The house").

  scripts/house_figures.py [REV]   (default: the working tree; REV: a commit, read through git)

What it counts, each a reading of the text (not a compiler's; good for comparing two trees):
  - the virtual member functions of the class Solver (sim/core/solver.h), its destructor aside;
  - calls through Simulation::solver() (`solver()`) in app/, render/, tools/ and in sim/verify;
  - the lines of sim/gpu/gpu_solver.cpp;
  - the public member functions of Viewer (app/viewer.h) and of HairRenderer;
  - for each piece of arithmetic or constant that the C++ and the shaders share, in how many files
    it is written out (1: once, for both languages);
  - the ten longest functions of app/ sim/ render/ gl/ tools/ (lines from the name to the closing
    brace)."""
import re
import subprocess
import sys

rev = sys.argv[1] if len(sys.argv) > 1 else None
roots = ("app/", "sim/", "render/", "gl/", "tools/", "shaders/")


def files():
    if rev:
        out = subprocess.check_output(["git", "ls-tree", "-r", "--name-only", rev], text=True)
    else:
        out = subprocess.check_output(["git", "ls-files", "--cached", "--others",
                                       "--exclude-standard"], text=True)
    return [f for f in out.split() if f.startswith(roots) and
            f.endswith((".h", ".cpp", ".glsl", ".comp", ".vert", ".frag"))]


def text(path):
    try:
        if rev:
            return subprocess.check_output(["git", "show", f"{rev}:{path}"], text=True,
                                           stderr=subprocess.DEVNULL)
        return open(path).read()
    except (subprocess.CalledProcessError, FileNotFoundError):
        return ""


def code(src):
    """The text without comments and string literals, line breaks kept."""
    out, i, n = [], 0, len(src)
    while i < n:
        c = src[i]
        if src.startswith("//", i):
            j = src.find("\n", i)
            i = n if j < 0 else j
        elif src.startswith("/*", i):
            j = src.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * src.count("\n", i, j))
            i = j
        elif c == '"' or (c == "'" and not (i > 0 and src[i - 1].isalnum())):
            j = i + 1
            while j < n and src[j] != c:
                j += 2 if src[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def class_body(src, name):
    m = re.search(r"^(class|struct) " + name + r"\b[^;{]*\{", src, re.M)
    if not m:
        return None, None
    depth, i = 1, m.end()
    while depth and i < len(src):
        depth += {"{": 1, "}": -1}.get(src[i], 0)
        i += 1
    return m.group(1), src[m.end():i - 1]


def members(src, name):
    """(public member functions, virtual member functions but the destructor) of a class."""
    kind, body = class_body(code(src), name)
    if body is None:
        return None, None
    access = "public" if kind == "struct" else "private"
    public = virtual = 0
    level = 0
    for line in body.split("\n"):
        s = line.strip()
        if level == 0:
            a = re.match(r"(public|private|protected):", s)
            if a:
                access = a.group(1)
            elif re.match(r"[\w:<>,~&*\s]*\b(operator\S*|~?\w+)\s*\(", s) and \
                    not s.startswith(("return", "using", "friend", "static_assert")) and \
                    not re.search(r"=\s*delete", s) and not re.match(r"~", s) and \
                    not re.match(r"(virtual\s+)?~", s) and not re.match(name + r"\s*\(", s) \
                    and not re.match(r"explicit\s+" + name, s):
                if access == "public":
                    public += 1
                if s.startswith("virtual") or " override" in s:
                    virtual += 1 if s.startswith("virtual") else 0
        level += line.count("{") - line.count("}")
        level = max(level, 0)
    return public, virtual


def functions(src):
    """(name, lines) of each function body at namespace or class scope."""
    src = code(src)
    out = []
    stack = []  # True for a function's braces (and everything inside one)
    last = 0    # where the text before the next brace starts
    for m in re.finditer(r"[{};]", src):
        c = m.group()
        if c == ";":
            if not stack or not stack[-1]:
                last = m.end()
            continue
        if c == "{":
            inside = bool(stack) and stack[-1]
            head = src[last:m.start()]
            func = False
            if not inside:
                h = head.strip()
                if re.search(r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->\s*[\w:<>\s,*&]+)?$",
                             h) and not re.match(r"(namespace|class|struct|enum|union)\b", h) and \
                        not re.search(r"=\s*$", h) and "(" in h:
                    name = re.search(r"(~?[\w:]+|operator\s*\S+)\s*\(", h)
                    if name and name.group(1) not in ("if", "for", "while", "switch", "catch"):
                        func = True
                        line = src.count("\n", 0, last + len(head) - len(head.lstrip())) + 1
                        out.append([name.group(1), line, None])
            stack.append("func" if func else bool(inside))
            last = m.end()
        else:
            if stack:
                top = stack.pop()
                if top == "func" and out and out[-1][2] is None:
                    out[-1][2] = src.count("\n", 0, m.start()) + 1
            if not stack or not stack[-1]:
                last = m.end()
    return [(n, e - s + 1) for n, s, e in out if e is not None]


# Shared pieces and a pattern that marks a place where one is written out. Each is counted in the
# files that hold it; the files that only expand or include the one definition do not match.
TWINS = [
    ("the wind field's coefficients", r"2\.7\s*\*\s*w\s*\*\s*t"),
    ("the head field's trilinear sample (GLSL)", r"dims\.x\s*\*\s*\(c\.y\s*\+\s*dims\.y\s*\*\s*c\.z\)"),
    ("the follower push's rounds and margin",
     r"round\s*<\s*8\b|kPushRounds\s*=|\(d\s*-\s*kPushMargin\)|v\.w\s*-\s*1e-4|"
     r"#define CSM_FOLLOWER_PUSH_ROUNDS\s"),
    ("the 65,535-group split of a dispatch (C++)", r"std::min<[\w:]+>\(groups,\s*65535u?\)"),
    ("the measure sample's hash", r"0x846ca68bu?"),
    ("pi in the shaders", r"const\s+float\s+kPi\s*=|#define CSM_PI\s"),
    ("d3() in sim/verify", r"glm::dvec3\s+d3\s*\(\s*const\s+glm::vec4"),
    ("finite() in sim/verify", r"bool\s+finite\s*\(\s*const\s+glm::vec4"),
    ("a printf format()", r"std::string\s+format\s*\(\s*const\s+char\s*\*"),
    ("FrameUniforms' fields", r"(mat4|glm::mat4)\s+u?[vV]iewProj\s*;|F\(mat4,\s*viewProj\b"),
    ("SimParams' fields", r"(vec3|glm::vec3)\s+gravity\s*;|F\(vec3,\s*gravity\)"),
]


def main():
    fs = files()
    texts = {f: text(f) for f in fs}
    solver_src = texts.get("sim/core/solver.h", "")
    _, solver_virtual = members(solver_src, "Solver")
    reach = {"app/render/tools": 0, "sim/verify": 0}
    for f, t in texts.items():
        n = len(re.findall(r"\bsolver\(\)", code(t)))
        if f.startswith(("app/", "render/", "tools/")):
            reach["app/render/tools"] += n
        elif f.startswith("sim/verify/"):
            reach["sim/verify"] += n
    gpu_lines = texts.get("sim/gpu/gpu_solver.cpp", "").count("\n")
    viewer_public, _ = members(texts.get("app/viewer.h", ""), "Viewer")
    renderer_public, _ = members(texts.get("render/hair_renderer.h", ""), "HairRenderer")
    print(f"Solver: virtual member functions          {solver_virtual}")
    print(f"calls through solver() in app/ render/ tools/  {reach['app/render/tools']}")
    print(f"calls through solver() in sim/verify       {reach['sim/verify']}")
    print(f"sim/gpu/gpu_solver.cpp lines              {gpu_lines}")
    print(f"Viewer: public member functions           {viewer_public}")
    print(f"HairRenderer: public member functions     {renderer_public}")
    print("shared pieces, files writing each out:")
    for label, pattern in TWINS:
        where = sorted(f for f, t in texts.items() if re.search(pattern, t))
        print(f"  {len(where):2d}  {label}" + (f"  ({', '.join(where)})" if where else ""))
    longest = []
    for f, t in texts.items():
        if f.endswith((".h", ".cpp")) and not f.startswith("shaders/"):
            longest += [(n, name, f) for name, n in functions(t)]
    print("the ten longest functions (lines):")
    for n, name, f in sorted(longest, reverse=True)[:10]:
        print(f"  {n:4d}  {name} ({f})")


main()
