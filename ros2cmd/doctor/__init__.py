"""`ros2 doctor` (also `ros2 wtf`): checks of this environment and of the running system.

As ros2doctor (ROS 2 Jazzy) and the tutorial "Using ros2doctor to identify issues" print it:
each check prints what it finds as `<file>: <line>: UserWarning: <message>` on stderr (an
error: `UserWarning: ERROR: <message>`, and the check fails), then `All <n> checks passed` or
`<n>/<m> check(s) failed` and `Failed modules: ...`; `--report` prints the sections
(`   NETWORK CONFIGURATION`, ... `   TOPIC LIST`) as `key  : value` lines.

What ros2doctor learns from rosdistro on the internet (the distribution's status, its
package versions) comes here from this environment: the pinned ROS 2 Jazzy wheels. Checks
ros2doctor does not have, for a learner on PyPI's ROS 2 and for a classroom: the Python and
the virtual environment, the project's packages in this environment's ament index, the DDS
settings (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS, ROS_LOCALHOST_ONLY),
nodes of one name (ros2doctor's Rolling NodeCheck), who else is in this ROS_DOMAIN_ID and a
free one to use instead, and (only with the SUBNET range) whether multicast works.

This module is the command: which checks and reports run, in ros2doctor's order; each family
of them is a module of api/, as ros2doctor's are.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import TYPE_CHECKING

from ros2cmd.sub_verbs import VERB_HELP
from ros_tutorials_common.cli import JazzyRawDescriptionHelpFormatter

if TYPE_CHECKING:  # the checks load with the command, not to build the parser
    from ros2cmd.doctor.api import Report, Result
    from ros2cmd.doctor.api.system import Doctor

# The checks that look at the running system (skipped when no node can be started).
GRAPH_CHECKS = ("node_check", "participant_check", "qos_compatibility_check", "topic_check")

HELP = """\
Checks this environment and the running system, and says what may stop ROS 2 from working:
the Python and virtual environment of the ROS 2 Jazzy wheels, this project's packages in the
ament index, the DDS settings (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ROS_STATIC_PEERS,
ROS_LOCALHOST_ONLY), the network interfaces,
and in the running system: nodes that share a name, topics with a publisher and no
subscriber or the reverse, incompatible QoS, and the DDS participants of other users or
machines in this ROS_DOMAIN_ID (then it suggests a free domain id, one where nothing is heard:
on this machine from its open ports, at once; on the network by listening 3 s).
It sends nothing beyond this machine unless ROS_AUTOMATIC_DISCOVERY_RANGE=SUBNET: only then
does it send one datagram to DDS's multicast group 239.255.0.1 (port 7399) to see it come
back, and listen to the DDS announcements on the network. It takes a few seconds."""


def checks(run: Doctor, exclude_packages: bool) -> list[tuple[str, Callable[[Doctor], Result]]]:
    """(category, check) in ros2doctor's order (its entry points' names, sorted); those that
    cannot run here left out."""
    from ros2cmd.doctor.api import domain, middleware, network, node, package, platform, topic

    found = [
        ("domain", domain.domain_check),
        ("network", network.multicast_check if run.settings.subnet else None),
        ("network", network.network_check),
        ("node", node.node_check),
        ("package", None if exclude_packages else package.package_check),
        ("domain", domain.participant_check),
        ("platform", platform.platform_check),
        ("middleware", middleware.qos_compatibility_check),
        ("topic", topic.topic_check),
    ]
    return [(category, check) for category, check in found if check is not None]


def run_checks(
    run: Doctor, include_warnings: bool, exclude_packages: bool
) -> tuple[list[str], int, int]:
    from ros2cmd.doctor.api import doctor_error

    failed: list[str] = []
    fail = total = 0
    # The graph first: every check then reads the same complete look at it.
    system = run.system
    for category, check in checks(run, exclude_packages):
        if system is None and check.__name__ in GRAPH_CHECKS:
            continue  # nothing to look at; the check that stopped it has said why
        result = check(run)
        if result.error or (include_warnings and result.warning):
            fail += 1
            if category not in failed:
                failed.append(category)
        total += 1
    if run.blocked and not run.settings.domain_problem():
        doctor_error(f"{run.blocked}; the running system was not checked")
        fail += 1
        failed.append("domain")
    return failed, fail, total


def reports(run: Doctor, categories: list[str] | None, exclude_packages: bool) -> list[Report]:
    """The reports of the categories (None: all), in ros2doctor's order."""
    from ros2cmd.doctor.api import domain, middleware, network, node, package, platform, topic

    makers = [
        ("network", network.network_report),
        ("node", node.node_report),
        ("package", None if exclude_packages else package.package_report),
        ("domain", domain.participant_report),
        ("platform", platform.platform_report),
        ("middleware", middleware.qos_compatibility_report),
        ("middleware", middleware.rmw_report),
        ("platform", platform.rosdistro_report),
        ("topic", topic.topic_report),
    ]
    return [
        make(run)
        for category, make in makers
        if make is not None and (categories is None or category in categories)
    ]


def doctor(args: argparse.Namespace) -> None:
    from ros2cmd.doctor.api import format_print
    from ros2cmd.doctor.api.settings import Settings
    from ros2cmd.doctor.api.system import Doctor

    run = Doctor(Settings.from_environment())
    try:
        if args.report:
            for report in reports(run, None, args.exclude_packages):
                format_print(report)
            return
        failed, fail, total = run_checks(run, args.include_warnings, args.exclude_packages)
        if fail:
            print(f"\n{fail}/{total} check(s) failed\n")
            print("Failed modules:", *failed)
        else:
            print(f"\nAll {total} checks passed\n")
        if args.report_failed and fail:
            for report in reports(run, failed, args.exclude_packages):
                format_print(report)
    finally:
        run.close()


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    """`ros2 doctor` and its alias `ros2 wtf`."""
    for name in ("doctor", "wtf"):
        parser = verbs.add_parser(
            name,
            help=VERB_HELP[name],
            description=HELP,
            formatter_class=JazzyRawDescriptionHelpFormatter,
        )
        group = parser.add_mutually_exclusive_group()
        group.add_argument("--report", "-r", action="store_true", help="Print all reports.")
        group.add_argument(
            "--report-failed",
            "-rf",
            action="store_true",
            help="Print reports of failed checks only.",
        )
        parser.add_argument(
            "--exclude-packages",
            "-ep",
            action="store_true",
            help="Exclude package checks or report.",
        )
        parser.add_argument(
            "--include-warnings",
            "-iw",
            action="store_true",
            help="Include warnings as failed checks. Warnings are ignored by default.",
        )
        parser.set_defaults(offline=True, run=lambda _graph, a: doctor(a))
