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
   jansson, inih, png, avr, arduino, unicorn, dw, micromouse:
   hal/arduino as an installed Arduino library): each library enters through the
   folders that name it.
2. Function lengths: no function in the folders named on the rules block's
   `max-function-lines N: FOLDER...` line is longer than N lines (from the
   line with its name to its closing brace).
3. No circles: no two units in the folders on the `no-call-circles:
   FOLDER...` line call each other (a unit is a source and its own header:
   sim/world/robot.c and robot.h). A call is a name followed by "(" in a
   function's or a macro's body (comments and strings ignored, not after
   . -> ::); it goes to the unit that defines that function, not static
   (a header's static inline counts). The functions declared in a header on
   the `call-contracts: HEADER...` line belong to no unit: hal/hal.h is
   called both ways by design (the firmware calls the backend's hal_*, the
   backend calls the firmware's fw_*). Taking a function's address (a
   table of callbacks) is not a call.

Prints one line per violation, `FILE:LINE: what`, and exits 1 if there was
any, 0 otherwise (2: the rules themselves are unreadable).
"""
import os
import re
import sys

# -I roots of the Makefile's INC, in its order; generated LCM headers
# (build/lcmgen/mmlcm_*.h) stand for the types in lcm/, the generated
# robot_profile.h (build/gen/NAME/) for firmware/'s own.
INC_ROOTS = ["firmware", "hal", "hal/sim", "hal/wire", "sim", "tools"]
SOURCES = (".c", ".h", ".cpp", ".ino")
# Files of ours that belong to a client's build tree, not ours: their includes
# resolve inside that tree (tools/opencm3-compat: libopencm3's, README there).
FOREIGN = ("tools/opencm3-compat/",)
CHECKED = ["firmware", "hal", "sim", "tools"]

C99 = set("""assert.h complex.h ctype.h errno.h fenv.h float.h inttypes.h iso646.h
limits.h locale.h math.h setjmp.h signal.h stdarg.h stdbool.h stddef.h stdint.h
stdio.h stdlib.h string.h tgmath.h time.h wchar.h wctype.h""".split())
LIBS = {  # library: header prefixes (a prefix ending in / is a folder)
    "ode": ["ode/"], "gl": ["GL/"], "glfw": ["GLFW/"], "lcm": ["lcm/"],
    "simavr": ["simavr/"], "jansson": ["jansson.h"], "inih": ["ini.h"],
    "png": ["png.h"], "avr": ["avr/", "util/"], "arduino": ["Arduino.h"],
    "micromouse": ["Micromouse.h"],  # hal/arduino as a sketch sees it, installed
    "unicorn": ["unicorn/"],  # the Cortex-M core (sim/arm)
    "dw": ["dwarf.h", "elfutils/", "libelf.h", "gelf.h"],  # elfutils: DWARF types (sim/io/elfvar_dwarf.c)
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
    rules, maxlen, lenfolders, circlefolders, contracts = {}, None, [], [], []
    for line in m.group(1).splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        key, _, rest = line.partition(":")
        key, allowed = key.strip(), rest.split()
        if key.startswith("max-function-lines"):
            try:
                maxlen, lenfolders = int(key.split()[1]), allowed
            except (IndexError, ValueError):
                print(f"arch_check: {path}: '{line}': want 'max-function-lines N: FOLDER...'")
                sys.exit(2)
        elif key == "no-call-circles":
            circlefolders = allowed
        elif key == "call-contracts":
            contracts = allowed
        else:
            rules[key.rstrip("/")] = allowed
    return rules, maxlen, lenfolders, circlefolders, contracts


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
    if name == "robot_profile.h":  # generated from a robot file's [firmware] (build/gen/NAME/): the firmware's own
        return "firmware/robot_profile.h"
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


DIRECTIVE = re.compile(r"(?m)^[ \t]*#(?:.*\\\n)*.*")  # a preprocessor line and its continuations
KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "do", "else", "case"}


def blank(m):
    return re.sub(r"[^\n]", " ", m.group(0))


def definitions(text, code=None):
    """(name, first line, last line, static, body start, body end) of each
    function definition (a C++ method, Class::name, is not one)."""
    code = DIRECTIVE.sub(blank, code if code is not None else strip_code(text))
    found, depth, head_start, i = [], 0, 0, 0
    for m in re.finditer(r"[{};]", code):
        c, i = m.group(0), m.start()
        if depth == 0 and c == "{":
            head = code[head_start:i]
            sig = re.search(r"([A-Za-z_]\w*)\s*\([^;{}]*\)\s*$", head)
            if sig and "=" not in head and sig.group(1) not in KEYWORDS:
                name = sig.group(1)
                if head[:sig.start(1)].rstrip().endswith("::"):
                    name = None
                line0 = code.count("\n", 0, head_start + sig.start(1)) + 1
                static = re.search(r"\bstatic\b", head[:sig.start(1)]) is not None
                found.append([name, line0, None, static, i, None])
            else:
                found.append([None, 0, None, False, i, None])
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                if found and found[-1][2] is None:
                    found[-1][2] = code.count("\n", 0, i) + 1
                    found[-1][5] = i
                head_start = i + 1
        elif c == ";" and depth == 0:
            head_start = i + 1
    return [tuple(f) for f in found if f[0] and f[2]]


def functions(text):
    """(name, first line, last line) of each function definition."""
    return [f[:3] for f in definitions(text)]


def declared(text):
    """Names of the functions a header declares (prototypes at file scope)."""
    code = DIRECTIVE.sub(blank, strip_code(text))
    return set(re.findall(r"\b([A-Za-z_]\w*)\s*\([^;{}()]*(?:\([^;{}()]*\)[^;{}()]*)*\)\s*;", code))


def calls(text):
    """(name, line) of each call in a source: a name followed by "(" in a
    function's body or in a macro's body, not a member (after ., -> or ::)."""
    code = strip_code(text)
    spans = [(f[4], f[5]) for f in definitions(text, code)]
    spans += [(m.start(), m.end()) for m in DIRECTIVE.finditer(code)
              if not re.match(r"\s*#\s*include\b", m.group(0))]
    out = []
    for m in re.finditer(r"(?<![\w.])(?<!->)(?<!::)([A-Za-z_]\w*)\s*\(", code):
        pos = m.start(1)
        if m.group(1) not in KEYWORDS and any(a <= pos < b for a, b in spans):
            out.append((m.group(1), code.count("\n", 0, pos) + 1))
    return out


def circles(root, files, contracts):
    """One line per pair of units (a source and its own header) in folders
    that call each other. A call of a function resolves to the unit whose
    source defines it (not static; a header's static inline counts too);
    a function declared in a contract header (hal/hal.h: the firmware calls
    the backend, the backend calls the firmware) is the contract's, so a
    call of it is no call between files."""
    unit = lambda rel: os.path.splitext(rel)[0]
    contract = set()
    for h in contracts:
        try:
            contract |= declared(open(os.path.join(root, h), encoding="utf-8", errors="replace").read())
        except OSError as e:
            print(f"arch_check: {h}: {e.strerror}")
            sys.exit(2)
    defs, local, texts = {}, {}, {}
    for rel in files:
        texts[rel] = text = open(os.path.join(root, rel), encoding="utf-8", errors="replace").read()
        for name, _, _, static, _, _ in definitions(text):
            local.setdefault(unit(rel), set()).add(name)
            if (not static or rel.endswith(".h")) and name not in contract:
                defs.setdefault(name, {})[unit(rel)] = rel
    edges = {}  # (caller unit, callee unit): first (file, line, name)
    for rel in files:
        u = unit(rel)
        for name, line in calls(texts[rel]):
            if name in local.get(u, ()):
                continue
            for v, vrel in defs.get(name, {}).items():
                if v != u and ((u, v) not in edges or (rel, line) < edges[(u, v)][:2]):
                    edges[(u, v)] = (rel, line, name, vrel)
    out = []
    for (u, v), (rel, line, name, vrel) in sorted(edges.items()):
        if u < v and (v, u) in edges:
            rel2, line2, name2, vrel2 = edges[(v, u)]
            out.append(f"{rel}:{line}: calls {name} ({vrel}) and {rel2}:{line2} calls {name2}"
                       f" ({vrel2}): the two files call each other")
    return out


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                           os.path.join(os.path.dirname(__file__), "..", ".."))
    rules, maxlen, lenfolders, circlefolders, contracts = read_rules(root)
    problems, sources = [], []
    for top in CHECKED:
        for d, _, names in sorted(os.walk(os.path.join(root, top))):
            for fn in sorted(names):
                if not fn.endswith(SOURCES):
                    continue
                rel = os.path.relpath(os.path.join(d, fn), root)
                if rel.startswith(FOREIGN):
                    continue
                sources.append(rel)
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
                if maxlen and any(inside(rel, f) for f in lenfolders) and not fn.endswith(".h"):
                    for name, a, b in functions(text):
                        if b - a + 1 > maxlen:
                            problems.append(f"{rel}:{a}: function {name} is {b - a + 1} lines (at most {maxlen})")
    problems += circles(root, [r for r in sources if any(inside(r, f) for f in circlefolders)],
                        contracts)
    for p in problems:
        print(p)
    print(f"arch_check: {len(problems)} problem{'s' if len(problems) != 1 else ''}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
