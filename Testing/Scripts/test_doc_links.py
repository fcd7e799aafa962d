"""Every relative link of the README and of docs/ resolves: the file (or folder)
it names exists in the repository, and a #fragment names a heading of that
Markdown file (GitHub's anchors: lower case, punctuation dropped, spaces as
hyphens). Links to the web are not followed. So does every repository path
the prose quotes in backticks (`docs/GUIDE.md`, `Plugin/Passes/...cxx`): a
file moved or renamed leaves no stale name behind. Prints each broken link
and exits 1 if there is any.

  python3 Testing/Scripts/test_doc_links.py REPOSITORY
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
# [text](target) and ![alt](target); a target ends at whitespace or ")".
LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
# A quoted path into one of the repository's own folders, ending in a file's
# extension; build outputs, globs and placeholders are not quoted paths.
QUOTED_PATH = re.compile(
    r"`((?:CMake|Examples|Measurement|ParaView|Plugin|Shaders|Testing|docs|scripts|\.ci)"
    r"/[\w./+-]*\.(?:md|py|cxx|h|glsl|cmake|sh|txt|xml|png|json|in))`")


def markdown_files():
    yield os.path.join(ROOT, "README.md")
    for folder, _, names in os.walk(os.path.join(ROOT, "docs")):
        for name in sorted(names):
            if name.endswith(".md"):
                yield os.path.join(folder, name)


def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside = False
    with open(path, encoding="utf-8") as text:
        for number, line in enumerate(text, 1):
            if FENCE.match(line):
                inside = not inside
            elif not inside:
                yield number, line


def anchor_of(heading):
    text = re.sub(r"`|\*|_(?=\w)|(?<=\w)_", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path):
    found = set()
    counts = {}
    for _, line in prose_lines(path):
        match = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if match:
            anchor = anchor_of(match.group(1))
            count = counts.get(anchor, 0)
            found.add(anchor if count == 0 else f"{anchor}-{count}")
            counts[anchor] = count + 1
    return found


def broken_links(path):
    for number, line in prose_lines(path):
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            file_part, _, fragment = target.partition("#")
            resolved = path if not file_part else os.path.normpath(
                os.path.join(os.path.dirname(path), file_part))
            where = f"{os.path.relpath(path, ROOT)}:{number}: {target}"
            if not os.path.exists(resolved):
                yield f"{where}: no such file"
            elif fragment and resolved.endswith(".md") and fragment not in anchors(resolved):
                yield f"{where}: no heading with that anchor"
        for quoted in QUOTED_PATH.findall(line):
            if not os.path.exists(os.path.join(ROOT, quoted)):
                yield f"{os.path.relpath(path, ROOT)}:{number}: `{quoted}`: no such file"


def main():
    broken = [problem for path in markdown_files() for problem in broken_links(path)]
    checked = sum(1 for _ in markdown_files())
    for problem in broken:
        print(problem)
    print(f"{checked} files, {len(broken)} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
