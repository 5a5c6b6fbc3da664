#!/usr/bin/env python3
"""The README and the engineer guide against the code, so that neither can drift from it.

Checks, each failure naming the doc's line and what is missing:
  paths    every repository path the README, the engineer guide and the design document name in
           backticks, in table cells or in links exists (`NAME`, `OUT`, `DIR`, `FILE` stand for
           any name; `render/methods/registry.{h,cpp}` is two files). A path written from inside
           render/ or input/ as the code includes it (`methods/sg_lights.h`,
           `journal/journal_log.h`) counts too.
  folders  every folder under render/, input/ and firmware-host/ (two levels down) that holds
           code, and every folder of assets/, is named in a folder table (a table whose first
           column is "folder") of the README or the guide: its path in a row's first column, or
           its own name in backticks (`sheer`, `journal/journal_log.h`) in its parent's row.
  layers   the guide's layer block (the code block under "## Layers": one line per layer, its
           render/ folders first, comma-separated) lists every render/ folder once, and a folder
           includes (#include "FOLDER/...") only its own line's folder or those on the lines above.
  fields   every `RuntimeMethod::field` the docs name is a member of RuntimeMethod
           (render/methods/runtime_method.h), and the guide's "Adding a rung" step that returns
           the entry names exactly its data members, bare (`name`, `glsl`, ...).
  methods  the guide's method table (under "## Methods and the registry") names exactly the
           methods render/methods/registry.cpp registers.
  parity   the guide's parity-test table names only tests that exist, and every test labelled
           `parity` under tests/.

Usage: docs_match_code.py [--root DIR] [--readme FILE] [--guide FILE] [--design FILE]
       docs_match_code.py [--root DIR] --self-test
--root is the repository (default: two folders above this file); --readme, --guide and --design
read another copy of a doc in its place (its links still resolve from the doc's place in the
repository). --self-test plants a mistake of each kind in temporary copies of the docs and checks
that each is caught. Python 3 standard library only. Exit status: 0 when the docs match.
"""
import argparse
import glob
import os
import re
import sys
import tempfile
from pathlib import Path

PATH_TOPS = ("render", "input", "firmware-host", "tests", "assets", "systemd", "docs", "debian")
PLACEHOLDERS = ("NAME", "OUT", "DIR", "FILE")
TOKEN = re.compile(r"(?<![\w./\-])((?:[\w.*\-]|<[\w]+>|\{[\w.,]+\}|/)+)")
SPAN = re.compile(r"`([^`\n]+)`")
LINK = re.compile(r"\]\(([^)\s]+)\)")
CODE_SUFFIXES = (".cpp", ".h")


class Doc:
    """One markdown file: its lines, where it lives in the repository, and its code fences."""

    def __init__(self, root, rel, source=None):
        self.rel = rel  # the doc's place in the repository, e.g. docs/engineer-guide.md
        self.lines = Path(source or root / rel).read_text(encoding="utf-8").split("\n")
        self.in_fence = []
        fenced = False
        for line in self.lines:
            opens = line.lstrip().startswith("```")
            self.in_fence.append(fenced or opens)
            if opens:
                fenced = not fenced

    def prose(self):
        """(line number, text) of every line outside code fences."""
        return [(i + 1, l) for i, l in enumerate(self.lines) if not self.in_fence[i]]

    def section(self, heading):
        """(line number, text) of the lines under `heading` up to the next heading of its level."""
        level = len(heading) - len(heading.lstrip("#"))
        out, inside = [], False
        for i, line in enumerate(self.lines):
            if not self.in_fence[i] and re.match(r"^#+ ", line):
                if inside and len(line) - len(line.lstrip("#")) <= level:
                    break
                if line.strip() == heading:
                    inside = True
                    continue
            if inside:
                out.append((i + 1, line))
        return out

    def tables(self, lines=None):
        """Each table as (header cells, [(line number, cells, raw line)])."""
        out, current = [], None
        for n, line in lines if lines is not None else self.prose():
            if line.startswith("|"):
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if current is None:
                    current = (cells, [])
                    out.append(current)
                elif not set(line.replace("|", "").strip()) <= set("-: "):
                    current[1].append((n, cells, line))
            else:
                current = None
        return out


def spans(text):
    return SPAN.findall(text)


def first_names(cell):
    """The backticked names of a table cell, less those in parentheses ("`x_test` (label `unit`)")."""
    return [s.strip() for s in spans(re.sub(r"\([^)]*\)", "", cell))]


class Checker:
    def __init__(self, root, readme=None, guide=None, design=None):
        self.root = Path(root).resolve()
        self.readme = Doc(self.root, "README.md", readme)
        self.guide = Doc(self.root, "docs/engineer-guide.md", guide)
        self.design = Doc(self.root, "docs/design.md", design)
        self.failures = []

    def fail(self, doc, line, message):
        where = f"{doc.rel}:{line}" if line else doc.rel
        self.failures.append(f"{where}: {message}")

    # --- paths -------------------------------------------------------------------------------
    def rooms(self):
        """Folders a path may be written from, as the code includes it: render/, input/,
        input/common/ and render/methods/ (`methods/x.h`, `journal/x.h`, `iwasaki/x.h`)."""
        out = {}
        for base in ("render", "input", "input/common", "render/methods"):
            d = self.root / base
            if d.is_dir():
                for sub in d.iterdir():
                    if sub.is_dir():
                        out.setdefault(sub.name, []).append(base)
        return out

    def exists(self, path):
        """Whether a written path names something in the repository (an anchor alone does)."""
        path = path.split("#")[0].rstrip(".")
        if not path:
            return True
        alternatives = [path]
        brace = re.search(r"\{([^}]*)\}", path)
        if brace:
            alternatives = [path[: brace.start()] + part + path[brace.end():] for part in brace.group(1).split(",")]
        for p in alternatives:
            if (self.root / p).exists():
                continue
            pattern = re.sub(r"<\w+>", "*", p)
            for word in PLACEHOLDERS:
                pattern = re.sub(rf"(?<![A-Za-z]){word}(?![A-Za-z])", "*", pattern)
            if not glob.glob(str(self.root / pattern)):
                return False
        return True

    def check_paths(self):
        rooms = self.rooms()
        for doc in (self.readme, self.guide, self.design):
            here = Path(doc.rel).parent
            for n, line in doc.prose():
                seen = []
                for span in spans(line):
                    for token in TOKEN.findall(span):
                        if "/" not in token:
                            continue
                        top = token.split("/")[0]
                        if top in PATH_TOPS:
                            seen.append((token, token))
                        elif top in rooms:
                            written = [f"{base}/{token}" for base in rooms[top]]
                            seen.append((token, written))
                if line.startswith("|"):
                    bare = SPAN.sub(" ", LINK.sub(" ", line))
                    for token in TOKEN.findall(bare):
                        if "/" in token and token.split("/")[0] in PATH_TOPS:
                            seen.append((token, token))
                for target in LINK.findall(line):
                    if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                        continue
                    seen.append((target, os.path.normpath(str(here / target.split("#")[0]))))
                for written, candidates in seen:
                    candidates = candidates if isinstance(candidates, list) else [candidates]
                    if not any(self.exists(c) for c in candidates):
                        self.fail(doc, n, f"names `{written}`, but the repository has no such file or folder"
                                  + (f" (looked for {', '.join(candidates)})" if candidates != [written] else ""))

    # --- folders -----------------------------------------------------------------------------
    def code_folders(self):
        out = []
        for top in ("render", "input", "firmware-host"):
            base = self.root / top
            for d in sorted(base.glob("*")) + sorted(base.glob("*/*")):
                if d.is_dir() and any(f.suffix in CODE_SUFFIXES for f in d.iterdir() if f.is_file()):
                    out.append(d.relative_to(self.root).as_posix())
        out += [d.relative_to(self.root).as_posix() for d in sorted((self.root / "assets").glob("*")) if d.is_dir()]
        return out

    def folder_rows(self):
        """{folder named in a folder table's first column: the names its row gives in backticks},
        and the README's folder table's first line."""
        rows, header_line = {}, 0
        for doc in (self.readme, self.guide):
            for header, body in doc.tables():
                if header[0].lower() != "folder" or not body:
                    continue
                if doc is self.readme and not header_line:
                    header_line = body[0][0] - 2
                for _, cells, line in body:
                    names = set()
                    for s in spans(line):
                        names.update(t.strip("/") for t in TOKEN.findall(s))
                        names.update(t.split("/")[0] for t in TOKEN.findall(s))
                    for f in first_names(cells[0]):
                        rows.setdefault(f.strip("/"), set()).update(names)
        return rows, header_line

    def check_folders(self):
        rows, line = self.folder_rows()
        if len(rows) < 10:
            self.fail(self.readme, 0, "no folder table found (a table whose first column is 'folder')")
            return
        for folder in self.code_folders():
            parent, name = folder.rsplit("/", 1)
            if folder in rows or name in rows.get(parent, set()):
                continue
            what = "holds code" if not folder.startswith("assets/") else "is a folder of assets"
            self.fail(self.readme, line,
                      f"the folder tables leave out {folder}/, which {what}: add a row `{folder}` to the "
                      f"README's folder table, or name `{name}` in the row of `{parent}`")

    # --- layers ------------------------------------------------------------------------------
    def check_layers(self):
        section = self.guide.section("## Layers")
        block = [(n, l) for n, l in section if self.guide.in_fence[n - 1] and not l.lstrip().startswith("```")]
        if not block:
            self.fail(self.guide, 0, "no code block of layers under '## Layers'")
            return
        level, where = {}, {}
        for i, (n, line) in enumerate(block):
            m = re.match(r"^([a-z_]+(?:, [a-z_]+)*)(\s{2,}|$)", line)
            if not m:
                continue
            for folder in m.group(1).split(", "):
                if folder in level:
                    self.fail(self.guide, n, f"the layer block lists `{folder}` twice (also line {where[folder]})")
                level[folder], where[folder] = i, n
        render = self.root / "render"
        folders = sorted(d.name for d in render.iterdir() if d.is_dir() and any(
            f.suffix in CODE_SUFFIXES for f in d.rglob("*")))
        first = block[0][0]
        for folder in folders:
            if folder not in level:
                self.fail(self.guide, first, f"the layer block leaves out render/{folder}/")
        for folder in level:
            if folder not in folders:
                self.fail(self.guide, where[folder], f"the layer block names `{folder}`, which is no code folder in render/")
        include = re.compile(r'^\s*#\s*include\s+"([\w\-]+)/')
        for folder in folders:
            if folder not in level:
                continue
            reported = set()
            for f in sorted((render / folder).rglob("*")):
                if f.suffix not in CODE_SUFFIXES:
                    continue
                for k, text in enumerate(f.read_text(encoding="utf-8", errors="replace").split("\n")):
                    m = include.match(text)
                    if not m or m.group(1) == folder or m.group(1) not in level or m.group(1) in reported:
                        continue
                    if level[m.group(1)] >= level[folder]:
                        reported.add(m.group(1))
                        self.fail(self.guide, where[folder],
                                  f"`{folder}` includes {m.group(1)}/ ({f.relative_to(self.root)}:{k + 1}), "
                                  f"which the layer block does not put on a line above it")

    # --- RuntimeMethod fields ----------------------------------------------------------------
    def runtime_method_members(self):
        header = (self.root / "render/methods/runtime_method.h").read_text(encoding="utf-8")
        m = re.search(r"struct RuntimeMethod \{(.*?)\n\};", header, re.S)
        if not m:
            return set(), set()
        data, functions = set(), set()
        for line in m.group(1).split("\n"):
            line = line.split("//")[0].rstrip()
            if re.match(r"^\s+return\b", line):  # a member function's body
                continue
            f = re.match(r"^\s+[\w:<>, ]+?[\s>&*](\w+)\(.*\).*\{", line)
            if f:
                functions.add(f.group(1))
                continue
            d = re.match(r"^\s+[\w:<>, ]+?[\s>](\w+)\s*(=[^;]*|\{[^;]*\})?;$", line)
            if d:
                data.add(d.group(1))
        return data, functions

    def check_fields(self):
        data, functions = self.runtime_method_members()
        if len(data) < 5:
            self.fail(self.guide, 0, "could not read RuntimeMethod's members from render/methods/runtime_method.h")
            return
        for doc in (self.readme, self.guide, self.design):
            for n, line in doc.prose():
                for field in re.findall(r"RuntimeMethod::(\w+)", line):
                    if field not in data | functions:
                        self.fail(doc, n, f"names `RuntimeMethod::{field}`, which render/methods/runtime_method.h does not declare")
        lines = self.guide.section("## Adding a rung")
        start = next((i for i, (_, l) in enumerate(lines) if "return the `RuntimeMethod` entry" in l), None)
        if start is None:
            self.fail(self.guide, 0, "'## Adding a rung' has no step that returns the `RuntimeMethod` entry")
            return
        step, n0 = [], lines[start][0]
        for i, (_, l) in enumerate(lines[start:]):
            if i and re.match(r"^\d+\. ", l):
                break
            step.append(l)
        text = " ".join(step)
        text = text[text.index("return the `RuntimeMethod` entry") + len("return the `RuntimeMethod` entry"):]
        named = set(re.findall(r"`([a-z_]+)`", text))
        for field in sorted(named - data):
            self.fail(self.guide, n0, f"the step that returns the `RuntimeMethod` entry names `{field}`, not a field of RuntimeMethod")
        for field in sorted(data - named):
            self.fail(self.guide, n0, f"the step that returns the `RuntimeMethod` entry leaves out its field `{field}`")

    # --- methods -----------------------------------------------------------------------------
    def registered_methods(self):
        """The names render/methods/registry.cpp registers, read from each entry's factory."""
        registry = (self.root / "render/methods/registry.cpp").read_text(encoding="utf-8")
        body = re.search(r"registry\(\) \{(.*?)\n\}", registry, re.S)
        factories = re.findall(r"\b(\w+_methods?)\(\)", body.group(1) if body else "")
        names, unread = [], []
        sources = sorted((self.root / "render/methods").glob("*/*.cpp"))
        for factory in factories:
            found = None
            for src in sources:
                text = src.read_text(encoding="utf-8")
                d = re.search(rf"^(?:RuntimeMethod|std::vector<RuntimeMethod>) {factory}\(\) \{{(.*?)^\}}", text, re.S | re.M)
                if d:
                    found = (text, d.group(1))
                    break
            if not found:
                unread.append(factory)
                continue
            text, definition = found
            got = []
            # A family built by a helper: the helper's name expression, with its suffixes.
            helpers = set(re.findall(r"\b(\w+)\(", definition)) - {factory}
            bodies = [definition] + [h.group(1) for h in (re.search(
                rf"^RuntimeMethod {helper}\([^)]*\) \{{(.*?)^\}}", text, re.S | re.M) for helper in helpers) if h]
            for b in bodies:
                for expr in re.findall(r"\bm\.name = ([^;]*);", b):
                    literals = re.findall(r'"(\w*)"', expr)
                    if "suffix" in expr:
                        suffixes = re.findall(r'\{"(\w*)",', text)
                        got += [p + s for p in literals for s in suffixes]
                    elif len(literals) == 1:
                        got.append(literals[0])
                    else:
                        got = []
                        break
            if got:
                names += got
            else:
                unread.append(factory)
        return names, unread

    def check_methods(self):
        names, unread = self.registered_methods()
        for factory in unread:
            self.fail(self.guide, 0, f"could not read the method names {factory}() registers (render/methods/registry.cpp); "
                      "teach tests/docs/docs_match_code.py to read them")
        if len(names) < 5:
            self.fail(self.guide, 0, "read fewer than five methods from render/methods/registry.cpp")
            return
        tables = [t for t in self.guide.tables(self.guide.section("## Methods and the registry")) if t[0][0] == "method"]
        if not tables:
            self.fail(self.guide, 0, "no method table (first column 'method') under '## Methods and the registry'")
            return
        listed = {}
        for n, cells, _ in tables[0][1]:
            for name in first_names(cells[0]):
                listed[name] = n
        header_line = tables[0][1][0][0] - 2
        for name in names:
            if name not in listed:
                self.fail(self.guide, header_line, f"the method table leaves out `{name}`, which render/methods/registry.cpp registers")
        for name, n in listed.items():
            if name not in names:
                self.fail(self.guide, n, f"the method table lists `{name}`, which render/methods/registry.cpp does not register")

    # --- parity tests ------------------------------------------------------------------------
    def registered_tests(self):
        """{test name: label} of every weft_test and add_test under tests/."""
        tests = {}
        for cmake in sorted((self.root / "tests").rglob("CMakeLists.txt")):
            text = cmake.read_text(encoding="utf-8")
            for name, label in re.findall(r"^\s*weft_test\((\w+)\s+(\w+)", text, re.M):
                tests[name] = label
            for name in re.findall(r"add_test\(NAME (\w+)", text):
                tests.setdefault(name, "")
        return tests

    def check_parity(self):
        tests = self.registered_tests()
        tables = [t for t in self.guide.tables(self.guide.section("## Parity tests")) if t[0][0] == "test"]
        if not tables:
            self.fail(self.guide, 0, "no test table (first column 'test') under '## Parity tests'")
            return
        listed = {}
        for n, cells, _ in tables[0][1]:
            for name in first_names(cells[0]):
                listed[name] = n
        for name, n in listed.items():
            if name not in tests:
                self.fail(self.guide, n, f"the parity table names `{name}`, which no tests/**/CMakeLists.txt registers")
        header_line = tables[0][1][0][0] - 2
        for name, label in sorted(tests.items()):
            if label == "parity" and name not in listed:
                self.fail(self.guide, header_line, f"the parity table leaves out `{name}` (label parity)")

    def run(self):
        for check in (self.check_paths, self.check_folders, self.check_layers, self.check_fields,
                      self.check_methods, self.check_parity):
            check()
        return self.failures


def self_test(root):
    """Each kind of drift, planted in a temporary copy of a doc, must be caught."""
    root = Path(root).resolve()
    readme = (root / "README.md").read_text(encoding="utf-8")
    guide = (root / "docs/engineer-guide.md").read_text(encoding="utf-8")

    def replace_once(text, old, new):
        if old not in text:
            raise SystemExit(f"self-test: the doc no longer holds {old!r}; update the self-test")
        return text.replace(old, new, 1)

    plants = [
        ("a folder that does not exist", "readme",
         lambda t: replace_once(t, "| `render/core` |", "| `render/core`, `render/no_such_room` |"), "render/no_such_room"),
        ("a file path that does not exist", "guide",
         lambda t: replace_once(t, "`render/methods/runtime_method.h`", "`render/methods/runtime_methods.h`"), "runtime_methods.h"),
        ("an include-style path that does not exist", "guide",
         lambda t: replace_once(t, "`methods/sg_lights.h`", "`methods/sg_light.h`"), "methods/sg_light.h"),
        ("a code folder left out of the folder table", "readme",
         lambda t: replace_once(t, "`sheer` with `sheer_vertex`", "`sheer_vertex`"), "render/methods/sheer/"),
        ("a RuntimeMethod field that does not exist", "guide",
         lambda t: replace_once(t, "`RuntimeMethod::kiosk_rung`", "`RuntimeMethod::ladder_position`"), "ladder_position"),
        ("a field left out of the entry's step", "guide",
         lambda t: replace_once(t, "`make_gpu`, ", ""), "`make_gpu`"),
        ("a registered method left out of the method table", "guide",
         lambda t: re.sub(r"^\| `mdfrot` \|.*\n", "", t, count=1, flags=re.M), "`mdfrot`"),
        ("a method that is not registered", "guide",
         lambda t: replace_once(t, "| `sgpoint` |", "| `sgpoint`, `sgspot` |"), "`sgspot`"),
        ("a parity test left out", "guide",
         lambda t: re.sub(r"^\| `sheer_parity_test` \|.*\n", "", t, count=1, flags=re.M), "sheer_parity_test"),
        ("two layers in the wrong order", "guide",
         lambda t: re.sub(r"^(gl, shaders .*\n)(methods .*\n)", r"\2\1", t, count=1, flags=re.M), "`methods` includes gl/"),
        ("a render/ folder left out of the layers", "guide",
         lambda t: replace_once(t, "\ngpu, label ", "\ngpu "), "leaves out render/label/"),
    ]
    missed = []
    with tempfile.TemporaryDirectory() as tmp:
        for what, doc, plant, expect in plants:
            copy = Path(tmp) / ("README.md" if doc == "readme" else "engineer-guide.md")
            copy.write_text(plant(readme if doc == "readme" else guide), encoding="utf-8")
            failures = Checker(root, **{doc: copy}).run()
            if not any(expect in f for f in failures):
                missed.append(f"{what}: no failure mentions {expect!r} (failures: {failures})")
            else:
                print(f"caught {what}: {next(f for f in failures if expect in f)}")
    return missed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=str(Path(__file__).resolve().parents[2]))
    parser.add_argument("--readme")
    parser.add_argument("--guide")
    parser.add_argument("--design")
    parser.add_argument("--self-test", action="store_true")
    a = parser.parse_args()
    if a.self_test:
        missed = self_test(a.root)
        for m in missed:
            print("MISSED " + m)
        return 1 if missed else 0
    failures = Checker(a.root, a.readme, a.guide, a.design).run()
    for f in failures:
        print(f)
    print(f"{len(failures)} mismatch(es) between the docs and the code" if failures else "the docs match the code")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
