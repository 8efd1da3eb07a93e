"""The topics: a publisher without a subscriber or the reverse, and the topic list."""

from __future__ import annotations

from ros2cmd.doctor.api import Report, Result, doctor_warn
from ros2cmd.doctor.api.system import Doctor

SKIP_TOPICS = ("/parameter_events", "/rosout")  # ros2doctor's topic check leaves them out


def topic_check(run: Doctor) -> Result:
    result = Result()
    for topic, (_types, publishers, subscribers) in sorted(run.system.topics.items()):
        if topic in SKIP_TOPICS:
            continue
        if publishers and not subscribers:
            doctor_warn(f"Publisher without subscriber detected on {topic}.")
            result.warning += 1
        elif subscribers and not publishers:
            doctor_warn(f"Subscriber without publisher detected on {topic}.")
            result.warning += 1
    return result


def topic_report(run: Doctor) -> Report:
    report = Report("TOPIC LIST")
    if run.not_looked_at(report):
        return report
    topics = {n: t for n, t in sorted(run.system.topics.items()) if n not in SKIP_TOPICS}
    if not topics:
        report.add("topic", "none")
        report.add("publisher count", 0)
        report.add("subscriber count", 0)
    for name, (_types, publishers, subscribers) in topics.items():
        report.add("topic", name)
        report.add("publisher count", len(publishers))
        report.add("subscriber count", len(subscribers))
    return report
