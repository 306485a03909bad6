#!/usr/bin/env bash
# Figures a script can produce must agree with the documents that quote them:
#   tests/doc_figures.sh [--write] SOURCE_DIR BUILD_DIR
# A document marks such a figure as <!-- fig:NAME -->VALUE<!-- /fig --> (README.md and
# docs/*.md). The names and where their values come from:
#   tests, tests.LABEL   ctest -N in BUILD_DIR ("Total Tests: N"), and ctest -N -L '^LABEL$' for
#                        each of cpu, gpu, app, cli, window and quick that ctest --print-labels lists
#   fuzz.targets         the fuzz targets: scripts/fuzz.sh's default list, which must name the
#                        same targets as tests/fuzz/CMakeLists.txt builds
#   fuzz.short_seconds   the seconds each target gets in `scripts/fuzz.sh short`
# Fails, naming file:line, the name, the document's value and the script's, on a figure that
# differs, on a name it does not know (a label ctest does not list is not known) and on a marker
# that is not closed on its line. With --write it puts the script's values in place instead (an
# unknown name still fails). CTEST (default: ctest) is the command run for ctest, split as a
# shell would split it.
set -u
write=0
if [ "${1:-}" = --write ]; then
  write=1
  shift
fi
src=${1:?usage: tests/doc_figures.sh [--write] SOURCE_DIR BUILD_DIR}
build=${2:?usage: tests/doc_figures.sh [--write] SOURCE_DIR BUILD_DIR}
exec python3 - "$src" "$build" "$write" <<'PY'
import glob, os, re, shlex, subprocess, sys

src, build, write = sys.argv[1], sys.argv[2], sys.argv[3] == "1"
ctest = shlex.split(os.environ.get("CTEST", "ctest"))
LABELS = ("cpu", "gpu", "app", "cli", "window", "quick")
problems = []


def run_ctest(*args):
    try:
        p = subprocess.run(ctest + list(args), cwd=build, capture_output=True, text=True)
    except OSError as e:
        sys.exit(f"doc_figures: cannot run {' '.join(ctest)}: {e}")
    if p.returncode != 0:
        sys.exit(f"doc_figures: {' '.join(ctest + list(args))} in {build} failed:\n"
                 f"{p.stdout}{p.stderr}")
    return p.stdout


def total(*args):
    out = run_ctest("-N", *args)
    m = re.search(r"^Total Tests: (\d+)\s*$", out, re.M)
    if not m:
        sys.exit(f"doc_figures: no \"Total Tests:\" in the output of ctest -N {' '.join(args)}"
                 f" in {build}")
    return int(m.group(1))


figures = {"tests": total()}
out = run_ctest("--print-labels")
listed = set(l.strip() for l in out.split("All Labels:", 1)[-1].splitlines() if l.strip())
for label in LABELS:
    if label in listed:
        figures["tests." + label] = total("-L", f"^{label}$")


def read(rel):
    with open(os.path.join(src, rel), encoding="utf-8") as f:
        return f.read()


fuzz_sh = read("scripts/fuzz.sh")
m = re.search(r"^targets=\(\$\{FUZZ_TARGETS:-([^}]*)\}\)", fuzz_sh, re.M)
if not m:
    sys.exit("doc_figures: scripts/fuzz.sh: no default target list (targets=(${FUZZ_TARGETS:-...}))")
script_targets = m.group(1).split()
m = re.search(r"^foreach\(target ([^)]*)\)", read("tests/fuzz/CMakeLists.txt"), re.M)
if not m:
    sys.exit("doc_figures: tests/fuzz/CMakeLists.txt: no foreach(target ...) list")
built_targets = m.group(1).split()
if sorted(script_targets) != sorted(built_targets):
    problems.append(f"scripts/fuzz.sh runs {' '.join(script_targets)} but "
                    f"tests/fuzz/CMakeLists.txt builds {' '.join(built_targets)}")
figures["fuzz.targets"] = len(built_targets)
m = re.search(r"^\s*seconds=\$\{2:-(\d+)\}", fuzz_sh, re.M)
if not m:
    sys.exit("doc_figures: scripts/fuzz.sh: no default for the short run's seconds "
             "(seconds=${2:-N})")
figures["fuzz.short_seconds"] = int(m.group(1))

MARK = re.compile(r"<!-- fig:([\w.-]+) -->(.*?)<!-- /fig -->")
OPEN = re.compile(r"<!-- fig:([\w.-]+) -->")
docs = ["README.md"] + sorted(os.path.relpath(p, src)
                              for p in glob.glob(os.path.join(src, "docs", "*.md")))
checked = 0
for rel in docs:
    path = os.path.join(src, rel)
    if not os.path.isfile(path):
        continue
    lines = read(rel).split("\n")
    changed = False
    for i, line in enumerate(lines):
        if len(MARK.findall(line)) != len(OPEN.findall(line)):
            problems.append(f"{rel}:{i + 1}: a <!-- fig:NAME --> marker not closed by "
                            f"<!-- /fig --> on its line")
        def check(m):
            global checked, changed
            name, value = m.group(1), m.group(2)
            checked += 1
            if name not in figures:
                label = name[len("tests."):] if name.startswith("tests.") else None
                why = (f"ctest in {build} lists no label {label}" if label in LABELS
                       else f"known: {', '.join(sorted(figures))}")
                problems.append(f"{rel}:{i + 1}: unknown figure \"{name}\" ({why})")
                return m.group(0)
            want = str(figures[name])
            if value.replace(",", "").strip() == want:
                return m.group(0)
            if write:
                changed = True
                print(f"doc_figures: {rel}:{i + 1}: {name} {value} -> {want}")
                return f"<!-- fig:{name} -->{want}<!-- /fig -->"
            problems.append(f"{rel}:{i + 1}: {name} is {value} in the document, {want} by the "
                            f"scripts")
            return m.group(0)
        lines[i] = MARK.sub(check, line)
    if changed:
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))

for p in problems:
    print(p)
if problems:
    print(f"FAIL: {len(problems)} problems, {checked} marked figures checked "
          f"(tests/doc_figures.sh --write SOURCE_DIR BUILD_DIR puts the scripts' values in)")
    sys.exit(1)
print(f"ok: {checked} marked figures agree ("
      + ", ".join(f"{k} {v}" for k, v in sorted(figures.items())) + ")")
PY
