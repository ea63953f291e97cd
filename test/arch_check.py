#!/usr/bin/env python3
"""arch_check.py - the architecture's rules, checked over a source tree.

  arch_check.py [ROOT]     (default: the repository this file is in)

1. Include arrows. The rules are read from ROOT/docs/ARCHITECTURE.md, the
   fenced block that follows the line "<!-- include rules -->": one line per
   folder (or file), `FOLDER: ALLOWED...`. A file obeys the rule of the
   longest folder that holds it. Every `#include "..."` is resolved as the
   compiler resolves it (the including file's folder, then the -I roots
   below) to a path in the tree; it must lie in one of the allowed folders
   or files. `#include <...>` is allowed by class: `<c>` the C99 standard
   headers, `<posix>` any other system header that is not one of the
   libraries below, `<lib:NAME>` one library (ode, gl, glfw, lcm, simavr,
   jansson, inih, png, avr, arduino, micromouse:
   hal/arduino as an installed Arduino library): each library enters through the
   folders that name it.
2. Function lengths: no function in the folders named on the rules block's
   `max-function-lines N: FOLDER...` line is longer than N lines (from the
   line with its name to its closing brace).

Prints one line per violation, `FILE:LINE: what`, and exits 1 if there was
any, 0 otherwise (2: the rules themselves are unreadable).
"""
import os
import re
import sys

# -I roots of the Makefile's INC, in its order; generated LCM headers
# (build/lcmgen/mmlcm_*.h) stand for the types in lcm/.
INC_ROOTS = ["firmware", "hal", "hal/sim", "hal/wire", "sim", "tools"]
SOURCES = (".c", ".h", ".cpp", ".ino")
CHECKED = ["firmware", "hal", "sim", "tools"]

C99 = set("""assert.h complex.h ctype.h errno.h fenv.h float.h inttypes.h iso646.h
limits.h locale.h math.h setjmp.h signal.h stdarg.h stdbool.h stddef.h stdint.h
stdio.h stdlib.h string.h tgmath.h time.h wchar.h wctype.h""".split())
LIBS = {  # library: header prefixes (a prefix ending in / is a folder)
    "ode": ["ode/"], "gl": ["GL/"], "glfw": ["GLFW/"], "lcm": ["lcm/"],
    "simavr": ["simavr/"], "jansson": ["jansson.h"], "inih": ["ini.h"],
    "png": ["png.h"], "avr": ["avr/", "util/"], "arduino": ["Arduino.h"],
    "micromouse": ["Micromouse.h"],  # hal/arduino as a sketch sees it, installed
}


def lib_of(header):
    for lib, prefixes in LIBS.items():
        for p in prefixes:
            if header == p or (p.endswith("/") and header.startswith(p)):
                return lib
    return None


def read_rules(root):
    path = os.path.join(root, "docs", "ARCHITECTURE.md")
    try:
        text = open(path, encoding="utf-8").read()
    except OSError as e:
        sys.exit(print(f"arch_check: {path}: {e.strerror}") or 2)
    m = re.search(r"<!-- include rules -->\s*```[^\n]*\n(.*?)```", text, re.S)
    if not m:
        print(f"arch_check: {path}: no rules block after '<!-- include rules -->'")
        sys.exit(2)
    rules, maxlen, lenfolders = {}, None, []
    for line in m.group(1).splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        key, _, rest = line.partition(":")
        key, allowed = key.strip(), rest.split()
        if key.startswith("max-function-lines"):
            maxlen, lenfolders = int(key.split()[1]), allowed
        else:
            rules[key.rstrip("/")] = allowed
    return rules, maxlen, lenfolders


def inside(path, folder):
    return path == folder or path.startswith(folder.rstrip("/") + "/")


def rule_for(rules, path):
    best = None
    for key in rules:
        if inside(path, key) and (best is None or len(key) > len(best)):
            best = key
    return best


def resolve(root, rel, name):
    """The tree path of a quoted include, or None."""
    base = os.path.basename(name)
    if base.startswith("mmlcm_") and base.endswith(".h"):
        return "lcm/" + base[len("mmlcm_"):-2] + ".lcm"
    for d in [os.path.dirname(rel)] + INC_ROOTS:
        p = os.path.normpath(os.path.join(d, name))
        if os.path.isfile(os.path.join(root, p)):
            return p
    return None


def allowed_angle(header, allowed):
    lib = lib_of(header)
    if lib:
        return f"<lib:{lib}>" in allowed, f"library {lib}"
    if header in C99:
        return "<c>" in allowed or "<posix>" in allowed, "C standard header"
    return "<posix>" in allowed, "system header"


def strip_code(text):
    """Comments, strings and character literals blanked, newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else "")); i = j + 1
        else:
            out.append(c); i += 1
    return "".join(out)


def functions(text):
    """(name, first line, last line) of each function definition."""
    code = strip_code(text)
    code = re.sub(r"(?m)^[ \t]*#.*(\\\n.*)*$", lambda m: re.sub(r"[^\n]", " ", m.group(0)), code)
    found, depth, head_start, i = [], 0, 0, 0
    for m in re.finditer(r"[{};]", code):
        c, i = m.group(0), m.start()
        if depth == 0 and c == "{":
            head = code[head_start:i]
            sig = re.search(r"([A-Za-z_]\w*)\s*\([^;{}]*\)\s*$", head)
            if sig and "=" not in head:
                name = sig.group(1)
                line0 = code.count("\n", 0, head_start + sig.start(1)) + 1
                found.append([name, line0, None])
            else:
                found.append([None, 0, None])
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                if found and found[-1][2] is None:
                    found[-1][2] = code.count("\n", 0, i) + 1
                head_start = i + 1
        elif c == ";" and depth == 0:
            head_start = i + 1
    return [(n, a, b) for n, a, b in found if n and b]


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), ".."))
    rules, maxlen, lenfolders = read_rules(root)
    problems = []
    for top in CHECKED:
        for d, _, names in sorted(os.walk(os.path.join(root, top))):
            for fn in sorted(names):
                if not fn.endswith(SOURCES):
                    continue
                rel = os.path.relpath(os.path.join(d, fn), root)
                key = rule_for(rules, rel)
                text = open(os.path.join(root, rel), encoding="utf-8", errors="replace").read()
                for no, line in enumerate(text.splitlines(), 1):
                    m = re.match(r'\s*#\s*include\s*([<"])([^>"]+)[>"]', line)
                    if not m:
                        continue
                    if key is None:
                        problems.append(f"{rel}:{no}: no include rule covers this file")
                        break
                    allowed = rules[key]
                    if m.group(1) == "<":
                        ok, what = allowed_angle(m.group(2), allowed)
                        if not ok:
                            problems.append(f"{rel}:{no}: {key} may not include <{m.group(2)}> ({what})")
                        continue
                    target = resolve(root, rel, m.group(2))
                    if target is None:
                        problems.append(f'{rel}:{no}: "{m.group(2)}" not found in the tree')
                    elif not any(inside(target, a) for a in allowed if not a.startswith("<")):
                        problems.append(f"{rel}:{no}: {key} may not include {target}")
                if maxlen and any(inside(rel, f) for f in lenfolders) and fn.endswith((".c", ".cpp")):
                    for name, a, b in functions(text):
                        if b - a + 1 > maxlen:
                            problems.append(f"{rel}:{a}: function {name} is {b - a + 1} lines (at most {maxlen})")
    for p in problems:
        print(p)
    print(f"arch_check: {len(problems)} problem{'s' if len(problems) != 1 else ''}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
