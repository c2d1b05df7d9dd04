#!/usr/bin/env python3
"""The docs stand alone: every link and file citation in them resolves inside the repository.

Checks, in the Markdown files tracked by git (README.md, docs/*.md, fuzz/README.md, ...):

* every Markdown link and image, inline `[text](target)`, a reference definition
  `[id]: target` or an HTML `<a href>` / `<img src>`, whose target is not a URL: the file exists and is tracked by git (so it ships;
  a folder counts when it holds tracked files), it lies inside the repository, and its `#anchor`
  is the GitHub slug of one of the target's headings (or an explicit `<a id="...">`);
* every `name.md` or `folder/name.md#anchor` written in the text (prose or inline code,
  outside fenced blocks): it names a tracked Markdown file, relative to the citing file, to the
  repository root or to docs/, and the anchor exists; `name.md, "Section"` names a heading of
  it (the heading contains the quoted words);
* no citation of pages that live outside the repository: `../shared/...`, `/work/...`, or the
  private reference pages by name (see OUTSIDE_PAGES).

and, in every other tracked text file (sources, CMakeLists.txt, Makefile, scripts), every
`docs/<file>.md` or `docs/<file>.md#anchor` mention (comments pointing at the docs).

Usage: check_links.py SOURCE_DIR. Prints FILE:LINE: problem for each broken link, exits 1 if any.
Python 3 standard library only.
"""
import os
import re
import subprocess
import sys
import unicodedata

# Pages the project was first written against that are not in the repository; the facts the
# docs need from them are written out in docs/ (performance.md, conventions.md, verification.md).
OUTSIDE_PAGES = ["numerical-robustness", "performance-anchors", "teaching-anchors", "pov-ray-and-blender",
                 "radiometry-blender"]
OUTSIDE_PATTERNS = [
    (re.compile(r"(?:\.\./)+shared/|/work/|(?<![\w-])shared/reference"), "cites a file outside the repository"),
    (re.compile(r"(?<![\w-])(" + "|".join(map(re.escape, OUTSIDE_PAGES)) + r")(?![\w-])"),
     "cites a page that is not in the repository"),
]

FENCE = re.compile(r"^\s{0,3}(`{3,}|~{3,})")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"<a\s+(?:[^>]*\s)?(?:id|name)=\"([^\"]+)\"", re.IGNORECASE)
INLINE_LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_LINK = re.compile(r"<(?:a|img)\s[^>]*?(?:href|src)=\"([^\"]+)\"", re.IGNORECASE)
REFERENCE_DEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)")
MD_MENTION = re.compile(r"(?<![\w/.\-])((?:\.\./|\./|[\w.\-]+/)*[\w.\-]+\.md)(#[\w\-]+)?(?![\w/])")
QUOTED_SECTION = re.compile(r"(?<![\w/.\-])((?:[\w.\-]+/)*[\w.\-]+\.md),? \"([^\"]+)\"")
DOCS_MENTION = re.compile(r"(?<![\w/.\-])(docs/[\w.\-]+\.md)(#[\w\-]+)?")
URL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.\-]*:")


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True, capture_output=True).stdout
    return sorted(set(p for p in out.decode().split("\0") if p and os.path.exists(os.path.join(root, p))))


def slug(text, seen):
    """GitHub's heading anchor: inline markup dropped, lower case, punctuation other than '-'
    and '_' removed, each space a '-'; a repeated heading gets -1, -2, ..."""
    text = re.sub(r"!\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"<[^>]+>", "", text)
    text = text.replace("`", "").replace("*", "").replace("~~", "")
    text = re.sub(r"(?<!\w)_+|_+(?!\w)", "", text)
    text = text.strip().lower()
    kept = []
    for ch in text:
        category = unicodedata.category(ch)
        if ch in "-_ " or category[0] in "LN" or category == "Mn":
            kept.append("-" if ch == " " else ch)
    base = "".join(kept)
    anchor = base
    n = seen.get(base, 0)
    if n:
        anchor = f"{base}-{n}"
    seen[base] = n + 1
    return anchor


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if m:
            marker = m.group(1)
            if fence is None:
                fence = marker[0] * len(marker)
            elif marker.startswith(fence):
                fence = None
            continue
        if fence is None:
            yield number, line


def heading_texts(path, cache):
    """The headings of a Markdown file as plain lower-case text."""
    if path not in cache:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        cache[path] = [re.sub(r"[`*]", "", m.group(2)).lower() for _, line in prose_lines(text)
                       for m in [HEADING.match(line)] if m]
    return cache[path]


def anchors_of(path, cache):
    if path not in cache:
        seen = {}
        found = set()
        with open(path, encoding="utf-8") as f:
            text = f.read()
        lines = list(prose_lines(text))
        for i, (_, line) in enumerate(lines):
            m = HEADING.match(line)
            if m:
                found.add(slug(m.group(2), seen))
            elif i + 1 < len(lines) and line.strip() and re.match(r"^\s{0,3}(=+|-+)\s*$", lines[i + 1][1]) \
                    and lines[i + 1][0] == lines[i][0] + 1 and not line.lstrip().startswith(("|", "*", "-", "#")):
                found.add(slug(line, seen))  # setext heading
            found.update(HTML_ANCHOR.findall(line))
        cache[path] = found
    return cache[path]


class Checker:
    def __init__(self, root):
        self.root = os.path.realpath(root)
        self.files = tracked_files(self.root)
        self.tracked = set(self.files)
        self.dirs = set()
        for p in self.files:
            d = os.path.dirname(p)
            while d:
                self.dirs.add(d)
                d = os.path.dirname(d)
        self.anchor_cache = {}
        self.heading_cache = {}
        self.problems = []

    def problem(self, rel, number, message):
        self.problems.append(f"{rel}:{number}: {message}")

    def resolve(self, rel_dir, target):
        """Repository-relative path of target from rel_dir, or None when it leaves the repository."""
        joined = os.path.normpath(os.path.join(self.root, rel_dir, target))
        if joined != self.root and not joined.startswith(self.root + os.sep):
            return None
        return os.path.relpath(joined, self.root)

    def check_anchor(self, rel, number, target_rel, anchor, shown):
        if not anchor:
            return
        if not target_rel.endswith(".md"):
            self.problem(rel, number, f"{shown}: an anchor into a file that is not Markdown")
            return
        if anchor not in anchors_of(os.path.join(self.root, target_rel), self.anchor_cache):
            self.problem(rel, number, f"{shown}: no heading of {target_rel} has the anchor #{anchor}")

    def check_link(self, rel, number, target):
        if not target or URL.match(target):
            return
        path, _, anchor = target.partition("#")
        if not path:
            self.check_anchor(rel, number, rel, anchor, target)
            return
        target_rel = self.resolve(os.path.dirname(rel), path)
        if target_rel is None:
            self.problem(rel, number, f"{target}: links outside the repository")
        elif target_rel not in self.tracked and target_rel.rstrip("/") not in self.dirs:
            what = "is not tracked by git" if os.path.exists(os.path.join(self.root, target_rel)) else "does not exist"
            self.problem(rel, number, f"{target}: {target_rel} {what}")
        else:
            self.check_anchor(rel, number, target_rel, anchor, target)

    def check_mention(self, rel, number, path, anchor, bases):
        """A file named in the text: first of bases (folders) where it is a tracked file."""
        for base in bases:
            target_rel = self.resolve(base, path)
            if target_rel is not None and target_rel in self.tracked:
                self.check_anchor(rel, number, target_rel, anchor, path + ("#" + anchor if anchor else ""))
                return
        self.problem(rel, number, f"{path}: names no Markdown file of the repository")

    def check_section(self, rel, number, path, section, bases):
        """`file.md, "Section"`: a heading of that file contains the quoted words."""
        for base in bases:
            target_rel = self.resolve(base, path)
            if target_rel is not None and target_rel in self.tracked:
                if not any(section.lower() in h for h in heading_texts(os.path.join(self.root, target_rel), self.heading_cache)):
                    self.problem(rel, number, f'{path}, "{section}": no heading of {target_rel} says "{section}"')
                return

    def check_outside(self, rel, number, line):
        for pattern, message in OUTSIDE_PATTERNS:
            m = pattern.search(line)
            if m:
                self.problem(rel, number, f"'{m.group(0)}' {message}; write the fact in docs/ and cite a paper or an official page")

    def check_markdown(self, rel):
        with open(os.path.join(self.root, rel), encoding="utf-8") as f:
            text = f.read()
        bases = [os.path.dirname(rel), "", "docs"]
        for number, line in prose_lines(text):
            for m in list(INLINE_LINK.finditer(line)) + list(HTML_LINK.finditer(line)):
                self.check_link(rel, number, m.group(1))
            m = REFERENCE_DEF.match(line)
            if m:
                self.check_link(rel, number, m.group(1))
            without_links = INLINE_LINK.sub("", line)
            without_urls = re.sub(r"[a-zA-Z][a-zA-Z0-9+.\-]*://\S+", "", without_links)
            for m in MD_MENTION.finditer(without_urls):
                self.check_mention(rel, number, m.group(1), (m.group(2) or "#")[1:], bases)
            for m in QUOTED_SECTION.finditer(without_urls):
                self.check_section(rel, number, m.group(1), m.group(2), bases)
            self.check_outside(rel, number, without_urls)

    def check_source(self, rel):
        try:
            with open(os.path.join(self.root, rel), encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, IsADirectoryError):
            return
        for number, line in enumerate(text.splitlines(), 1):
            for m in DOCS_MENTION.finditer(line):
                self.check_mention(rel, number, m.group(1), (m.group(2) or "#")[1:], [""])
            self.check_outside(rel, number, line)

    def run(self):
        for rel in self.files:
            if rel.endswith(".md"):
                self.check_markdown(rel)
            elif not rel.startswith(("fuzz/corpus/", "tests/data/")) and rel != "tests/docs/check_links.py":
                self.check_source(rel)
        return self.problems


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    checker = Checker(sys.argv[1])
    problems = checker.run()
    for p in problems:
        print(p)
    markdown = sum(1 for f in checker.files if f.endswith(".md"))
    print(f"{len(problems)} broken links in {markdown} Markdown files and {len(checker.files) - markdown} other files")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
