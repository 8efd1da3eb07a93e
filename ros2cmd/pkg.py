"""`ros2 pkg ...`: the packages of the ament index, and a new package (ROS 2's ros2pkg).

    ros2 pkg list                          every package of the ament index, sorted
    ros2 pkg prefix turtlesim [--share]    its install prefix (or share/turtlesim)
    ros2 pkg executables turtlesim         `turtlesim draw_square` ... one a line, sorted
    ros2 pkg xml turtlesim [-t version]    its package.xml (or one tag's text)
    ros2 pkg create --build-type ament_python --license Apache-2.0 --node-name my_node my_package

The packages are those of the ament index (ros_tutorials_common/ament.py: this environment,
and what AMENT_PREFIX_PATH adds). A package's executables are exactly what `ros2 run` starts,
from the one table in ros_tutorials_common/packages.py: what an installed package has in
<prefix>/lib/<package>/, and for this project's packages and the seeds' names for them
(`demo_nodes_cpp`, `pub_sub`) the lessons: `turtlesim` is the interface package, its nodes are
ros_tutorials_turtlesim's, listed under the name the tutorials type.

`create` writes the files ros2pkg's templates write (package.xml, setup.py, setup.cfg,
resource/, test/, the node; CMakeLists.txt and src/ for ament_cmake; LICENSE for the licenses
ament_copyright knows, in ros2cmd/licenses/) and prints the same lines while it does. Unlike
ros2pkg's templates, every value is escaped for the file it goes into (XML in package.xml,
a Python string in setup.py), and what cannot be written safely (a control character, a
dependency that is not a package name, a package.xml catkin_pkg would not read) is refused
with one line before anything is written.
"""

from __future__ import annotations

import argparse
import getpass
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

from ros2cmd.errors import ToolError
from ros_tutorials_common import ament, packages

LICENSES = Path(__file__).parent / "licenses"
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


def package_prefix(name: str) -> Path:
    try:
        return ament.package_prefix(name)
    except ament.PackageNotFound:
        raise ToolError(f"Package '{name}' not found") from None


def list_packages() -> None:
    for name in sorted(ament.packages()):
        print(name)


def prefix(name: str, share: bool = False) -> None:
    if name in ament.packages():
        path = package_prefix(name)
        print(path / "share" / name if share else path)
        return
    try:  # a seed's name `ros2 run` takes (demo_nodes_cpp): the package it stands for
        print(packages.share_directory(name) if share else packages.prefix(name))
    except packages.UnknownPackage as error:
        known = packages.resolve_package(name)
        raise ToolError(str(error) if known else f"Package '{name}' not found") from None


def executables(name: str) -> dict[str, Path]:
    """A package's executables: name -> the file that runs (a script or a module's source);
    the pairs `ros2 run` takes (ros_tutorials_common/packages.py), a seed's name's too."""
    found = packages.executable_files(name)
    if not found:
        package_prefix(name)  # "Package 'NAME' not found" unless it is a package
    return found


def print_executables(name: str | None, full_path: bool) -> None:
    for package in [name] if name else sorted(ament.packages()):
        for executable, path in executables(package).items():
            print(path if full_path else f"{package} {executable}")


def xml(name: str, tag: str | None) -> None:
    manifest = package_prefix(name) / "share" / name / "package.xml"
    if not manifest.is_file():
        raise ToolError("Package XML manifest not found")
    try:
        tree = ElementTree.parse(manifest)
    except ElementTree.ParseError as error:
        raise ToolError(f"{manifest}: not valid XML: {error}") from None
    if tag is None:
        ElementTree.dump(tree)
        return
    elements = tree.getroot().findall(tag)
    if not elements:
        raise ToolError("XML tag not found")
    for element in elements:
        print(element.text)


# `ros2 pkg create`


@dataclass
class NewPackage:
    """What `ros2 pkg create` was asked for: the fields of the package.xml it writes."""

    name: str
    build_type: str
    package_format: int = 3
    description: str = "TODO: Package description"
    license: str = "TODO: License declaration"
    maintainer_name: str = ""
    maintainer_email: str = ""
    dependencies: list[str] = field(default_factory=list)
    node_name: str | None = None
    library_name: str | None = None

    @property
    def buildtool_dependencies(self) -> list[str]:
        if self.build_type != "ament_cmake":
            return []
        return ["ament_cmake_ros"] if self.library_name else ["ament_cmake"]

    @property
    def test_dependencies(self) -> list[str]:
        if self.build_type == "ament_cmake":
            return ["ament_lint_auto", "ament_lint_common"]
        return ["ament_copyright", "ament_flake8", "ament_pep257", "python3-pytest"]

    @property
    def maintainer(self) -> str:
        return f"{self.maintainer_name} <{self.maintainer_email}>"


def _group(tag: str, names: list[str]) -> list[str]:
    """One package.xml dependency group, followed by an empty line, as ros2pkg writes it."""
    return [f"  <{tag}>{name}</{tag}>" for name in names] + [""] if names else []


def package_xml(package: NewPackage) -> str:
    schema = f"http://download.ros.org/schema/package_format{package.package_format}.xsd"
    email = quoteattr(package.maintainer_email)
    lines = [
        '<?xml version="1.0"?>',
        f'<?xml-model href="{schema}" schematypens="http://www.w3.org/2001/XMLSchema"?>',
        f'<package format="{package.package_format}">',
        f"  <name>{package.name}</name>",
        "  <version>0.0.0</version>",
        f"  <description>{escape(package.description)}</description>",
        f"  <maintainer email={email}>{escape(package.maintainer_name)}</maintainer>",
        f"  <license>{escape(package.license)}</license>",
        "",
        *_group("buildtool_depend", package.buildtool_dependencies),
        *_group("depend", package.dependencies),
        *_group("test_depend", package.test_dependencies),
        "  <export>",
        f"    <build_type>{package.build_type}</build_type>",
        "  </export>",
        "</package>",
    ]
    return "\n".join(lines) + "\n"


def python_text(value: str) -> str:
    """value inside a single-quoted Python string, as ros2pkg's setup.py template quotes."""
    return value.replace("\\", "\\\\").replace("'", "\\'")


def setup_py(package: NewPackage) -> str:
    scripts = (
        f"            '{package.node_name} = {package.name}.{package.node_name}:main'\n"
        if package.node_name
        else ""
    )
    return f"""from setuptools import find_packages, setup

package_name = '{package.name}'

setup(
    name=package_name,
    version='0.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages',
            ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='{python_text(package.maintainer_name)}',
    maintainer_email='{python_text(package.maintainer_email)}',
    description='{python_text(package.description)}',
    license='{python_text(package.license)}',
    tests_require=['pytest'],
    entry_points={{
        'console_scripts': [
{scripts}        ],
    }},
)
"""


def setup_cfg(package: NewPackage) -> str:
    return (
        f"[develop]\nscript_dir=$base/lib/{package.name}\n"
        f"[install]\ninstall_scripts=$base/lib/{package.name}\n"
    )


def python_node(package: NewPackage) -> str:
    return f"""def main():
    print('Hi from {package.name}.')


if __name__ == '__main__':
    main()
"""


_APACHE_HEADER = """# Copyright {year} Open Source Robotics Foundation, Inc.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
"""
# ros2pkg's three linter tests of an ament_python package, as its templates have them.
PYTHON_TESTS = {
    "test_copyright.py": _APACHE_HEADER.format(year=2015)
    + """
from ament_copyright.main import main
import pytest


# Remove the `skip` decorator once the source file(s) have a copyright header
@pytest.mark.skip(reason='No copyright header has been placed in the generated source file.')
@pytest.mark.copyright
@pytest.mark.linter
def test_copyright():
    rc = main(argv=['.', 'test'])
    assert rc == 0, 'Found errors'
""",
    "test_flake8.py": _APACHE_HEADER.format(year=2017)
    + """
from ament_flake8.main import main_with_errors
import pytest


@pytest.mark.flake8
@pytest.mark.linter
def test_flake8():
    rc, errors = main_with_errors(argv=[])
    assert rc == 0, \\
        'Found %d code style errors / warnings:\\n' % len(errors) + \\
        '\\n'.join(errors)
""",
    "test_pep257.py": _APACHE_HEADER.format(year=2015)
    + """
from ament_pep257.main import main
import pytest


@pytest.mark.linter
@pytest.mark.pep257
def test_pep257():
    rc = main(argv=['.', 'test'])
    assert rc == 0, 'Found code style errors / warnings'
""",
}


def cmakelists(package: NewPackage) -> str:
    """ament_cmake's CMakeLists.txt, with the node and library ros2pkg's template adds."""
    name, node, library, deps = (
        package.name,
        package.node_name,
        package.library_name,
        package.dependencies,
    )
    lines = [
        "cmake_minimum_required(VERSION 3.8)",
        f"project({name})",
        "",
        'if(CMAKE_COMPILER_IS_GNUCXX OR CMAKE_CXX_COMPILER_ID MATCHES "Clang")',
        "  add_compile_options(-Wall -Wextra -Wpedantic)",
        "endif()",
        "",
        "# find dependencies",
        "find_package(ament_cmake REQUIRED)",
    ]
    if library:
        lines.append("find_package(ament_cmake_ros REQUIRED)")
    if deps:
        lines += [f"find_package({dep} REQUIRED)" for dep in deps]
    else:
        lines += [
            "# uncomment the following section in order to fill in",
            "# further dependencies manually.",
            "# find_package(<dependency> REQUIRED)",
        ]
    target_dependencies = ['  "' + dep + '"' for dep in deps]
    if library:
        lines += [
            "",
            f"add_library({library} src/{library}.cpp)",
            f"add_library({name}::{library} ALIAS {library})",
            f"target_compile_features({library} PUBLIC c_std_99 cxx_std_17)  "
            "# Require C99 and C++17",
            f"target_include_directories({library} PUBLIC",
            "  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>",
            "  $<INSTALL_INTERFACE:include/${PROJECT_NAME}>)",
        ]
        if deps:
            lines += ["ament_target_dependencies(", f"  {library}", *target_dependencies, ")"]
        lines += [
            "",
            "# Causes the visibility macros to use dllexport rather than dllimport,",
            "# which is appropriate when building the dll but not consuming it.",
            f'target_compile_definitions({library} PRIVATE "{name.upper()}_BUILDING_LIBRARY")',
            "",
            "install(",
            "  DIRECTORY include/",
            "  DESTINATION include/${PROJECT_NAME}",
            ")",
            "install(",
            f"  TARGETS {library}",
            "  EXPORT export_${PROJECT_NAME}",
            "  ARCHIVE DESTINATION lib",
            "  LIBRARY DESTINATION lib",
            "  RUNTIME DESTINATION bin",
            ")",
        ]
    if node:
        lines += [
            "",
            f"add_executable({node} src/{node}.cpp)",
            f"target_include_directories({node} PUBLIC",
            "  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>",
            "  $<INSTALL_INTERFACE:include/${PROJECT_NAME}>)",
        ]
        if library:
            lines.append(f"target_link_libraries({node} {library})")
        else:
            lines.append(
                f"target_compile_features({node} PUBLIC c_std_99 cxx_std_17)  "
                "# Require C99 and C++17"
            )
            if deps:
                lines += ["ament_target_dependencies(", f"  {node}", *target_dependencies, ")"]
        lines += ["", f"install(TARGETS {node}", "  DESTINATION lib/${PROJECT_NAME})"]
    lines += [
        "",
        "if(BUILD_TESTING)",
        "  find_package(ament_lint_auto REQUIRED)",
        "  # the following line skips the linter which checks for copyrights",
        "  # comment the line when a copyright and license is added to all source files",
        "  set(ament_cmake_copyright_FOUND TRUE)",
        "  # the following line skips cpplint (only works in a git repo)",
        "  # comment the line when this package is in a git repo and when",
        "  # a copyright and license is added to all source files",
        "  set(ament_cmake_cpplint_FOUND TRUE)",
        "  ament_lint_auto_find_test_dependencies()",
        "endif()",
    ]
    if library:
        lines += [
            "",
            "ament_export_include_directories(",
            '  "include/${PROJECT_NAME}"',
            ")",
            "ament_export_libraries(",
            f"  {library}",
            ")",
            "ament_export_targets(",
            "  export_${PROJECT_NAME}",
            ")",
        ]
    lines += ["", "ament_package()"]
    return "\n".join(lines) + "\n"


def cpp_node(package: NewPackage) -> str:
    return f"""#include <cstdio>

int main(int argc, char ** argv)
{{
  (void) argc;
  (void) argv;

  printf("hello world {package.name} package\\n");
  return 0;
}}
"""


def _class_name(library: str) -> str:
    return "".join(library.replace("_", " ").title().split())


def cpp_header(package: NewPackage) -> str:
    name, library = package.name, package.library_name or ""
    guard = f"{name.upper()}__{library.upper()}_HPP_"
    cls = _class_name(library)
    return f"""#ifndef {guard}
#define {guard}

#include "{name}/visibility_control.h"

namespace {name}
{{

class {cls}
{{
public:
  {cls}();

  virtual ~{cls}();
}};

}}  // namespace {name}

#endif  // {guard}
"""


def cpp_library(package: NewPackage) -> str:
    name, library = package.name, package.library_name or ""
    cls = _class_name(library)
    return f"""#include "{name}/{library}.hpp"

namespace {name}
{{

{cls}::{cls}()
{{
}}

{cls}::~{cls}()
{{
}}

}}  // namespace {name}
"""


def visibility_control(package: NewPackage) -> str:
    p = package.name.upper()
    return f"""#ifndef {p}__VISIBILITY_CONTROL_H_
#define {p}__VISIBILITY_CONTROL_H_

// This logic was borrowed (then namespaced) from the examples on the gcc wiki:
//     https://gcc.gnu.org/wiki/Visibility

#if defined _WIN32 || defined __CYGWIN__
  #ifdef __GNUC__
    #define {p}_EXPORT __attribute__ ((dllexport))
    #define {p}_IMPORT __attribute__ ((dllimport))
  #else
    #define {p}_EXPORT __declspec(dllexport)
    #define {p}_IMPORT __declspec(dllimport)
  #endif
  #ifdef {p}_BUILDING_LIBRARY
    #define {p}_PUBLIC {p}_EXPORT
  #else
    #define {p}_PUBLIC {p}_IMPORT
  #endif
  #define {p}_PUBLIC_TYPE {p}_PUBLIC
  #define {p}_LOCAL
#else
  #define {p}_EXPORT __attribute__ ((visibility("default")))
  #define {p}_IMPORT
  #if __GNUC__ >= 4
    #define {p}_PUBLIC __attribute__ ((visibility("default")))
    #define {p}_LOCAL  __attribute__ ((visibility("hidden")))
  #else
    #define {p}_PUBLIC
    #define {p}_LOCAL
  #endif
  #define {p}_PUBLIC_TYPE
#endif

#endif  // {p}__VISIBILITY_CONTROL_H_
"""


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
    git = shutil.which("git")
    if git is None:
        return ""
    result = subprocess.run(
        [git, "config", "user.email"], capture_output=True, text=True, check=False
    )
    return result.stdout.strip()


def create(args: argparse.Namespace) -> None:
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

    try:  # what colcon reads the package.xml with: a file it would refuse is not written
        catkin_package.parse_package_string(package_xml(package), warnings=[])
    except catkin_package.InvalidPackage as error:
        reason = next(line.strip("- ") for line in str(error).splitlines() if line.strip())
        raise ToolError(f"cannot create the package: {reason}") from None


def write_package(package: NewPackage, destination: str) -> None:
    """Write the package's files, saying each one as ros2pkg does, in its order."""
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


def register(verbs: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    parser = verbs.add_parser("pkg", help="Various package related sub-commands")
    sub = parser.add_subparsers(dest="command", metavar="Commands", required=True)

    p = sub.add_parser("create", help="Create a new ROS 2 package")
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
    p.set_defaults(offline=True, run=lambda _, a: create(a))

    p = sub.add_parser("executables", help="Output a list of package specific executables")
    p.add_argument("package_name", nargs="?", help="The package name")
    p.add_argument("--full-path", action="store_true", help="Show full path of each executable")
    p.set_defaults(offline=True, run=lambda _, a: print_executables(a.package_name, a.full_path))

    p = sub.add_parser("list", help="Output a list of available packages")
    p.set_defaults(offline=True, run=lambda _, a: list_packages())

    p = sub.add_parser("prefix", help="Output the prefix path of a package")
    p.add_argument("package_name", help="The package name")
    p.add_argument("--share", action="store_true", help="Show share directory for the package")
    p.set_defaults(offline=True, run=lambda _, a: prefix(a.package_name, a.share))

    p = sub.add_parser("xml", help="Output the XML of the package manifest or a specific tag")
    p.add_argument("package_name", help="The package name")
    p.add_argument("-t", "--tag", help="The XML tag to output (e.g. 'version')")
    p.set_defaults(offline=True, run=lambda _, a: xml(a.package_name, a.tag))
