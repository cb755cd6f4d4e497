#!/usr/bin/env python3
"""Every relative link and #anchor in README.md and doc/*.md resolves.

Usage: check_links.py <source dir>. Prints each broken link as
"<file>: missing <link>" and exits 1 if there is one, 0 otherwise.
Anchors follow GitHub's rule: the heading in lower case, punctuation
other than '-' and '_' dropped, spaces as '-', '-1', '-2', ... for repeats.
"""
import os
import re
import sys


def anchors(path):
    found, seen, inside = set(), {}, False
    for line in open(path, encoding="utf-8"):
        if line.startswith("```"):
            inside = not inside
            continue
        heading = None if inside else re.match(r"^#{1,6}\s+(.*)", line)
        if heading:
            name = re.sub(r"[^\w\- ]", "", heading.group(1).strip().lower())
            name = name.replace(" ", "-")
            repeat = seen.get(name, 0)
            seen[name] = repeat + 1
            found.add(name if repeat == 0 else f"{name}-{repeat}")
    return found


def broken_links(root, name):
    text = open(os.path.join(root, name), encoding="utf-8").read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    for match in re.finditer(r"!?\[[^\]]*\]\(([^)\s]+)\)", text):
        link = match.group(1)
        if re.match(r"^[a-z]+:", link):
            continue
        path, _, fragment = link.partition("#")
        target = (os.path.normpath(os.path.join(root, os.path.dirname(name), path))
                  if path else os.path.join(root, name))
        if not os.path.exists(target):
            yield link
        elif fragment and target.endswith(".md") and fragment not in anchors(target):
            yield link


def main(root):
    names = ["README.md"] + sorted(
        "doc/" + f for f in os.listdir(os.path.join(root, "doc")) if f.endswith(".md"))
    bad = [(n, link) for n in names for link in broken_links(root, n)]
    for name, link in bad:
        print(f"{name}: missing {link}")
    print(f"{len(names)} files, {len(bad)} broken links")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
