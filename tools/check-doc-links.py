#!/usr/bin/env python3
"""Checks that every relative link and image in README.md and docs/*.md resolves.

A link's file must exist (relative to the page that holds it), and a #fragment must name a
heading of the target page, spelled as GitHub spells heading anchors. Web links (http, https,
mailto) are not fetched. Code spans and fenced code blocks are skipped.

usage: tools/check-doc-links.py [REPOSITORY_ROOT]   (default: the folder above this script)
Prints one line per broken link (page:line: target: why) and exits 1 if there is any.
"""
import pathlib
import re
import sys
import urllib.parse

INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\"[^\"]*\")?\s*$")
HTML = re.compile(r"<(?:img|a)\b[^>]*\b(?:src|href)=\"([^\"]+)\"", re.IGNORECASE)
CODE_SPAN = re.compile(r"(`+).*?\1")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")


def slug(heading):
    """GitHub's anchor for a heading: lower case, markup and punctuation dropped, spaces to '-'."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = text.replace("`", "").lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def page_lines(path):
    """The page's lines outside fenced code blocks, as (line number, text)."""
    fence = None
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        stripped = line.lstrip()
        if fence:
            if stripped.startswith(fence):
                fence = None
            continue
        if stripped.startswith("```") or stripped.startswith("~~~"):
            fence = stripped[:3]
            continue
        yield number, line


def anchors(path, cache={}):
    if path not in cache:
        seen, found = {}, set()
        for _, line in page_lines(path):
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            found.add(base if count == 0 else f"{base}-{count}")
        for m in re.finditer(r"<a\s+(?:name|id)=\"([^\"]+)\"", path.read_text(encoding="utf-8")):
            found.add(m.group(1))
        cache[path] = found
    return cache[path]


def targets(line):
    text = CODE_SPAN.sub("", line)
    for pattern in (INLINE, HTML):
        for m in pattern.finditer(text):
            yield m.group(1)
    m = REFERENCE.match(text)
    if m:
        yield m.group(1)


def check(root, page):
    problems = []
    for number, line in page_lines(page):
        for target in targets(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):
                continue  # http:, https:, mailto: …: not checked
            where = f"{page.relative_to(root)}:{number}: {target}"
            path_part, _, fragment = target.partition("#")
            path_part = urllib.parse.unquote(path_part)
            if path_part.startswith("/"):
                problems.append(f"{where}: an absolute path; link relative to the page")
                continue
            resolved = (page.parent / path_part).resolve() if path_part else page
            if not resolved.exists():
                problems.append(f"{where}: no such file ({resolved.relative_to(root) if resolved.is_relative_to(root) else resolved})")
                continue
            if not resolved.is_relative_to(root):
                problems.append(f"{where}: outside the repository")
                continue
            if fragment and resolved.suffix == ".md" and urllib.parse.unquote(fragment) not in anchors(resolved):
                problems.append(f"{where}: no heading with the anchor #{fragment} in {resolved.relative_to(root)}")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent).resolve()
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    problems, links = [], 0
    for page in pages:
        if not page.exists():
            problems.append(f"{page.relative_to(root)}: missing")
            continue
        links += sum(1 for _, line in page_lines(page) for _ in targets(line))
        problems += check(root, page)
    for p in problems:
        print(p)
    print(f"check-doc-links: {len(pages)} pages, {links} links and images, {len(problems)} broken")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
