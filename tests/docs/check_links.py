#!/usr/bin/env python3
"""Every relative link of the project's Markdown resolves.

Checks README.md, every page under docs/ and every README.md under src/, python/, tests/,
examples/ and benchmarks/: each link [text](target) that is not a web address must name a
file or folder that exists, relative to the page, and a #anchor must name a heading of the
page it points to (as GitHub turns a heading into an anchor). Links inside code (fenced
blocks and `spans`) are text, not links. Prints each broken link as FILE:LINE: TARGET (why)
and exits with 1 when there is one.

    python3 tests/docs/check_links.py [SOURCE_DIR]
"""

import re
import sys
from pathlib import Path

LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"`[^`]*`")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$")
EXTERNAL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")  # http:, https:, mailto:, ...


def pages(root):
    """The Markdown pages to check, sorted."""
    found = {root / "README.md"} if (root / "README.md").exists() else set()
    found.update((root / "docs").rglob("*.md"))
    for folder in ("src", "python", "tests", "examples", "benchmarks", "scripts"):
        found.update((root / folder).rglob("README.md"))
    return sorted(p for p in found if "build" not in p.relative_to(root).parts[:1])


def prose_lines(text):
    """(line number, line) of the lines outside fenced code, code spans blanked."""
    in_fence = False
    for number, line in enumerate(text.splitlines(), start=1):
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        if not in_fence:
            yield number, CODE_SPAN.sub("", line)


def slug(heading):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`|\*\*|__", "", heading.strip().lower())
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link in a heading keeps its text
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page, cache={}):
    """The anchors of a page's headings (GitHub numbers repeats: name, name-1, ...)."""
    if page not in cache:
        seen = {}
        result = set()
        for _, line in prose_lines(page.read_text(encoding="utf-8")):
            match = HEADING.match(line)
            if not match:
                continue
            base = slug(match.group(1))
            count = seen.get(base, 0)
            seen[base] = count + 1
            result.add(base if count == 0 else f"{base}-{count}")
        cache[page] = result
    return cache[page]


def broken_links(page):
    """(line, target, why) for each link of the page that does not resolve."""
    for number, line in prose_lines(page.read_text(encoding="utf-8")):
        for match in LINK.finditer(line):
            target = match.group(1)
            if EXTERNAL.match(target):
                continue
            path_part, _, anchor = target.partition("#")
            destination = (page.parent / path_part).resolve() if path_part else page
            if not destination.exists():
                yield number, target, "no such file"
            elif anchor and destination.suffix == ".md" and anchor not in anchors(destination):
                yield number, target, f"no heading with anchor #{anchor}"


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]).resolve()
    checked = pages(root)
    failures = 0
    for page in checked:
        for number, target, why in broken_links(page):
            print(f"{page.relative_to(root)}:{number}: {target} ({why})")
            failures += 1
    print(f"{len(checked)} pages checked, {failures} broken link(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
