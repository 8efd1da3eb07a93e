"""The nodes: names that two nodes share (ros2doctor's Rolling NodeCheck), and the node list."""

from __future__ import annotations

from collections import Counter

from ros2cmd.doctor.api import Report, Result, doctor_warn
from ros2cmd.doctor.api.system import Doctor


def node_check(run: Doctor) -> Result:
    result = Result()
    for name, count in sorted(Counter(run.system.nodes).items()):
        if count > 1:
            doctor_warn(f"Duplicate node name: {name}")
            result.warning += 1
    return result


def node_report(run: Doctor) -> Report:
    report = Report("NODE LIST")
    if run.not_looked_at(report):
        return report
    nodes = run.system.nodes
    report.add("node count", len(nodes))
    for name in nodes or ["none"]:
        report.add("node", name)
    return report
