"""The package index the launcher and the tools read: where packages are, what they can run.

Packages are found the ament way (ament.py beside this): a package is installed in a prefix of
AMENT_PREFIX_PATH when the ament index there lists it, and its files are in <prefix>/share/<pkg>/.
`make setup` registers this project's packages (folders with a package.xml) in this
environment's index, share/<pkg>/ linking to their package.xml, launch/ and config/
(tools/register_packages.py). ``share_directory()`` and ``prefix()`` answer `$(find-pkg-share)`
and `$(find-pkg-prefix)`; ``package_folder()`` answers ROS 1's `rospack find` and `$(find)`.

A tutorial package is one of those whose Python package can be imported; a stand-in is a ROS
package PyPI lacks that this project provides as a top-level folder with a package.xml (tf2_ros,
ament_copyright). Their executables are found, never listed by hand, so a lesson or a stand-in
merged later is picked up with no change here:
- each module of the package that defines a top-level ``main()`` (``publisher``,
  ``tf2_ros.tf2_echo``), and
- for a tutorial package, each console script whose entry point lives in the package
  (``topic_publisher``); a stand-in's console script is a command on PATH, as in ROS's bin/.
Both run as ``python -m <module>``; this is the one place that decides that: ``command()``
turns (package, executable) into a command line for the launcher and for ``rosrun``.

The seeds name their packages differently (``rosrun beginner_tutorials talker``);
``PACKAGE_ALIASES`` says where their executables are here.

Any other package of the ament index runs as ROS 2 runs it: its executables are the files in
<prefix>/lib/<package>/ (``installed_executables``), what colcon installs for a learner's own
package (`ros2 pkg create`, `colcon build`, `source install/setup.bash`). A package of a
sourced workspace (an overlay: a prefix other than this environment) shadows a seed's name
(the tutorials' own `my_package`, not seed 004's).
"""

from __future__ import annotations

import difflib
import importlib.util
import os
import pkgutil
import re
import sys
from collections.abc import Sequence
from functools import cache
from pathlib import Path

from ros_tutorials_common import ament, lesson_scripts
from ros_tutorials_common.pypi_packages import cpp_package_line

PACKAGE_PREFIX = "ros_tutorials_"
DISTRIBUTION = "ros-tutorials"
# A module's own main(): an executable (_has_main).
_TOP_LEVEL_MAIN = re.compile(r"^def main\(", re.MULTILINE)

# The seeds' package names -> this project's package(s) holding their executables (searched
# in order, the first that has the executable wins).
_TOPIC_AND_SERVICE = ("ros_tutorials_topic", "ros_tutorials_service")
PACKAGE_ALIASES: dict[str, str | tuple[str, ...]] = {
    "beginner_tutorials": _TOPIC_AND_SERVICE,  # seeds 001, 002
    "roscpp_tutorials": _TOPIC_AND_SERVICE,  # seed 001 (talker, listener, add_two_ints_*)
    "rospy_tutorials": _TOPIC_AND_SERVICE,
    "pub_sub": "ros_tutorials_topic",  # seed 003
    "service": "ros_tutorials_service",  # seed 003's AddTwoInts package
    "my_package": (*_TOPIC_AND_SERVICE, "ros_tutorials_parameter"),  # seed 004
    # turtlesim's nodes: rosidl's generated module is already called `turtlesim`.
    "turtlesim": "ros_tutorials_turtlesim",  # seeds 001-004
    # ROS 2's demos the Beginner CLI tutorials run (the service introspection demo).
    "demo_nodes_cpp": "ros_tutorials_demo_nodes",
    "demo_nodes_py": "ros_tutorials_demo_nodes",
}
# A seed executable whose name belongs to another lesson here: (seed package, name) -> name.
EXECUTABLE_ALIASES: dict[tuple[str, str], str] = {
    ("pub_sub", "publisher"): "num_publisher",  # seed 003's publisher ends up sending Num
    ("pub_sub", "subscriber"): "num_subscriber",
    ("service", "add_two_int"): "add_two_ints_server",  # seed 003's targets (CMakeLists.txt)
    ("service", "client"): "add_two_ints_client",
    # seed 004's rospy scripts print what the seed shows ("Receive : ", "Returning [...]")
    ("my_package", "talker"): "workshop_talker",
    ("my_package", "listener"): "workshop_listener",
    ("my_package", "add_two_ints_server"): "workshop_add_two_ints_server",
    ("my_package", "add_two_ints_client"): "workshop_add_two_ints_client",
}
# ROS 1 GUI tools the seeds name that this project does not have, and what does their job
# here (rqt's plugins are in the browser: `rqt`, `rqt_publisher`, ..., ros_tutorials_web).
MISSING_TOOLS: dict[str, str] = {
    "rqt_topic": "use `ros2 topic list`, `ros2 topic echo`, `ros2 topic hz`",
}


class UnknownExecutable(LookupError):
    """No such package or executable; str() is one line naming the candidates."""


class PackageNotFound(UnknownExecutable):
    """command() was given a package name that names nothing runnable here."""


class UnknownPackage(LookupError):
    """No package of that name in the ament index; str() is one line."""


@cache
def package_dirs() -> dict[str, Path]:
    """This project's packages in the ament index, and the folder of each one's Python code.

    A package is this project's when its share/PKG/package.xml links to the package.xml in the
    folder of its Python package (tools/register_packages.py links them so): the tutorial
    packages and the stand-ins (tf2_ros, ...). A learner's package built with
    `--symlink-install` keeps its Python package one folder deeper, an interface package
    (turtlesim) has its Python code generated elsewhere: neither is one."""
    found = {}
    for name, prefix in ament.packages().items():
        tutorial = name.startswith(PACKAGE_PREFIX)  # shadowed by an overlay, still ours
        source = None
        if not tutorial:
            manifest = prefix / "share" / name / "package.xml"
            if not manifest.is_symlink():
                continue
            source = manifest.resolve().parent
            if not (source / "__init__.py").is_file():  # an interface package's folder
                continue
        spec = importlib.util.find_spec(name)
        if spec and spec.submodule_search_locations:
            folder = Path(next(iter(spec.submodule_search_locations)))
            if source is None or folder.resolve() == source:
                found[name] = folder
    return found


def stand_in(package: str) -> bool:
    """A ROS package PyPI lacks that this project provides (tf2_ros), not a tutorial package."""
    return package in package_dirs() and not package.startswith(PACKAGE_PREFIX)


def _has_main(source_file: Path) -> bool:
    # Read the source instead of importing it: importing a node module loads rclpy. A line
    # that starts with `def main(` is a top-level definition (nested ones are indented); a
    # search, not a parse: `ros2 run` reads every module of the package before it starts one.
    try:
        text = source_file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    return _TOP_LEVEL_MAIN.search(text) is not None


def _declared_parameters(source_file: Path) -> set[str]:
    """The parameter names a node module declares by a literal name (declare_parameter("x"))."""
    import ast  # only for the parameter lookups (rosparam, the launcher's checks)

    try:
        tree = ast.parse(source_file.read_text(encoding="utf-8"))
    except (OSError, SyntaxError, UnicodeDecodeError):
        return set()
    return {
        node.args[0].value
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr == "declare_parameter"
        and node.args
        and isinstance(node.args[0], ast.Constant)
        and isinstance(node.args[0].value, str)
    }


def executables_declaring(parameter: str) -> list[tuple[str, str]]:
    """(package, executable) of the executables whose node declares ``parameter``, read from
    their source; one name per module, the console script's (the book's) where there is one."""
    found: dict[str, tuple[str, str]] = {}
    for package, directory in package_dirs().items():
        for name, line in executables(package).items():
            module = module_of(line) or ""
            if not module.startswith(f"{package}."):
                continue
            short = module.rpartition(".")[2]
            if module in found and name == short:
                continue  # the console script's name wins over the module's
            if parameter in _declared_parameters(directory / f"{short}.py"):
                found[module] = (package, name)
    return sorted(found.values())


@cache
def executables(package: str) -> dict[str, list[str]]:
    """Executable name -> command line, for one package of this project ({} if unknown).

    The same rule for a tutorial package and a stand-in: the modules that define main(). A
    stand-in's console script (`ament_copyright`) is a command on PATH, as ROS installs it in
    bin/, so neither it nor the module it runs is an executable of the package."""
    directory = package_dirs().get(package)
    if directory is None:
        return {}
    scripts = {name: target for name, target in console_scripts().items()
               if target.startswith(f"{package}.")}  # fmt: skip
    on_path = {target.partition(":")[0] for target in scripts.values()} if stand_in(package) else ()
    found = {}
    for module in pkgutil.iter_modules([str(directory)]):
        qualified = f"{package}.{module.name}"
        if module.ispkg or qualified in on_path:
            continue
        if _has_main(directory / f"{module.name}.py"):
            found[module.name] = module_command(qualified)
    if not stand_in(package):
        found.update((name, _script_command(target)) for name, target in scripts.items())
    return dict(sorted(found.items()))


@cache
def _project_scripts() -> list[tuple[str, str]]:
    """(name, ``module:attr``) of this project's console scripts: the only distribution whose
    scripts run a package of this project. Read from its installed metadata, the first
    ``ros_tutorials-*.dist-info`` on sys.path, as importlib.metadata finds a distribution,
    without importing importlib.metadata, which took 30 ms of CPU: a third of the launcher's
    start before its first process (and a scan of every distribution's entry points, about 250
    with the ROS wheels, as much again)."""
    import configparser

    prefix = DISTRIBUTION.replace("-", "_") + "-"
    for folder in sys.path:
        try:
            names = sorted(os.listdir(folder or "."))
        except OSError:  # gone, or a zip file
            continue
        for name in names:
            if name.startswith(prefix) and name.endswith(".dist-info"):
                entry_points = configparser.ConfigParser(delimiters=("=",), interpolation=None)
                entry_points.optionxform = str  # names keep their case
                try:
                    entry_points.read(os.path.join(folder, name, "entry_points.txt"), "utf-8")
                except (configparser.Error, UnicodeDecodeError):
                    return []
                if not entry_points.has_section("console_scripts"):
                    return []
                return list(entry_points["console_scripts"].items())
    return []


@cache
def console_scripts() -> dict[str, str]:
    """Console script name -> the ``module:function`` it runs; for a lesson's script, the
    lesson's own main (the script applies the DDS defaults first, ros_tutorials_common/
    lesson_scripts.py; `ros2 run` and the launcher apply them themselves)."""

    found = {}
    for name, value in _project_scripts():
        module, _, function = value.partition(":")
        lesson = lesson_scripts.lesson_module(value)
        found[name] = f"{lesson}:main" if lesson else f"{module.strip()}:{function.strip()}"
    return found


def module_command(module: str) -> list[str]:
    """``python -m MODULE``; a plain rclpy node's module (a lesson's) starts through
    lesson_scripts, where the project starts lessons."""
    if module.partition(".")[0] in lesson_scripts.PLAIN_NODE_PACKAGES:
        return lesson_scripts.command(module)
    return [sys.executable, "-m", module]


def module_of(line: Sequence[str]) -> str | None:
    """The module of this project a command line of ``module_command`` runs, else None."""
    line = list(line)
    started = lesson_scripts.started_module(line)
    if started is not None:
        return started
    return line[2] if line[1:2] == ["-m"] and len(line) > 2 else None


def _script_command(target: str) -> list[str]:
    module, _, function = target.partition(":")
    function = function.strip()
    if function == "main":
        return module_command(module.strip())
    code = f"import sys; from {module} import {function}; sys.exit({function}())"
    return [sys.executable, "-c", code]


def installed_executables(package: str) -> dict[str, list[str]]:
    """Executable name -> command line, for a package of the ament index: the files in
    <prefix>/lib/<package>/ that can be run, as ros2pkg finds them ({} if none)."""
    try:
        lib = ament.package_prefix(package) / "lib" / package
    except ament.PackageNotFound:
        return {}
    found = {}
    for folder, subfolders, files in os.walk(lib):
        subfolders[:] = sorted(sub for sub in subfolders if not sub.startswith("."))
        for file in files:
            path = os.path.join(folder, file)
            if os.access(path, os.X_OK) and os.path.isfile(path):
                found.setdefault(file, [path])
    return dict(sorted(found.items()))


def overlay_package(name: str) -> bool:
    """Whether NAME is a package of a sourced workspace (a prefix other than this
    environment's), not one of this project's."""
    prefix = ament.packages().get(name)
    here = os.path.realpath(sys.prefix)
    return prefix is not None and os.path.realpath(prefix) != here and name not in package_dirs()


def unsourced_install(package: str) -> Path | None:
    """The install/ folder of a workspace, here or above, where PACKAGE is built though no
    sourced setup file put it in the ament index; None if there is none."""
    here = Path.cwd()
    for folder in (here, *here.parents):
        install = folder / "install"
        for prefix in (install / package, install):  # isolated (the default), or merged
            marker = prefix / "share" / "ament_index" / "resource_index" / "packages" / package
            if marker.is_file():
                return install
    return None


def not_sourced_hint(package: str) -> str:
    """'PACKAGE is built in ... : run `source .../setup.bash`' when it is built but not sourced;
    '' when it is not."""
    install = unsourced_install(package)
    if install is None:
        return ""
    shown = install.relative_to(Path.cwd()) if install.parent == Path.cwd() else install
    return (
        f"{package!r} is built in {install} but that workspace is not sourced: "
        f"run `source {shown}/setup.bash`"
    )


def runnable_packages() -> list[str]:
    ours = [package for package in package_dirs() if executables(package)]
    overlays = [name for name in ament.packages() if overlay_package(name)]
    return ours + [name for name in overlays if installed_executables(name)]


def resolve_package(name: str) -> tuple[str, ...]:
    """The packages of this project a package name stands for: itself, or a seed's alias
    (none for a package of a sourced workspace, which shadows a seed's name)."""
    if name in package_dirs():
        return (name,)
    if overlay_package(name):
        return ()
    target = PACKAGE_ALIASES.get(name, ())
    targets = (target,) if isinstance(target, str) else target
    return tuple(package for package in targets if package in package_dirs())


def known_package_names(near: str = "") -> str:
    """The packages `ros2 pkg list` shows (the ament index) and the names `ros2 run` takes for
    them (demo_nodes_cpp, the seeds' beginner_tutorials), as one line: the names nearest to
    NEAR first (a typo's intended name), then the rest in order."""
    index = ament.packages()
    seeds = [name for name in PACKAGE_ALIASES if name not in index and resolve_package(name)]
    names = sorted([*index, *seeds])
    nearest = difflib.get_close_matches(near, names, n=5, cutoff=0.6) if near else []
    return ", ".join([*nearest, *(name for name in names if name not in nearest)])


def unknown_package_line(name: str) -> str:
    """Why NAME is no package here, in one line: built in a workspace that is not sourced, a
    C++ package of the official pages (with its Python twin), or unknown, with the list of
    known packages nearest names first. The one text `ros2 run`, rosrun, a launch file's
    `$(find-pkg-share)` and `ros2 launch PKG FILE` give."""
    return (
        not_sourced_hint(name)
        or cpp_package_line(name)
        or f"unknown package {name!r}; known packages: {known_package_names(name)}"
    )


@cache
def _tools() -> dict[str, list[str]]:
    """This project's own commands (``rqt_graph``, ...) by console script name."""
    return {name: _script_command(value) for name, value in _project_scripts()}


def executable_commands(package: str) -> dict[str, list[str]]:
    """Executable name -> command line, for any package name `ros2 run`, rosrun, the launcher
    and `ros2 pkg executables` take: the one table of which (package, executable) pairs exist.

    An installed package's lib/<package>/ comes first; a package of a sourced workspace is only
    that (it shadows a seed's name and its executables' names). For a package of this project,
    or a seed's name, the executables of the packages it stands for, and a seed's own names for
    them (EXECUTABLE_ALIASES: seed 003's `pub_sub publisher`)."""
    known = installed_executables(package)
    targets = resolve_package(package)
    for name in targets:
        for found, line in executables(name).items():
            known.setdefault(found, line)
    if targets and targets != (package,):  # a seed's name: its own names win over the lessons'
        for (seed, name), target in EXECUTABLE_ALIASES.items():
            if seed == package and target in known:
                known[name] = known[target]
    return dict(sorted(known.items()))


def executable_files(package: str) -> dict[str, Path]:
    """What `ros2 pkg executables` lists: the names of executable_commands(), one per program,
    each with the file that runs (an installed file; a console script; a module's source).

    A program with several names is listed under the seed's name, else its console script's
    (what a colcon install puts in lib/PKG/: `turtle_teleop_key`, not the module `teleop_key`)."""
    commands = executable_commands(package)
    seed_names = {name for seed, name in EXECUTABLE_ALIASES if seed == package}
    scripts = console_scripts()

    def rank(name: str) -> int:
        return 0 if name in seed_names else 1 if name in scripts else 2

    chosen: dict[tuple[str, ...], str] = {}
    for name in sorted(commands, key=rank):
        chosen.setdefault(tuple(commands[name]), name)
    files = {}
    for line, name in chosen.items():
        if line[1:2] != ("-m",) and line[1:2] != ("-c",):
            files[name] = Path(line[0])  # an installed file
        elif name in scripts:
            files[name] = Path(sys.executable).parent / name
        else:  # a module of this project's: its source
            package_name, _, module = (module_of(line) or "").rpartition(".")
            files[name] = package_dirs()[package_name] / f"{module}.py"
    return dict(sorted(files.items()))


def command(package: str, executable: str) -> list[str]:
    """The command line that runs EXECUTABLE of PACKAGE, as rosrun and launch files name them.

    A seed's package name is looked up in PACKAGE_ALIASES, and ROS 1's ``rosrun rqt_graph
    rqt_graph`` (a tool whose package and executable have one name) runs this project's
    command of that name. Raises UnknownExecutable naming the candidates.
    """
    if PACKAGE_ALIASES.get(package) and not overlay_package(package):
        hint = not_sourced_hint(package)
        if hint:  # the learner's own package of a seed's name, built but not sourced
            raise PackageNotFound(hint)
    known = executable_commands(package)
    if not known:
        if package == executable and executable in _tools():
            return list(_tools()[executable])
        if package in MISSING_TOOLS:
            raise UnknownExecutable(
                f"{package} is a GUI tool this project does not have; {MISSING_TOOLS[package]}"
            )
        if package in ament.packages():
            raise UnknownExecutable(f"package {package!r} has no executables")
        raise PackageNotFound(unknown_package_line(package))
    # The name as given first (an installed `listener.py`); then without the suffix the book's
    # ROS 1 files sometimes add to a script's name (type="talker.py").
    name = executable if executable in known else executable.removesuffix(".py")
    if name not in known:
        hint = "" if overlay_package(package) else not_sourced_hint(package)
        if hint:  # a package of this environment's name that the learner's own has too
            raise PackageNotFound(hint)
        have = ", ".join(sorted(known))
        raise UnknownExecutable(
            f"package {package!r} has no executable {executable!r}; it has: {have}"
        )
    return list(known[name])


def ament_package(name: str) -> str:
    """The package of the ament index a name stands for: itself, or for a seed's name that is
    not a package here, the one package of this project it stands for (pub_sub -> topic).

    `turtlesim` is a package here (its interfaces keep their real name), so its paths are the
    interface package's; its executables and launch files are ros_tutorials_turtlesim's.
    """
    if name in ament.packages():
        return name
    targets = resolve_package(name)
    if len(targets) == 1:
        return targets[0]
    if targets:
        raise UnknownPackage(f"{name} (a seed's package) stands for {', '.join(targets)}; name one")
    raise UnknownPackage(unknown_package_line(name))


def share_directory(name: str) -> Path:
    """<prefix>/share/<package>: `$(find-pkg-share PKG)`, `ros2 pkg prefix --share PKG`."""
    return ament.share_directory(ament_package(name))


def prefix(name: str) -> Path:
    """The install prefix of a package: `$(find-pkg-prefix PKG)`, `ros2 pkg prefix PKG`."""
    return ament.package_prefix(ament_package(name))


def package_folder(name: str) -> Path:
    """The package's own folder, what ROS 1's `rospack find` and `$(find PKG)` answered.

    For a package of this workspace that is its source folder, where the learner edits:
    share/PKG/package.xml is a link to it, as a symlink install (`colcon build
    --symlink-install`) makes. For an installed package (std_msgs) it is share/PKG.
    """
    share = share_directory(name)
    manifest = share / "package.xml"
    return manifest.resolve().parent if manifest.is_symlink() else share


def launch_packages(name: str) -> tuple[str, ...]:
    """The packages whose share folders `ros2 launch NAME FILE` looks in: this project's that
    the name stands for (a seed's name, `turtlesim`), else the package of the ament index of
    that name (a learner's own); none if it is neither."""
    if PACKAGE_ALIASES.get(name) and not overlay_package(name) and not_sourced_hint(name):
        return ()  # the learner's own package of a seed's name, built but not sourced
    found = resolve_package(name)
    if not found and name in ament.packages():
        found = (name,)
    return found


def launch_files(package: str) -> list[Path]:
    """The launch files a package installs in share/PKG/launch/."""
    folder = ament.share_directory(package) / "launch"
    if not folder.is_dir():
        return []
    suffixes = (".launch", ".xml", ".py", ".yaml", ".yml")  # the three formats of ros2 launch
    return sorted(path for path in folder.iterdir() if path.name.endswith(suffixes))


def share_files(package: str, file_name: str) -> list[Path]:
    """Every file named FILE_NAME in share/PACKAGE and its folders, as `ros2 launch PKG FILE`
    looks (ros2launch walks the whole share directory: a package may install its launch file
    in share/PKG itself). The folders this environment links in (launch/, config/) are
    followed, each real folder once."""
    share = ament.share_directory(package)
    found, seen = [], set()
    for folder, subfolders, files in os.walk(share, followlinks=True):
        real = os.path.realpath(folder)
        if real in seen:  # a link back up the tree
            subfolders[:] = []
            continue
        seen.add(real)
        subfolders.sort()
        if file_name in files:
            found.append(Path(folder, file_name))
    return found
