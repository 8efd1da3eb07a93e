"""The DDS domain: the settings (domain id, discovery range, static peers), and the other
participants in this ROS_DOMAIN_ID with a free domain id to use instead."""

from __future__ import annotations

from ros2cmd.doctor.api import Report, Result, doctor_error, doctor_warn
from ros2cmd.doctor.api.settings import PORTABLE_DOMAIN_IDS, RANGES
from ros2cmd.doctor.api.system import Doctor
from ros_tutorials_common.dds import peer_name_ok


def domain_check(run: Doctor) -> Result:
    result = Result()
    settings = run.settings
    problem = settings.domain_problem()
    if problem:
        doctor_error(f"{problem}; the running system was not checked")
        result.error += 1
    if settings.range_text and settings.range_text not in RANGES:
        doctor_warn(
            f"ROS_AUTOMATIC_DISCOVERY_RANGE={settings.range_text} is not one of "
            f"{', '.join(RANGES)}: rcl takes it as LOCALHOST"
        )
        result.warning += 1
    if settings.localhost_only is not None:
        doctor_warn(
            f"ROS_LOCALHOST_ONLY={settings.localhost_only} is deprecated: use "
            "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (or SUBNET) and ROS_STATIC_PEERS"
        )
        result.warning += 1
    peers = [p.strip() for p in (settings.static_peers or "").split(";") if p.strip()]
    for peer in peers:
        if not peer_name_ok(peer):
            doctor_warn(f"ROS_STATIC_PEERS: {peer!r} is not an IP address or a host name")
            result.warning += 1
    if settings.discovery_range == "OFF" and not peers:
        doctor_warn(
            "ROS_AUTOMATIC_DISCOVERY_RANGE=OFF and no ROS_STATIC_PEERS: "
            "no other process can be discovered"
        )
        result.warning += 1
    return result


def participant_check(run: Doctor) -> Result:
    result = Result()
    others = run.others()
    if not others:
        return result
    run.fill_addresses()
    free = run.free_domain
    advice = (
        f"ROS_DOMAIN_ID {free} has none: `export ROS_DOMAIN_ID={free}` in each of your "
        "terminals to work apart"
        if free is not None
        else "no free domain id was found to suggest"
    )
    doctor_warn(
        f"{len(others)} other participant(s) in ROS_DOMAIN_ID {run.domain_id} "
        f"that are not your processes here: "
        f"{'; '.join(p.describe() for p in others)}. {advice}"
    )
    result.warning += 1
    return result


def participant_report(run: Doctor) -> Report:
    report = Report("DOMAIN PARTICIPANTS")
    settings = run.settings
    report.add("domain id", _domain_id_text(run))
    report.add("discovery range", settings.describe_range())
    report.add("static peers", settings.static_peers or "none")
    if settings.localhost_only is not None:
        report.add("ROS_LOCALHOST_ONLY", f"{settings.localhost_only} (deprecated)")
    if run.not_looked_at(report):
        return report
    run.fill_addresses()
    for participant in run.system.participants or []:
        report.add("participant", participant.describe())
    if not run.system.participants:
        report.add("participant", "none but this one")
    free = run.free_domain
    report.add("free domain id", free if free is not None else "none found")
    return report


def _domain_id_text(run: Doctor) -> str:
    if run.domain_id is None:
        return "invalid"
    if run.domain_id > PORTABLE_DOMAIN_IDS:  # allowed, so not a check's warning
        return (
            f"{run.domain_id} (above {PORTABLE_DOMAIN_IDS}: its ports may meet the ports "
            f"the operating system hands out; 0 to {PORTABLE_DOMAIN_IDS} are safe)"
        )
    return str(run.domain_id)
