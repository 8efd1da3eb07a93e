"""A long module of the toolkit says at its top why it is one module (issue 37's rule): over
LONG_MODULE lines, its docstring begins with "(About N lines: ...)"."""

from __future__ import annotations

from test_import_rules import LESSON_PACKAGES, ROOT, project_modules

# Over this many lines, a module of the toolkit says at its top why it is one module.
LONG_MODULE = 550


def test_a_long_toolkit_module_says_why_at_its_top():
    """No file of the toolkit above about 500 lines without a reason written at its top, as
    "(About N lines: ...)" in its docstring."""
    unexplained = []
    for name, path in project_modules(ROOT).items():
        if name.split(".")[0] in LESSON_PACKAGES:
            continue  # the lessons have their own, stricter rule (test_lessons.py)
        text = path.read_text()
        if text.count("\n") > LONG_MODULE and "(About " not in text[:1500]:
            unexplained.append(f"{path.relative_to(ROOT)}: {text.count(chr(10))} lines")
    assert not unexplained, "long modules without a reason at their top:\n" + "\n".join(unexplained)
