#!/usr/bin/env python3
"""Checks the shape of the Rust code (docs/architecture in the developers' guide):

- no import cycle between modules: for every module, the graph of its child modules (and of its own file), an
  edge from A to B when code in A (or below it) names B (or something below it), must be acyclic; a module's
  file may re-export its children (`pub use child::Item;`) without that counting as use;
- no function longer than 150 lines outside tests (`#[cfg(test)]` modules and `tests/` folders).

Run from the repository root: `python3 tools/check_structure.py` (exit 1 and one line per finding otherwise).
No dependencies beyond the standard library; comments and string literals are stripped before the code is read.
"""

import os
import re
import sys

MAX_FN_LINES = 150
CRATE_DIRS = ["crates/pounding", "crates/pounding-study", "crates/pounding-cli", "crates/pounding-py"]


def strip(text):
    """The text with comments, string and char literals blanked (line structure kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "r" and re.match(r'r#*"', text[i:i + 10]) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'r(#*)"', text[i:])
            close = '"' + m.group(1)
            j = text.find(close, i + len(m.group(0)))
            j = n if j < 0 else j + len(close)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "'":
            # A char literal ('a', '\n', '\u{..}'), not a lifetime ('a without a closing quote).
            m = re.match(r"'(\\u\{[0-9a-fA-F]+\}|\\.|[^\\'])'", text[i:])
            if m:
                out.append(" " * len(m.group(0)))
                i += len(m.group(0))
            else:
                out.append(c)
                i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def crate_files(crate):
    """{module path tuple: file} of the crate's library or binary source."""
    src = os.path.join(crate, "src")
    root = "lib.rs" if os.path.exists(os.path.join(src, "lib.rs")) else "main.rs"
    files = {}

    def walk(path, file, folder):
        files[path] = file
        code = strip(open(file, encoding="utf-8").read())
        for m in re.finditer(r"^\s*(?:pub(?:\([^)]*\))?\s+)?mod\s+([a-z_][a-z0-9_]*)\s*;", code, re.M):
            name = m.group(1)
            for cand in (os.path.join(folder, name + ".rs"), os.path.join(folder, name, "mod.rs")):
                if os.path.exists(cand):
                    sub = os.path.join(folder, name)
                    walk(path + (name,), cand, sub)
                    break

    walk((), os.path.join(src, root), src)
    return files


def test_spans(code):
    """Line ranges [start, end) of `#[cfg(test)] mod ... { }` blocks."""
    spans = []
    for m in re.finditer(r"#\[cfg\(test\)\]\s*(?:pub\s+)?mod\s+\w+\s*\{", code):
        start = m.end() - 1
        depth, j = 0, start
        while j < len(code):
            if code[j] == "{":
                depth += 1
            elif code[j] == "}":
                depth -= 1
                if depth == 0:
                    break
            j += 1
        spans.append((code.count("\n", 0, m.start()), code.count("\n", 0, j) + 1))
    return spans


def references(path, code, modules):
    """The modules that `code` (of module `path`) names."""
    out = set()
    children = {p[-1] for p in modules if len(p) == len(path) + 1 and p[:len(path)] == path}
    tops = {p[0] for p in modules if len(p) == 1}
    # Lines that only re-export children (`pub use child::...;`, possibly grouped) do not count as use.
    code = re.sub(r"^\s*pub(?:\([^)]*\))?\s+use\s+(?:self::)?([a-z_][a-z0-9_]*)::[^;]*;",
                  lambda m: "" if m.group(1) in children else m.group(0), code, flags=re.M)
    for m in re.finditer(r"(?<![A-Za-z0-9_:])((?:crate|super|self|[a-z_][a-z0-9_]*)(?:::[A-Za-z_][A-Za-z0-9_]*)+)", code):
        parts = m.group(1).split("::")
        if parts[0] == "crate":
            base, rest = (), parts[1:]
        elif parts[0] in ("super", "self"):
            base, rest = path, parts
            while rest and rest[0] in ("super", "self"):
                if rest[0] == "super":
                    base = base[:-1]
                rest = rest[1:]
        elif parts[0] in children:
            base, rest = path, parts
        elif path == () and parts[0] in tops:
            base, rest = (), parts
        else:
            continue
        target = base
        for p in rest:
            if target + (p,) in modules:
                target = target + (p,)
            else:
                break
        out.add(target)
    return out


def cycles(crate):
    files = crate_files(crate)
    modules = set(files)
    uses = {}
    for path, file in files.items():
        code = strip(open(file, encoding="utf-8").read())
        for a, b in test_spans(code):
            lines = code.split("\n")
            code = "\n".join(lines[:a] + [""] * (b - a) + lines[b:])
        uses[path] = references(path, code, modules)
    found = []
    for parent in sorted(modules):
        kids = sorted(p for p in modules if len(p) == len(parent) + 1 and p[:len(parent)] == parent)
        if not kids:
            continue
        nodes = kids + [parent]  # the parent node is the parent's own file

        def owner(m):
            """The node of `parent`'s graph that module `m` falls in, if any."""
            if m == parent:
                return parent
            for k in kids:
                if m[:len(k)] == k:
                    return k
            return None

        edges = {n: set() for n in nodes}
        for src, targets in uses.items():
            a = owner(src)
            if a is None:
                continue
            for t in targets:
                b = owner(t)
                if b is not None and b != a:
                    # A child naming its parent's module path only to reach a sibling is counted on the sibling.
                    edges[a].add(b)
        # Tarjan's strongly connected components.
        index, low, stack, on, comps = {}, {}, [], set(), []
        counter = [0]

        def visit(v):
            index[v] = low[v] = counter[0]
            counter[0] += 1
            stack.append(v)
            on.add(v)
            for w in edges[v]:
                if w not in index:
                    visit(w)
                    low[v] = min(low[v], low[w])
                elif w in on:
                    low[v] = min(low[v], index[w])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    comps.append(comp)

        for v in nodes:
            if v not in index:
                visit(v)
        for comp in comps:
            name = lambda p: "::".join(p) if p != parent else ("::".join(p) or "crate") + " (its own file)"
            found.append(f"{crate}: import cycle among {{{', '.join(sorted(name(p) for p in comp))}}}")
    return found


def long_functions(root):
    found = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in ("target", ".git", ".venv", "tests", "fuzz")]
        for f in filenames:
            if not f.endswith(".rs"):
                continue
            file = os.path.join(dirpath, f)
            code = strip(open(file, encoding="utf-8").read())
            skip = test_spans(code)
            for m in re.finditer(r"\bfn\s+([A-Za-z_][A-Za-z0-9_]*)", code):
                line = code.count("\n", 0, m.start())
                if any(a <= line < b for a, b in skip):
                    continue
                # The body: the first `{` after the signature (or none: a declaration ending in `;`).
                j = m.end()
                depth_paren = 0
                while j < len(code):
                    ch = code[j]
                    if ch in "([":
                        depth_paren += 1
                    elif ch in ")]":
                        depth_paren -= 1
                    elif ch == ";" and depth_paren == 0:
                        j = -1
                        break
                    elif ch == "{" and depth_paren == 0:
                        break
                    j += 1
                if j < 0 or j >= len(code):
                    continue
                depth, k = 0, j
                while k < len(code):
                    if code[k] == "{":
                        depth += 1
                    elif code[k] == "}":
                        depth -= 1
                        if depth == 0:
                            break
                    k += 1
                lines = code.count("\n", m.start(), k) + 1
                if lines > MAX_FN_LINES:
                    found.append(f"{file}:{line + 1}: fn {m.group(1)} has {lines} lines (at most {MAX_FN_LINES} outside tests)")
    return found


def main():
    findings = []
    for crate in CRATE_DIRS:
        findings += cycles(crate)
    for root in ["crates", "bench/rust"]:
        findings += long_functions(root)
    for f in findings:
        print(f)
    if findings:
        sys.exit(1)
    print("no import cycles; no function over %d lines outside tests" % MAX_FN_LINES)


if __name__ == "__main__":
    main()
