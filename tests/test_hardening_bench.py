"""`make bench`: one failing step must not lose the other figures (no timing is asserted)."""

from __future__ import annotations

import sys

import benchmarks.__main__ as bench
from benchmarks.common import Row


def test_a_failing_benchmark_step_keeps_the_other_figures(monkeypatch, capsys):
    def good() -> list[Row]:
        return [Row("a figure that was measured", "42 us")]

    def broken() -> list[Row]:
        raise RuntimeError("make test failed with exit 2")

    monkeypatch.setattr(bench, "GROUPS", {"one": [good, broken], "two": [good]})
    monkeypatch.setattr(sys, "argv", ["benchmarks"])
    assert bench.main() == 1
    out = capsys.readouterr().out
    table = out[out.index("| what") :]
    assert table.count("a figure that was measured") == 2  # both groups' good steps
    assert "one: broken FAILED" in table and "make test failed with exit 2" in table
    assert "1 step(s) failed: one.broken" in out
