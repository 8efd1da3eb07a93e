"""The launcher's command line: python -m launcher [PKG] FILE [name:=value ...] [options]."""

from __future__ import annotations

import argparse
import shlex
import sys
from pathlib import Path

from launch_foundation.declarations import ArgInfo
from launch_foundation.errors import CodeRefused, LaunchError
from launch_foundation.naming import valid_name
from launcher import guardian
from launcher.loading import describe_args, resolve
from launcher.plan import DEFAULT_SIGKILL_TIMEOUT, DEFAULT_SIGTERM_TIMEOUT, format_plan, make_plan
from launcher.python_files import LaunchFileRaised
from launcher.scope import Options
from ros_tutorials_common import completion, packages
from ros_tutorials_common.cli import positive_seconds
from ros_tutorials_common.dds import environment_problem
from ros_tutorials_common.shutdown import program_main

EXAMPLES = """\
examples:
  python -m launcher union.launch                     the topic lesson, two namespaces
  python -m launcher ros_tutorials_topic union.launch like roslaunch PKG FILE
  python -m launcher union.launch --print             show the processes, start nothing
  python -m launcher FILE name:=value                 set a launch argument

exit code: 0 all ended cleanly, 1 a process failed or the launch could not start,
130 after Ctrl-C (143 after SIGTERM)."""


def build_parser(prog: str | None = None) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog=prog or program(),
        description="Run a launch file: ROS 1 (roslaunch) XML, or ROS 2 XML, YAML or Python.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "words",
        nargs="*",
        metavar="[PKG] FILE [name:=value ...]",
        help="a launch file (a path, or a file name in a package's launch/ folder) and arguments",
    )
    completion.attach(parser, words=completion.launch_words)
    parser.add_argument("--screen", action="store_true", help="show every process's stdout too")
    parser.add_argument(
        "-p", "--print", action="store_true", help="print the processes it would start, and exit"
    )
    parser.add_argument(
        "-s", "--show-args", action="store_true", help="list the file's arguments, and exit"
    )
    parser.add_argument(
        "-d",
        "--debug",
        action="store_true",
        help="show tracebacks of errors and each command line as it starts",
    )
    parser.add_argument(
        "--allow-code",
        action="store_true",
        help="allow $(eval) and $(command) in XML and YAML files (they run code written in the "
        "file); a Python launch file is code and always runs",
    )
    parser.add_argument(
        "--sigterm-timeout",
        type=positive_seconds,
        default=DEFAULT_SIGTERM_TIMEOUT,
        metavar="S",
        help="seconds from SIGINT to SIGTERM when stopping (default %(default)s)",
    )
    parser.add_argument(
        "--sigkill-timeout",
        type=positive_seconds,
        default=DEFAULT_SIGKILL_TIMEOUT,
        metavar="S",
        help="seconds from SIGTERM to SIGKILL when stopping (default %(default)s)",
    )
    return parser


def program() -> str:
    """The launcher's name as the user typed it: roslaunch, ros2 launch, or python -m launcher."""
    name = Path(sys.argv[0]).name
    return {"roslaunch": "roslaunch", "ros2": "ros2 launch"}.get(name, "python -m launcher")


_program_name = program  # main's argument of that name hides it


def _shipped() -> dict[str, list[Path]]:
    """Each tutorial package's launch files."""
    return {package: packages.launch_files(package) for package in packages.package_dirs()}


def find_launch_file(names: list[str]) -> Path:
    """FILE, or PKG FILE, as a path; a bare name is looked up in the packages' launch/ folders."""
    if len(names) == 2:
        package, name = names
        found = packages.launch_packages(package)  # a seed's name too: my_package
        if not found:
            raise LaunchError(packages.unknown_package_line(package))
        # Anywhere in share/PKG, as `ros2 launch PKG NAME` finds it; once, or say where.
        paths = [path for pkg in found for path in packages.share_files(pkg, name)]
        if len(paths) == 1:
            return paths[0]
        if paths:
            where = ", ".join(f"'{path}'" for path in paths)
            raise LaunchError(
                f"file {name!r} was found more than once in the share directory of package "
                f"{package!r}: [{where}]"
            )
        have = ", ".join(file.name for pkg in found for file in packages.launch_files(pkg))
        message = f"{package} has no launch file {name!r}"
        elsewhere = [pkg for pkg, files in _shipped().items() if name in (f.name for f in files)]
        if elsewhere:  # seed 000 puts union.launch in the service package
            runs = "; ".join(f"{program()} {pkg} {name}" for pkg in elsewhere)
            raise LaunchError(f"{message}; {name} is in {', '.join(elsewhere)}: {runs}")
        raise LaunchError(f"{message}; it has: {have or 'none'}")
    if len(names) != 1:
        raise LaunchError(f"expected [PKG] FILE, got: {' '.join(names) or 'nothing'}")
    path = Path(names[0])
    if path.is_file() or "/" in names[0]:
        if not path.is_file():
            raise LaunchError(f"no launch file {path}")
        return path
    shipped = _shipped()
    package = packages.resolve_package(names[0])
    if package and not any(file.name == names[0] for files in shipped.values() for file in files):
        have = ", ".join(f.name for pkg in package for f in packages.launch_files(pkg)) or "none"
        raise LaunchError(
            f"{names[0]} is a package; name one of its launch files too "
            f"({program()} {names[0]} FILE): {have}"
        )
    matches = [file for files in shipped.values() for file in files if file.name == names[0]]
    if len(matches) == 1:
        return matches[0]
    if matches:
        where = ", ".join(file.parent.parent.name for file in matches)
        raise LaunchError(
            f"{names[0]} is in several packages ({where}); say which: {program()} PKG FILE"
        )
    have = ", ".join(f"{pkg} {file.name}" for pkg, files in shipped.items() for file in files)
    raise LaunchError(f"no launch file {names[0]!r} here or in any package; known: {have}")


def split_words(words: list[str]) -> tuple[list[str], dict[str, str]]:
    """The file words and the name:=value arguments."""
    names, args = [], {}
    for word in words:
        name, equals, value = word.partition("=")
        if equals and ":=" not in word and valid_name(name) and not Path(word).exists():
            raise LaunchError(
                f"{word!r}: launch arguments are written name:=value; did you mean {name}:={value}?"
            )
        if ":=" not in word:
            names.append(word)
            continue
        name, _, value = word.partition(":=")
        # ros2 launch argument names may have parts: perception/enable:=false
        if not all(valid_name(part) for part in name.split("/")):
            raise LaunchError(f"malformed argument {word!r}: expected name:=value")
        args[name] = value
    return names, args


def format_args(infos: list[ArgInfo]) -> str:
    if not infos:
        return "This launch file has no arguments."
    lines = ["Arguments (pass arguments as '<name>:=<value>'):"]
    for info in infos:
        lines += ["", f"    {info.name!r}:"]
        if info.description:
            lines.append(f"        {info.description}")
        elif info.fmt == "ros2":  # as ros2 launch --show-args says it
            lines.append("        no description given")
        if info.choices:
            lines.append(f"        Valid choices are: {info.choices}")
        if info.fixed:
            lines.append(f"        (fixed value: {info.default!r}; cannot be set)")
        elif info.default is None:
            lines.append("        (required)")
        else:
            lines.append(f"        (default: {info.default!r})")
    return "\n".join(lines)


@program_main  # `roslaunch --print FILE | head`
def _print_and_end(text: str) -> int:
    print(text)
    return 0


@program_main  # until the supervisor handles it (Supervisor.run)
def main(
    argv: list[str] | None = None, program: str | None = None, standalone: bool | None = None
) -> int:
    """The launcher's command line. STANDALONE (default: no ARGV given) means this process is
    the launcher (`roslaunch`, `ros2 launch`): it forks its guardian before starting."""
    parser = build_parser(program)
    completion.answer(parser)  # the shell asking for TAB's completions (roslaunch): ends here
    options = parser.parse_intermixed_args(argv)
    if standalone is None:
        standalone = argv is None
    name = program or _program_name()
    ros2 = name == "ros2 launch"  # speaks as ros2 launch does
    try:
        names, args = split_words(options.words)
        path = find_launch_file(names)
        if options.show_args:
            return _print_and_end(format_args(describe_args(path)))
        launch = resolve(path, args, Options(allow_code=options.allow_code))
        specs = make_plan(launch, options.screen, options.sigterm_timeout, options.sigkill_timeout)
    except (LaunchError, RecursionError) as error:
        if options.debug:
            import traceback

            traceback.print_exc()
        if isinstance(error, RecursionError):
            error = LaunchError("the launch file is nested too deeply")
        if isinstance(error, LaunchFileRaised):  # the Python launch file's own lines
            print(error.traceback, file=sys.stderr, end="")
        if isinstance(error, CodeRefused):  # exactly what to type to allow it
            words = shlex.join(sys.argv[1:] if argv is None else argv)
            error = f"{error.what}; to allow it, run: {name} {words} --allow-code"
        print(f"error: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    if options.print or not ros2:  # at start, before the plan or the first process
        for warning in launch.warnings:
            print(f"warning: {warning}", file=sys.stderr, flush=True)
    if options.print:
        return _print_and_end(format_plan(specs, launch.messages, launch.steps, launch.containers))
    problem = environment_problem()  # as `ros2 run`: one line before any node starts
    if problem:
        print(f"error: {problem}", file=sys.stderr)
        return 1
    # Imported here so --print and --show-args stay fast (this pulls in the ROS plumbing).
    from launcher.supervise import Supervisor, make_log_dir

    try:
        log_dir = make_log_dir()
    except LaunchError as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    if standalone:  # the program itself: from here on this process is the launcher's
        guardian.guard()  # guardian, and the launcher goes on in a child
    if not ros2:  # ros2 launch says them after where its logs are (the supervisor does)
        for message in launch.messages:
            print(f"[launcher] {message}", flush=True)
    return Supervisor(
        specs, log_dir, options.debug, launch.steps, ros2, launch.warnings, launch.messages
    ).run()


if __name__ == "__main__":
    raise SystemExit(main())
