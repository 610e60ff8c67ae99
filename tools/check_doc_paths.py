#!/usr/bin/env python3
"""Every repository file the README and docs/ cite exists: relative links, and paths (in
backticks or in prose) that start with one of the tree's top-level folders. Usage: check_doc_paths.py ROOT"""
import os
import re
import sys

TOP = ("include/", "integration/", "scenes/", "examples/", "tests/", "bench/", "fuzz/", "tools/", "docs/", "cmake/", ".ci/")


def cited(text):
    prose = re.sub(r"`[^`]*`", "", re.sub(r"```.*?```", "", text, flags=re.S))
    for link in re.findall(r"\]\(([^)#\s]+)", prose):
        if not re.match(r"[a-z]+:", link):
            yield link, True
    for path in re.findall(r"(?<![\w/.-])((?:include|integration|scenes|examples|tests|bench|fuzz|tools|cmake)/[\w./-]*\w)", prose):
        if "." in os.path.basename(path) or path.endswith("/"):
            yield path, False
    for code in re.findall(r"`([^`\s]+)`", text):
        path = code.split(":")[0].split("#")[0].rstrip(".,;")
        if path.startswith(TOP) and not re.search(r"[*<{]|NAME", path):
            yield path, False


def main():
    root = sys.argv[1]
    docs = ["README.md"] + [os.path.join(d, f) for d, _, fs in os.walk(os.path.join(root, "docs")) for f in fs if f.endswith(".md")]
    missing = []
    for doc in docs:
        doc_path = os.path.join(root, doc)
        with open(doc_path, encoding="utf-8") as f:
            text = f.read()
        for path, relative in cited(text):
            base = os.path.dirname(doc_path) if relative else root
            if not os.path.exists(os.path.join(base, path)):
                missing.append(f"{os.path.relpath(doc_path, root)}: {path}")
    for m in missing:
        print("missing:", m)
    print(f"{len(docs)} documents, {len(missing)} missing files")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
