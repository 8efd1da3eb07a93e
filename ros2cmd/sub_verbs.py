"""How a verb registers its sub-verbs, as ros2cli's verb extensions do: each module of the
verb's `verb/` package has HELP (its line in the verb's help), add_arguments(parser) and
main(graph, args), the command `cli.execute` runs."""

from __future__ import annotations

import argparse
from types import ModuleType

from ros_tutorials_common.cli import JazzyRawDescriptionHelpFormatter

# Each verb's line in `ros2 -h`, ros2cli's words: the verbs register their parsers with it, and
# `ros2 -h` prints it without loading any verb's module (cli.help_parser).
VERB_HELP = {
    "action": "Various action related sub-commands",
    "bag": "bags: record, info, play (rosbag2, MCAP storage)",
    "daemon": "Various daemon related sub-commands",
    "doctor": "Check ROS setup and other potential issues",
    "interface": "Show information about ROS interfaces",
    "launch": "Run a launch file",
    "node": "Various node related sub-commands",
    "param": "Various param related sub-commands",
    "pkg": "Various package related sub-commands",
    "run": "Run a package specific executable",
    "service": "Various service related sub-commands",
    "topic": "Various topic related sub-commands",
    "wtf": "Use `wtf` as alias to `doctor`",
}


def add_count_option(parser: argparse.ArgumentParser, things: str) -> None:
    """ros2cli's -c of the lists (`--count-topics`, `--count-services`)."""
    parser.add_argument(
        "-c",
        f"--count-{things}",
        action="store_true",
        help=f"Only display the number of {things} discovered",
    )


def add_sub_verbs(
    sub: argparse._SubParsersAction,
    sub_verbs: dict[str, ModuleType],
    *,
    offline: bool = False,
    listed_in_description: bool = False,
    parents: list[argparse.ArgumentParser] | None = None,
) -> None:
    """A parser for each sub-verb, in the order given. With listed_in_description the verb's
    help lists the sub-verbs itself (`ros2 topic -h`), and HELP is each one's description."""
    for name, module in sub_verbs.items():
        if listed_in_description:
            texts = {
                "description": module.HELP,
                "formatter_class": JazzyRawDescriptionHelpFormatter,
            }
        else:
            texts = {"help": module.HELP}
        parser = sub.add_parser(name, parents=parents or [], **texts)
        parser.set_defaults(run=module.main, offline=offline)
        module.add_arguments(parser)
