#!/usr/bin/env bash
# References to documents and files must point at something that exists:
#   tests/doc_refs.sh SOURCE_DIR
# Scans the repository's text files (git ls-files, plus new files git does not ignore; not
# docs/charts, docs/images or the fuzz corpora) and fails, naming file:line, on
#   - a Markdown document named anywhere (docs/NAME, or a bare NAME resolved against docs/
#     and the root) that does not exist;
#   - a section cited by number ("<doc> section 2.1", "<doc> §2.1", "section 2.1 of <doc>")
#     with no heading in that document starting with that number ("## 2." or "### 2.1 ");
#   - a section cited by title (<doc>, "Heading" or <doc> "Heading") with no heading whose
#     text, less its number, is that title or starts with it (case and backticks ignored);
#   - a repository path in a comment or a document (app/ sim/ render/ gl/ shaders/ presets/
#     tests/ tools/ scripts/ docs/, with a file extension) that does not exist. Shader paths
#     also resolve under shaders/, as the shader loader names them. Globs and patterns (with
#     * or { or ...), placeholders in capitals (presets/NAME.json) and anything under build/
#     are skipped.
# Document names and sections are checked in the whole text (parameter descriptions in
# string literals cite sections too); paths only in comments and documents.
set -u
src=${1:?usage: tests/doc_refs.sh SOURCE_DIR}
exec python3 - "$src" <<'PY'
import os, re, subprocess, sys

src = sys.argv[1]

def listed():
    try:
        out = subprocess.run(
            ["git", "-C", src, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            check=True, capture_output=True).stdout.decode("utf-8", "replace")
        names = sorted(set(n for n in out.split("\0") if n))
    except (OSError, subprocess.CalledProcessError):
        names = []
        for root, dirs, files in os.walk(src):
            dirs[:] = [d for d in dirs if not d.startswith((".git", "build"))]
            for f in files:
                names.append(os.path.relpath(os.path.join(root, f), src))
    return [n for n in names if os.path.isfile(os.path.join(src, n))]

SKIP_PREFIXES = ("docs/charts/", "docs/images/", "tests/fuzz/corpus/", "tests/fuzz/regressions/")
SKIP_SUFFIXES = (".dict", ".gitignore")
C_LIKE = (".h", ".hpp", ".c", ".cc", ".cpp", ".comp", ".glsl", ".vert", ".frag", ".geom", ".in")
HASH_LIKE = (".sh", ".py", ".cmake", ".txt", ".yml", ".yaml", ".toml")
SHADER_EXT = (".comp", ".glsl", ".vert", ".frag", ".geom")
TOP = r"(?:app|sim|render|gl|shaders|presets|tests|tools|scripts|docs)"

path_re = re.compile(r"(?<![\w./~$-])(" + TOP + r"/(?:[\w+-]+/)*[\w+-]+(?:\.[\w+-]+)*\.[A-Za-z]\w*)(?![\w/*{])")
doc_re = re.compile(r"(?<![\w./~$-])((?:[\w.-]+/)*[\w-]+\.md)(?![\w/])")
# The document name, with the Markdown around it: `name`, [`name`](link).
DOC = r"((?:[\w.-]+/)*[\w-]+\.md)`?(?:\]\([^)\s]*\))?"
NUM = r"(\d+(?:\.\d+)*)(?!\.?\d)"
sec_after_re = re.compile(DOC + r"\s*,?\s*(?:section|§)\s*" + NUM)
sec_before_re = re.compile(r"\bsection\s+" + NUM + r"\s+of\s+`?\[?`?" + DOC)
title_re = re.compile(DOC + r"(?:\s*,\s*|\s+)[\"“]([^\"”\n]*(?:\n[^\"”\n]*){0,2})[\"”]")

def kind(name):
    base = os.path.basename(name)
    if base.endswith(C_LIKE):
        return "c"
    if base.endswith(HASH_LIKE) or base in ("CMakeLists.txt", "run", ".editorconfig",
                                            ".clang-format"):
        return "hash"
    return "doc"

def texts(name, text):
    """(full, comments): the whole text with leading comment markers blanked, and the text
    that paths are checked in (comments of code, all of a document), line for line."""
    k = kind(name)
    full, comments = [], []
    for line in text.split("\n"):
        if k == "c":
            full.append(re.sub(r"^\s*//+", "", line))
            m = re.search(r"(?<![:\"])//(.*)$", line)
            comments.append(m.group(1) if m else "")
        elif k == "hash":
            full.append(re.sub(r"^\s*#+", "", line))
            m = re.search(r"(?:^|\s)#(.*)$", line)
            comments.append(m.group(1) if m else "")
        else:
            full.append(line)
            comments.append(line)
    return "\n".join(full), "\n".join(comments)

def norm(title):
    t = title.replace("`", "").replace("*", "")
    t = re.sub(r"\s+", " ", t).strip().lower()
    return re.sub(r"^\d+(?:\.\d+)*\.?\s+", "", t)

headings_cache = {}
def headings(path):
    if path not in headings_cache:
        nums, titles = set(), []
        fence = False
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith("```"):
                    fence = not fence
                    continue
                m = None if fence else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
                if not m:
                    continue
                n = re.match(r"(\d+(?:\.\d+)*)\.?(?:\s|$)", m.group(1))
                if n:
                    nums.add(n.group(1))
                titles.append(norm(m.group(1)))
        headings_cache[path] = (nums, titles)
    return headings_cache[path]

def resolve_doc(name, referrer):
    if ".." in name.split("/"):
        return None, True  # outside the repository: not ours to check
    here = os.path.dirname(referrer)
    cands = [name, os.path.join(here, name)]
    if "/" not in name:
        cands += [os.path.join("docs", name)]
    for c in cands:
        p = os.path.normpath(os.path.join(src, c))
        if os.path.isfile(p):
            return p, True
    return None, False

def path_exists(tok):
    if tok.startswith("build/"):
        return True
    if re.fullmatch(r"[A-Z][A-Z0-9_]*", os.path.basename(tok).split(".")[0]):
        return True  # a placeholder: presets/NAME.json
    if os.path.exists(os.path.join(src, tok)):
        return True
    return tok.endswith(SHADER_EXT) and os.path.exists(os.path.join(src, "shaders", tok))

failures, checked = [], 0
def fail(name, text, pos, what):
    failures.append(f"{name}:{text.count(chr(10), 0, pos) + 1}: {what}")

for name in listed():
    if name.startswith(SKIP_PREFIXES) or name.endswith(SKIP_SUFFIXES):
        continue
    with open(os.path.join(src, name), "rb") as f:
        raw = f.read()
    if b"\0" in raw[:8192]:
        continue
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        continue
    if ".md" not in text and "/" not in text:
        continue
    full, comments = texts(name, text)
    # Documents named.
    for m in doc_re.finditer(full):
        checked += 1
        if not resolve_doc(m.group(1), name)[1]:
            fail(name, full, m.start(1), f"missing document {m.group(1)}")
    # Sections by number.
    refs = [(m.start(), m.group(1), m.group(2)) for m in sec_after_re.finditer(full)]
    refs += [(m.start(), m.group(2), m.group(1)) for m in sec_before_re.finditer(full)]
    for pos, doc, num in refs:
        checked += 1
        path, ok = resolve_doc(doc, name)
        if path and num not in headings(path)[0]:
            fail(name, full, pos, f"{doc} has no section {num}")
    # Sections by title.
    for m in title_re.finditer(full):
        doc, title = m.group(1), norm(m.group(2))
        if not title:
            continue
        checked += 1
        path, ok = resolve_doc(doc, name)
        if path and not any(t == title or t.startswith(title + " ") or
                            t.startswith(title + ":") or t.startswith(title + ",") or
                            t.startswith(title + " (") for t in headings(path)[1]):
            fail(name, full, m.start(), f'{doc} has no heading "{m.group(2)}"')
    # Repository paths in comments and documents.
    for m in path_re.finditer(comments):
        tok = m.group(1)
        if tok.endswith(".md") or comments.startswith("..", m.end()):
            continue
        checked += 1
        if not path_exists(tok):
            fail(name, comments, m.start(1), f"missing file {tok}")

for f in failures:
    print(f)
if failures:
    print(f"FAIL: {len(failures)} of {checked} references point at nothing")
    sys.exit(1)
print(f"ok: {checked} references checked")
PY
