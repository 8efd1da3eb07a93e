"""The documentation stays true: README.md and docs/ are read as a code host renders them.

Every relative link and image resolves (a file that exists, a heading anchor that the target
page has, a line range within the file), every `path:lines` reference to a file of this
repository is within that file, every page of docs/ can be reached from the index, and the
README fits on a screen or two. No process is started: the whole file takes well under a
second.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
INDEX = DOCS / "README.md"
README_MAX_LINES = 200

PAGES = sorted([ROOT / "README.md", *DOCS.rglob("*.md")])
FENCE = re.compile(r"^ *```.*?^ *```", re.M | re.S)
INLINE_CODE = re.compile(r"`[^`\n]*`")
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
LINE_ANCHOR = re.compile(r"^L(\d+)(?:-L(\d+))?$")
# `ros_tutorials_topic/publisher.py:19-37`: a file of this repository and a line range.
PATH_LINES = re.compile(r"([\w.-]+(?:/[\w.-]+)+):(\d+)(?:-(\d+))?\b")


def prose(text: str) -> str:
    """The text a reader follows links in: no fenced blocks, no inline code."""
    return INLINE_CODE.sub("", FENCE.sub("", text))


def slug(heading: str) -> str:
    """A heading's anchor as GitHub makes it: lower case, punctuation dropped, spaces to -."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link in a heading: its text
    return re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")


def anchors(page: Path) -> set[str]:
    found: set[str] = set()
    seen: dict[str, int] = {}
    for match in re.finditer(r"^#{1,6} +(.+?) *#*$", FENCE.sub("", page.read_text()), re.M):
        base = slug(match.group(1))
        count = seen.get(base, 0)
        seen[base] = count + 1
        found.add(base if count == 0 else f"{base}-{count}")
    return found


def line_count(path: Path) -> int:
    return len(path.read_text().splitlines())


def links(page: Path) -> list[str]:
    return [
        href
        for href in LINK.findall(prose(page.read_text()))
        if not re.match(r"[a-z][a-z0-9+.-]*:", href)  # http:, https:, mailto:
    ]


def test_there_are_pages_and_they_have_links():
    assert INDEX in PAGES and len(PAGES) > 10
    assert all(links(page) for page in PAGES if page.name == "README.md")


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(ROOT)))
def test_every_relative_link_and_image_resolves(page):
    problems = []
    for href in links(page):
        path_part, _, anchor = href.partition("#")
        target = (page.parent / path_part).resolve() if path_part else page
        if not target.exists():
            problems.append(f"{href}: no such file")
            continue
        if not anchor:
            continue
        if target.suffix == ".md":
            if anchor not in anchors(target):
                problems.append(f"{href}: {target.name} has no heading with anchor #{anchor}")
        elif match := LINE_ANCHOR.match(anchor):
            first, last = int(match.group(1)), int(match.group(2) or match.group(1))
            if not 1 <= first <= last <= line_count(target):
                problems.append(f"{href}: lines {first}-{last} of {line_count(target)}")
        else:
            problems.append(f"{href}: an anchor of a file that is not a page or a line range")
    assert not problems, f"{page.relative_to(ROOT)}:\n" + "\n".join(problems)


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(ROOT)))
def test_every_path_lines_reference_is_within_its_file(page):
    problems = []
    for match in PATH_LINES.finditer(page.read_text()):
        path = ROOT / match.group(1)
        if not path.is_file() or path.suffix == ".md":
            continue  # not a file of this repository (a URL's path, a log folder ...)
        first = int(match.group(2))
        last = int(match.group(3) or first)
        if not 1 <= first <= last <= line_count(path):
            problems.append(f"{match.group(0)}: {path.name} has {line_count(path)} lines")
    assert not problems, f"{page.relative_to(ROOT)}:\n" + "\n".join(problems)


def test_the_lesson_pages_point_at_lesson_lines():
    """Each lesson page names the lines of its lesson file to read."""
    for name, lesson in [
        ("topics.md", "ros_tutorials_topic/"),
        ("services.md", "ros_tutorials_service/"),
        ("parameters.md", "ros_tutorials_parameter/"),
        ("actions.md", "ros_tutorials_action/"),
        ("launch.md", "ros_tutorials_topic/launch/"),
    ]:
        references = [m.group(1) for m in PATH_LINES.finditer((DOCS / name).read_text())]
        assert any(path.startswith(lesson) for path in references), name


def test_every_page_is_reachable_from_the_index():
    reached, todo = {INDEX}, [INDEX]
    while todo:
        page = todo.pop()
        for href in links(page):
            target = (page.parent / href.partition("#")[0]).resolve()
            if (
                target.suffix == ".md"
                and target.is_file()
                and target.is_relative_to(DOCS)
                and target not in reached
            ):
                reached.add(target)
                todo.append(target)
    missing = sorted(str(p.relative_to(ROOT)) for p in set(DOCS.rglob("*.md")) - reached)
    assert not missing, f"not reachable from docs/README.md: {missing}"


def test_the_readme_fits_and_points_to_the_course():
    readme = (ROOT / "README.md").read_text()
    count = len(readme.splitlines())
    assert count <= README_MAX_LINES, f"README.md has {count} lines, at most {README_MAX_LINES}"
    assert "(docs/README.md)" in readme
    assert "make run" in readme and "make test" in readme


def test_the_readme_names_the_pythons_the_whole_suite_passed_on():
    """The README's Prerequisites name as the Python to use exactly those whose whole suite
    passed, as the table in docs/dev/testing.md ("Pythons") records each run."""
    table = (DOCS / "dev" / "testing.md").read_text().split("\n## Pythons\n", 1)[1]
    rows = re.findall(r"^\| 3\..*$", table, re.M)
    results = [re.match(r"\| (3\.\d+)\.\d+ \| (passed|not passed|not run) \|", row) for row in rows]
    assert rows and all(results), f"a Python row without passed, not passed or not run: {rows}"
    passed = {found[1] for found in results if found[2] == "passed"}
    readme = (ROOT / "README.md").read_text()
    line = re.search(r"^- Linux x86_64 with Python (.+?) \(`python3`", readme, re.M)
    assert line, "the README's Prerequisites no longer say which Python"
    named = set(re.findall(r"3\.\d+", line[1]))
    assert named == passed, (
        f"README names {sorted(named)}; the whole suite passed on {sorted(passed)}"
    )
