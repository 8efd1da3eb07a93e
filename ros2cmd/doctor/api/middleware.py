"""The middleware: QoS compatibility of every publisher and subscriber pair, and the RMW."""

from __future__ import annotations

import re

from ros2cmd.doctor.api import Report, Result, doctor_error, doctor_warn
from ros2cmd.doctor.api.system import Doctor


def qos_compatibility_check(run: Doctor) -> Result:
    from rclpy.qos import QoSCompatibility, qos_check_compatible

    result = Result()
    for topic, (_types, publishers, subscribers) in sorted(run.system.topics.items()):
        for pub in publishers:
            for sub in subscribers:
                compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
                reason = re.sub(r"^(?i:warning|error): ", "", reason)
                if compatibility == QoSCompatibility.WARNING:
                    doctor_warn(f"QoS compatibility warning found on topic '{topic}': {reason}")
                    result.warning += 1
                elif compatibility == QoSCompatibility.ERROR:
                    doctor_error(f"QoS compatibility error found on topic '{topic}': {reason}")
                    result.error += 1
    return result


def qos_compatibility_report(run: Doctor) -> Report:
    from rclpy.qos import QoSCompatibility, qos_check_compatible

    report = Report("QOS COMPATIBILITY LIST")
    if run.not_looked_at(report):
        return report
    for topic, (_types, publishers, subscribers) in sorted(run.system.topics.items()):
        for pub in publishers:
            for sub in subscribers:
                compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
                report.add("topic [type]", f"{topic} [{pub.topic_type}]")
                report.add("publisher node", pub.node_name)
                report.add("subscriber node", sub.node_name)
                status = "OK" if compatibility == QoSCompatibility.OK else reason
                report.add("compatibility status", status)
    if not report.items:
        report.add("compatibility status", "No publisher/subscriber pairs found")
    return report


def rmw_report(run: Doctor) -> Report:
    from rclpy.utilities import get_rmw_implementation_identifier

    report = Report("RMW MIDDLEWARE")
    report.add("middleware name", get_rmw_implementation_identifier())
    return report
