"""The `ros2` console script: `ros2 launch ...` goes to the launcher before anything loads rclpy.

The launcher does not use rclpy, and a launch must not load it: a process that loaded rclpy
(and Fast DDS with it) without using it can crash in Fast DDS's exit code after a Ctrl-C
(docs/dev/limits.md). Every other verb is ros2cmd.cli's. TAB completion (the shell running
`ros2` with argcomplete's `_ARGCOMPLETE`) is answered first, from the launcher's parser after
`ros2 launch`, else from ros2's, and runs nothing.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from ros_tutorials_common import completion
from ros_tutorials_common.shutdown import program_main


@program_main  # while rclpy loads, too
def main(argv: Sequence[str] | None = None) -> int:
    if completion.requested():  # the shell asking for TAB's completions: ends here
        _complete()
    words = list(sys.argv[1:] if argv is None else argv)
    if words[:1] == ["launch"]:
        from launcher.__main__ import main as launch

        return launch(words[1:], program="ros2 launch", standalone=argv is None)
    from ros2cmd.cli import main as cli_main

    return cli_main(words)


def _complete() -> None:
    """Answer a completion of the line in COMP_LINE (argcomplete's protocol), from the
    launcher's parser after `ros2 launch`, else from ros2's (past a verb, the verb's own)."""
    completion.arm()  # the budget covers building the parser too
    words = completion.line_words()  # `ros2 launch ` and more: the launcher's own words
    if words[1:2] == ["launch"] and len(words) > 2:
        from launcher.__main__ import build_parser as launch_parser

        completion.answer(launch_parser("ros2 launch"), skip=1)
    from ros2cmd.cli import VERB_MODULES, build_parser, help_parser

    # Past the verb, that verb's parser alone (its modules only); at the verb, the verbs'
    # names (what `ros2 -h` lists, no verb's module loaded).
    if len(words) > 2 and words[1] in VERB_MODULES:
        completion.answer(build_parser(words[1]))
    completion.answer(help_parser())
