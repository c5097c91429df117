#!/usr/bin/env python3
"""The repository's documents stand on their own: run from the source tree's root (or with it as
the argument), it fails, naming each file and line, on
- a Markdown link or image to a file that is not in the tree;
- a path into the workplace's shared folder, or the name of one of its texts outside docs/ (the
  patterns below): a clone has none of them, so the model is cited as docs/model.md;
- a seed text's number, an issue's number or "the issue": nothing a clone can look up;
- a README.md over 250 lines (its depth belongs in docs/);
- a section cited by title in a Markdown file of the tree that has no such heading: `docs/X.md "Title"`,
  `docs/X.md, "Title"`, `X.md "Title"` (a name relative to the citing file, as inside docs/) and
  `[text](X.md), "Title"` fail unless X.md has a heading (any level), or a bold lead opening a
  paragraph or list item, whose text starts with Title. A title wrapped across comment lines is
  joined first (the lines' comment markers dropped, the whitespace collapsed); a citation whose file
  is not in the tree is left to the link rule.
It reads the files git tracks, plus new ones not ignored, so build outputs are left out; outside a
git checkout, every file but those under build*/ and dot-folders.
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
README_MAX_LINES = 250
# [text](target) and ![alt](target), the target up to a space or the closing parenthesis.
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
# The patterns are assembled from parts so that this file does not itself name what it forbids.
SHARED_FOLDER = re.escape("..") + "/" + "shared/"
FORBIDDEN = [
    (re.compile(SHARED_FOLDER), "a path into the workplace's shared folder, which a clone does not have"),
    (re.compile(r"seed 00[0-4]", re.IGNORECASE), "a seed text's number, which a clone cannot look up"),
    (re.compile(r"\bissue #?[0-9]+", re.IGNORECASE), "an issue's number, which a clone cannot look up"),
    (re.compile(r"\b(the|this) issue\b", re.IGNORECASE), "an issue a clone cannot read: name the bound or setting"),
]
OUTSIDE_TEXTS = re.compile(r"\b(" + "|".join(["PHY" + "SICS", "LAVA" + "PIPE", "STY" + "LE"]) + r")\.md\b")
# This file holds the patterns.
SELF = Path(__file__).resolve()
# A Markdown file's name (a path of word characters, dots, dashes and slashes), the closing of a link
# or code span around it, an optional comma and an optional opening parenthesis, then a quoted title.
# Run over a file's lines joined by single spaces, so that a title wrapped across lines is one string.
SECTION_CITATION = re.compile(r"(?<![\w./-])((?:\.\./|[\w-]+/)*[\w.-]+\.md)(?:#[\w-]*)?`?\)?`?,? \(?\"([^\"]+)\"")
# What a line of a comment or a Markdown quote starts with, dropped before the lines are joined.
LEADING_MARKERS = re.compile(r"^\s*(?://+|#+|\*+|/\*+|>)?\s*")


def tracked_files():
    try:
        out = subprocess.run(["git", "-C", str(ROOT), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                             check=True, capture_output=True).stdout
        return [ROOT / name for name in out.decode().split("\0") if name]
    except (OSError, subprocess.CalledProcessError):
        return [p for p in ROOT.rglob("*")
                if not any(part.startswith(("build", ".")) for part in p.relative_to(ROOT).parts)]


def normalized(title):
    """A title or heading as compared: without code spans' backticks, its whitespace collapsed."""
    return " ".join(title.replace("`", "").split())


def headings(path, cache={}):
    """The text of each Markdown heading of path (outside fenced code), normalized, and of each bold lead
    that opens a paragraph or a list item (`**Cost model**`, `- **The ocean's slab.**`), which the
    documents use as sections within a section and cite as such."""
    if path not in cache:
        found, in_code = [], False
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.lstrip().startswith("```"):
                in_code = not in_code
            elif not in_code and re.match(r"^#{1,6}\s", line):
                found.append(normalized(line.lstrip("#")))
            elif not in_code and (lead := re.match(r"^\s*(?:[-*]\s+)?\*\*(.+?)\*\*", line)):
                found.append(normalized(lead.group(1)))
        cache[path] = found
    return cache[path]


def section_citations(path, relative, lines):
    """Each citation of a section of a Markdown file of the tree by a title that starts no heading there."""
    parts, line_starts, length = [], [], 0
    for line in lines:
        part = " ".join(LEADING_MARKERS.sub("", line, count=1).split())
        line_starts.append(length)
        if part:
            parts.append(part)
            length += len(part) + 1
    text = " ".join(parts)
    problems = []
    for match in SECTION_CITATION.finditer(text):
        name, title = match.group(1), normalized(match.group(2))
        cited = next((c for c in (path.parent / name, ROOT / name) if c.is_file()), None)
        if cited is None or not title:
            continue  # not a file of the tree: the link rule speaks for Markdown links
        if any(heading.startswith(title) for heading in headings(cited.resolve())):
            continue
        number = max(i for i, start in enumerate(line_starts) if start <= match.start()) + 1
        problems.append(f'{relative}:{number}: cites {name} "{title}", which starts no heading of that file')
    return problems


def main():
    problems = []
    for path in tracked_files():
        if not path.is_file() or path.resolve() == SELF:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue  # images, EXR files
        relative = path.relative_to(ROOT)
        lines = text.splitlines()
        for number, line in enumerate(lines, 1):
            for pattern, why in FORBIDDEN:
                if pattern.search(line):
                    problems.append(f"{relative}:{number}: {why}: {line.strip()[:120]}")
            if relative.parts[0] != "docs" and OUTSIDE_TEXTS.search(line):
                problems.append(f"{relative}:{number}: names a workplace text outside docs/ (cite docs/model.md): "
                                f"{line.strip()[:120]}")
        problems.extend(section_citations(path, relative, lines))
        if path.suffix.lower() != ".md":
            continue
        if relative.as_posix() == "README.md" and len(lines) > README_MAX_LINES:
            problems.append(f"README.md: {len(lines)} lines (at most {README_MAX_LINES}; depth goes to docs/)")
        in_code = False
        for number, line in enumerate(lines, 1):
            if line.lstrip().startswith("```"):
                in_code = not in_code
                continue
            if in_code:
                continue
            for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
                if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE) or target.startswith("#"):
                    continue  # a URL, mailto: or an anchor in the same file
                file_part = target.split("#", 1)[0]
                if not (path.parent / file_part).exists():
                    problems.append(f"{relative}:{number}: links to '{target}', which is not in the tree")
    for problem in problems:
        print(problem)
    print(f"check_docs: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
