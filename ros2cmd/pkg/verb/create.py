"""`ros2 pkg create NAME`: writes the files ros2pkg's templates write (templates.py; LICENSE
for the licenses ament_copyright knows, from ros2cmd/licenses/) and prints the same lines
while it does. What cannot be written safely (a control character, a dependency that is not a
package name, a package.xml catkin_pkg would not read) is refused with one line before
anything is written."""

from __future__ import annotations

import argparse
import getpass
import os
import re
import shutil
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from ros2cmd.errors import ToolError

if TYPE_CHECKING:  # the templates (dataclasses, xml) load when a package is created
    from ros2cmd.pkg.templates import NewPackage

HELP = "Create a new ROS 2 package"
LICENSES = Path(__file__).resolve().parents[2] / "licenses"  # ros2cmd/licenses/
# The SPDX identifiers ament_copyright has a LICENSE text for, in its order.
KNOWN_LICENSES = (
    "Apache-2.0", "BSL-1.0", "BSD-2.0", "BSD-3-Clause", "BSD-2-Clause", "MIT", "MIT-0",
    "GPL-3.0-only", "LGPL-3.0-only",
)  # fmt: skip
BUILD_TYPES = ("ament_cmake", "ament_python")
# REP 144: what colcon, CMake and Python (an ament_python package is a Python package) accept.
PACKAGE_NAME = r"[a-z][a-z0-9_]*"
# A dependency: a package or a rosdep key (python3-pytest): also a CMake and XML word.
DEPENDENCY_NAME = r"[A-Za-z0-9][A-Za-z0-9_.+-]*"
# What XML 1.0 cannot hold, and control characters (a newline would break setup.py's
# one-line strings); lone surrogates are bytes of the command line that are not UTF-8.
UNWRITABLE = re.compile(r"[\x00-\x1f\x7f-\x9f\ud800-\udfff\ufffe\uffff]")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    p = parser
    p.add_argument("package_name", help="The package name")
    p.add_argument(
        "--package-format",
        "--package_format",
        type=int,
        default=3,
        choices=[2, 3],
        help="The package.xml format.",
    )
    p.add_argument(
        "--description",
        default="TODO: Package description",
        help="The description given in the package.xml",
    )
    p.add_argument(
        "--license",
        default="TODO: License declaration",
        help="The license attached to this package; this can be an arbitrary string, but a "
        "LICENSE file will only be generated if it is one of the supported licenses "
        "(pass '?' to get a list)",
    )
    p.add_argument(
        "--destination-directory",
        default=os.curdir,
        help="Directory where to create the package directory",
    )
    p.add_argument(
        "--build-type",
        default="ament_cmake",
        choices=BUILD_TYPES,
        help="The build type to process the package with",
    )
    p.add_argument("--dependencies", nargs="+", default=[], help="list of dependencies")
    p.add_argument("--maintainer-email", help="email address of the maintainer of this package")
    p.add_argument("--maintainer-name", help="name of the maintainer of this package")
    p.add_argument("--node-name", help="name of the empty executable")
    p.add_argument("--library-name", help="name of the empty library")


def main(_graph: None, args: argparse.Namespace) -> None:
    if args.license == "?":
        print("Supported licenses:\n" + "\n".join(KNOWN_LICENSES))
        return
    node_name, library_name = args.node_name, args.library_name
    if node_name and node_name == library_name:
        node_name += "_node"
        print("[WARNING] node name can not be equal to the library name", file=sys.stderr)
        print(f"[WARNING] renaming node to {node_name}", file=sys.stderr)
    if not re.fullmatch(PACKAGE_NAME, args.package_name):
        # ros2pkg writes it anyway; colcon and CMake then fail on it far from here.
        raise ToolError(
            f"'{args.package_name}' is not a valid package name: lower-case letters, digits "
            "and underscores, starting with a letter (REP 144), e.g. my_package"
        )
    for what, name in (("node", node_name), ("library", library_name)):
        if name is not None and not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
            raise ToolError(f"--{what}-name '{name}' is not a valid name: letters, digits, '_'")
    if args.build_type == "ament_python" and args.package_name == "test":
        # The package's code folder and its tests' folder would be the same.
        raise ToolError(
            "Aborted since 'ament_python' packages can't be named 'test'. "
            "Please choose a different package name."
        )
    from ros2cmd.pkg.templates import NewPackage

    maintainer = args.maintainer_name or getpass.getuser()
    package = NewPackage(
        name=args.package_name,
        build_type=args.build_type,
        package_format=args.package_format,
        description=args.description,
        license=args.license,
        maintainer_name=maintainer,
        maintainer_email=args.maintainer_email or git_email() or f"{maintainer}@todo.todo",
        dependencies=list(args.dependencies),
        node_name=node_name,
        library_name=library_name,
    )
    check_writable(package)
    destination = args.destination_directory
    package_path = os.path.join(destination, package.name)
    if os.path.exists(package_path):
        raise ToolError(
            f"Aborted! The directory already exists: {package_path}; either remove the "
            "directory or choose a different destination directory or package name"
        )
    print("going to create a new package")
    print("package name:", package.name)
    print("destination directory:", os.path.abspath(destination))
    print("package format:", package.package_format)
    print("version:", "0.0.0")
    print("description:", package.description)
    print("maintainer:", [package.maintainer])
    print("licenses:", [package.license])
    print("build type:", package.build_type)
    print("dependencies:", package.dependencies)
    if node_name:
        print("node_name:", node_name)
    if library_name:
        print("library_name:", library_name)
    try:
        write_package(package, destination)
    except OSError as error:
        raise ToolError(f"cannot create the package: {error}") from None


def check_writable(package: NewPackage) -> None:
    """ToolError, before anything is written, for a value that cannot go into the files."""
    for option, value in (
        ("--description", package.description),
        ("--license", package.license),
        ("--maintainer-name", package.maintainer_name),
        ("--maintainer-email", package.maintainer_email),
    ):
        found = UNWRITABLE.search(value)
        if found:
            raise ToolError(
                f"{option} cannot be written into package.xml: it holds the character "
                f"U+{ord(found.group()):04X} (a control character, or bytes that are not UTF-8)"
            )
    for name in package.dependencies:
        if not re.fullmatch(DEPENDENCY_NAME, name):
            raise ToolError(
                f"--dependencies {name!r} is not a package name: letters, digits and "
                "'_', '-', '.', '+', starting with a letter or digit"
            )
    from catkin_pkg import package as catkin_package  # here: `ros2 pkg list` needs it not

    from ros2cmd.pkg.templates import package_xml

    try:  # what colcon reads the package.xml with: a file it would refuse is not written
        catkin_package.parse_package_string(package_xml(package), warnings=[])
    except catkin_package.InvalidPackage as error:
        reason = next(line.strip("- ") for line in str(error).splitlines() if line.strip())
        raise ToolError(f"cannot create the package: {reason}") from None


def write_package(package: NewPackage, destination: str) -> None:
    """Write the package's files, saying each one as ros2pkg does, in its order."""
    from ros2cmd.pkg.templates import (
        PYTHON_TESTS,
        cmakelists,
        cpp_header,
        cpp_library,
        cpp_node,
        package_xml,
        python_node,
        setup_cfg,
        setup_py,
        visibility_control,
    )

    root = _folder(destination, package.name)
    _file(root, "package.xml", package_xml(package))
    name, node, library = package.name, package.node_name, package.library_name
    if package.build_type == "ament_python":
        print("creating source folder")
        source = _folder(root, name)
        _file(root, "setup.py", setup_py(package))
        _file(root, "setup.cfg", setup_cfg(package))
        _file(_folder(root, "resource"), name, "")
        _file(source, "__init__.py", "")
        tests = _folder(root, "test")
        for test_file, content in PYTHON_TESTS.items():
            _file(tests, test_file, content)
        if node:
            _file(source, f"{node}.py", python_node(package))
        if library:
            _file(_folder(source, library), "__init__.py", "")
    else:
        print("creating source and include folder")
        source = _folder(root, "src")
        include = _folder(root + os.sep + "include", name)
        _file(root, "CMakeLists.txt", cmakelists(package))
        if node:
            _file(source, f"{node}.cpp", cpp_node(package))
        if library:
            _file(include, f"{library}.hpp", cpp_header(package))
            _file(source, f"{library}.cpp", cpp_library(package))
            _file(include, "visibility_control.h", visibility_control(package))
    if package.license in KNOWN_LICENSES:
        Path(root, "LICENSE").write_text((LICENSES / f"{package.license}.txt").read_text())
    else:
        print(
            f"\n[WARNING]: Unknown license '{package.license}'.  This has been set in the "
            "package.xml, but no LICENSE file has been created.\nIt is recommended to use one "
            "of the ament license identifiers:\n" + "\n".join(KNOWN_LICENSES)
        )


def _folder(base: str, name: str) -> str:
    path = os.path.join(base, name)
    print("creating folder", path)
    os.makedirs(path, exist_ok=True)
    return path


def _file(folder: str, name: str, content: str) -> None:
    path = os.path.join(folder, name)
    print("creating", path)
    with open(path, "w", encoding="utf-8") as file:
        file.write(content)


def git_email() -> str:
    """The user's `git config user.email`, as ros2pkg takes it ('' if none)."""
    import subprocess  # only to ask git: not to build the parser

    git = shutil.which("git")
    if git is None:
        return ""
    result = subprocess.run(
        [git, "config", "user.email"], capture_output=True, text=True, check=False
    )
    return result.stdout.strip()
