#!/usr/bin/env python3
"""No call takes two random draws as arguments: the order in which a call's arguments are
evaluated is unspecified, so f(u(rng), u(rng)) gives other numbers with another compiler.
Braced lists ({u(rng), u(rng)}) are evaluated in order and pass. Checks the C++ sources and
the C++ blocks of the Markdown pages. Usage: check_draw_order.py ROOT"""
import os
import re
import sys

# A draw: a distribution applied to an engine, an engine's method, or a test's draw helper.
DRAW = re.compile(r"\b\w+\((?:rng|gen|engine)\)|\brng\.\w+\(\)|\b(?:Uniform|uniform|unit|asymmetry|Random\w*)\(\)")
SKIP = ("build", ".git", "out")


def arguments(text, start):
    """The top-level arguments of the call whose '(' is at text[start - 1]."""
    depth, args, current, i = 1, [], [], start
    while i < len(text) and depth > 0:
        c = text[i]
        depth += c in "([{"
        depth -= c in ")]}"
        if depth == 1 and c == ",":
            args.append("".join(current))
            current = []
        elif depth > 0:
            current.append(c)
        i += 1
    return args + ["".join(current)]


def unsequenced(text):
    for call in re.finditer(r"\b(?!if\b|for\b|while\b|switch\b|return\b)\w+(?:<[^<>;]*>)?\s*\(", text):
        args = arguments(text, call.end())
        if sum(bool(DRAW.search(a)) for a in args) >= 2:
            yield text.count("\n", 0, call.start()) + 1, text[call.start():call.start() + 80].replace("\n", " ")


def main():
    root = sys.argv[1]
    found = 0
    for d, dirs, files in os.walk(root):
        dirs[:] = [x for x in dirs if not x.startswith(SKIP)]
        for f in files:
            path = os.path.join(d, f)
            if not f.endswith((".cpp", ".hpp", ".md")):
                continue
            with open(path, encoding="utf-8", errors="replace") as fh:
                text = fh.read()
            if f.endswith(".md"):  # only the C++ blocks, blanked elsewhere so line numbers hold
                text = re.sub(r"(?s)(^|```)(?!cpp\n).*?(?=```cpp\n|\Z)", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
            for line, code in unsequenced(text):
                print(f"{os.path.relpath(path, root)}:{line}: two draws as arguments of one call: {code}")
                found += 1
    print(f"{found} calls with unsequenced draws")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
