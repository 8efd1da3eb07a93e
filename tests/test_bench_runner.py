"""`make bench`: one failing step must not lose the other figures (no timing is asserted)."""

from __future__ import annotations

import os
import sys

import benchmarks.__main__ as bench
from benchmarks import common
from benchmarks.common import Row


def test_a_failing_benchmark_step_keeps_the_other_figures(monkeypatch, capsys):
    def good() -> list[Row]:
        return [Row("a figure that was measured", "42 us")]

    def broken() -> list[Row]:
        raise RuntimeError("make test failed with exit 2")

    monkeypatch.setattr(bench, "GROUPS", {"one": [good, broken], "two": [good]})
    monkeypatch.setattr(sys, "argv", ["benchmarks"])
    # The benchmarks claim a domain of their own and set it in os.environ: give this test
    # session's back afterwards (the later tests of this process and their commands use it).
    monkeypatch.setitem(os.environ, "ROS_DOMAIN_ID", os.environ["ROS_DOMAIN_ID"])
    monkeypatch.setattr(common, "_domain_lock", None)
    assert bench.main() == 1
    out = capsys.readouterr().out
    table = out[out.index("| what") :]
    assert table.count("a figure that was measured") == 2  # both groups' good steps
    assert "one: broken FAILED" in table and "make test failed with exit 2" in table
    assert "1 step(s) failed: one.broken" in out
