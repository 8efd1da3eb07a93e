"""The network: ros2doctor's NetworkCheck and its report (the interfaces), and whether
multicast comes back (only with the SUBNET range: otherwise nothing leaves this machine)."""

from __future__ import annotations

from ros2cmd import netcheck
from ros2cmd.doctor.api import Report, Result, doctor_error, doctor_warn
from ros2cmd.doctor.api.system import Doctor


def multicast_check(run: Doctor) -> Result:
    result = Result()
    ok, detail = run.multicast
    if not ok:
        doctor_error(
            f"multicast did not come back to this machine ({detail}): with "
            "ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET, DDS finds other machines by multicast; "
            "without it list them in ROS_STATIC_PEERS"
        )
        result.error += 1
    return result


def network_check(run: Doctor) -> Result:
    """ros2doctor's NetworkCheck: a loopback, a non-loopback and a multicast interface."""
    result = Result()
    found = [i for i in run.interfaces if i.flags >= 0]
    if not any(i.loopback for i in found):
        doctor_error("No loopback IP address is found.")
        result.error += 1
    if not any(not i.loopback for i in found):
        doctor_warn("Only loopback IP address is found.")
        result.warning += 1
    if not any(i.multicast for i in found):
        doctor_warn("No multicast IP address is found.")
        result.warning += 1
    return result


def network_report(run: Doctor) -> Report:
    report = Report("NETWORK CONFIGURATION")
    for interface in run.interfaces:
        for key, value in interface.report_items():
            report.add(key, value)
    if run.multicast is None:
        report.add(
            "multicast",
            f"not tried: ROS_AUTOMATIC_DISCOVERY_RANGE={run.settings.discovery_range} "
            "keeps DDS traffic on this machine",
        )
    else:
        ok, detail = run.multicast
        group = f"{netcheck.DDS_MULTICAST_GROUP}:{netcheck.MULTICAST_TEST_PORT}"
        report.add("multicast", f"{group} came back in {detail}" if ok else detail)
    return report
