"""`ros2 pkg`: the ament index's packages, and `ros2 pkg create` as the tutorials run it
("Introducing turtlesim" and "Creating your first ROS 2 package", ROS 2 Jazzy).

Every command is the installed `ros2`; a created package is checked by what reads it:
catkin_pkg parses its package.xml, Python runs its node.
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest
from catkin_pkg.package import parse_package
from helpers import fails, ok
from helpers import run as tool

import ros2cmd

# Introducing-Turtlesim.rst, "ros2 pkg executables turtlesim".
TURTLESIM_EXECUTABLES = """\
turtlesim draw_square
turtlesim mimic
turtlesim turtle_teleop_key
turtlesim turtlesim_node
"""
# Creating-Your-First-ROS2-Package.rst: what `ros2 pkg create` prints; the lines that name
# the learner's folder, name and e-mail address are checked apart.
CREATED_PYTHON_PAGE = """\
going to create a new package
package name: my_package
destination directory: /home/user/ros2_ws/src
package format: 3
version: 0.0.0
description: TODO: Package description
maintainer: ['<name> <email>']
licenses: ['Apache-2.0']
build type: ament_python
dependencies: []
node_name: my_node
creating folder ./my_package
creating ./my_package/package.xml
creating source folder
creating folder ./my_package/my_package
creating ./my_package/setup.py
creating ./my_package/setup.cfg
creating folder ./my_package/resource
creating ./my_package/resource/my_package
creating ./my_package/my_package/__init__.py
creating folder ./my_package/test
creating ./my_package/test/test_copyright.py
creating ./my_package/test/test_flake8.py
creating ./my_package/test/test_pep257.py
creating ./my_package/my_package/my_node.py
"""
CREATED_CMAKE_PAGE = """\
going to create a new package
package name: my_package
destination directory: /home/user/ros2_ws/src
package format: 3
version: 0.0.0
description: TODO: Package description
maintainer: ['<name> <email>']
licenses: ['Apache-2.0']
build type: ament_cmake
dependencies: []
node_name: my_node
creating folder ./my_package
creating ./my_package/package.xml
creating source and include folder
creating folder ./my_package/src
creating folder ./my_package/include/my_package
creating ./my_package/CMakeLists.txt
creating ./my_package/src/my_node.cpp
"""
LEARNER_LINES = ("destination directory: ", "maintainer: ")


def create(tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    """`ros2 pkg create ARGS` typed in tmp_path (the workspace's src/)."""
    result = tool("ros2", "pkg", "create", *args, cwd=str(tmp_path))
    assert "Traceback" not in result.stderr
    return result


def assert_printed_as_the_page(printed: str, page: str, folder: Path) -> None:
    def general(text: str) -> list[str]:
        return [line for line in text.splitlines() if not line.startswith(LEARNER_LINES)]

    assert general(printed) == general(page)
    lines = printed.splitlines()
    assert lines[2] == f"destination directory: {folder}"
    assert lines[6].startswith("maintainer: ['") and lines[6].endswith(">']")


def test_executables_of_turtlesim_as_the_page():
    assert ok("ros2", "pkg", "executables", "turtlesim") == TURTLESIM_EXECUTABLES


def test_executables_of_every_package_and_their_paths():
    listed = ok("ros2", "pkg", "executables").splitlines()
    assert listed == sorted(listed, key=lambda line: line.split()[0])
    assert set(TURTLESIM_EXECUTABLES.splitlines()) <= set(listed)
    assert "ros_tutorials_topic topic_publisher" in listed
    paths = ok("ros2", "pkg", "executables", "turtlesim", "--full-path").splitlines()
    assert [Path(path).name for path in paths] == [
        line.split()[1] for line in TURTLESIM_EXECUTABLES.splitlines()
    ]
    assert all(os.access(path, os.X_OK) for path in paths)


def test_list_prefix_and_xml():
    packages = ok("ros2", "pkg", "list").splitlines()
    assert packages == sorted(packages)
    assert {"turtlesim", "std_msgs", "geometry_msgs", "ros_tutorials_topic"} <= set(packages)
    prefix = Path(ok("ros2", "pkg", "prefix", "turtlesim").strip())
    share = Path(ok("ros2", "pkg", "prefix", "--share", "turtlesim").strip())
    assert share == prefix / "share" / "turtlesim"
    assert (prefix / "share" / "ament_index" / "resource_index" / "packages" / "turtlesim").exists()
    assert ok("ros2", "pkg", "xml", "turtlesim", "-t", "name") == "turtlesim\n"
    manifest = ok("ros2", "pkg", "xml", "std_msgs")
    assert manifest.startswith('<package format="3">') and "<name>std_msgs</name>" in manifest


@pytest.mark.parametrize(
    "args,message",
    [
        (("prefix", "nope_pkg"), "error: Package 'nope_pkg' not found"),
        (("prefix", "--share", "nope_pkg"), "error: Package 'nope_pkg' not found"),
        (("executables", "nope_pkg"), "error: Package 'nope_pkg' not found"),
        (("xml", "nope_pkg"), "error: Package 'nope_pkg' not found"),
        (("xml", "turtlesim", "-t", "nope"), "error: XML tag not found"),
    ],
)
def test_errors_are_one_line(args, message):
    assert fails("ros2", "pkg", *args) == message


def test_create_ament_python_as_the_page(tmp_path):
    result = create(
        tmp_path, "--build-type", "ament_python", "--license", "Apache-2.0",
        "--node-name", "my_node", "my_package",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert_printed_as_the_page(result.stdout, CREATED_PYTHON_PAGE, tmp_path)
    package = tmp_path / "my_package"
    # The page's `ls`, and the LICENSE ros2pkg writes for a license it knows.
    assert sorted(path.name for path in package.iterdir()) == [
        "LICENSE", "my_package", "package.xml", "resource", "setup.cfg", "setup.py", "test",
    ]  # fmt: skip
    assert "Apache License" in (package / "LICENSE").read_text()
    manifest = parse_package(str(package / "package.xml"))
    assert manifest.name == "my_package" and manifest.version == "0.0.0"
    assert manifest.package_format == 3 and manifest.get_build_type() == "ament_python"
    assert manifest.licenses == ["Apache-2.0"]
    assert manifest.description == "TODO: Package description"
    assert [str(dep) for dep in manifest.test_depends] == [
        "ament_copyright", "ament_flake8", "ament_pep257", "python3-pytest",
    ]  # fmt: skip
    node = subprocess.run(
        [sys.executable, str(package / "my_package" / "my_node.py")],
        capture_output=True, text=True, timeout=30, check=True,
    )  # fmt: skip
    assert node.stdout == "Hi from my_package.\n"
    setup = (package / "setup.py").read_text()
    assert "'my_node = my_package.my_node:main'" in setup
    compile(setup, "setup.py", "exec")
    assert (package / "setup.cfg").read_text() == (
        "[develop]\nscript_dir=$base/lib/my_package\n"
        "[install]\ninstall_scripts=$base/lib/my_package\n"
    )
    assert (package / "resource" / "my_package").read_text() == ""


def test_create_ament_cmake_as_the_page(tmp_path):
    result = create(
        tmp_path, "--build-type", "ament_cmake", "--license", "Apache-2.0",
        "--node-name", "my_node", "my_package",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert_printed_as_the_page(result.stdout, CREATED_CMAKE_PAGE, tmp_path)
    package = tmp_path / "my_package"
    manifest = parse_package(str(package / "package.xml"))
    assert manifest.get_build_type() == "ament_cmake"
    assert [str(dep) for dep in manifest.buildtool_depends] == ["ament_cmake"]
    cmake = (package / "CMakeLists.txt").read_text()
    assert "project(my_package)" in cmake and "add_executable(my_node src/my_node.cpp)" in cmake
    assert (
        'printf("hello world my_package package\\n");'
        in (package / "src" / "my_node.cpp").read_text()
    )
    assert (package / "include" / "my_package").is_dir()


def test_create_with_every_option(tmp_path):
    result = create(
        tmp_path, "robot_pkg", "--build-type", "ament_python",
        "--destination-directory", "src", "--license", "MIT",
        "--maintainer-name", "Ada", "--maintainer-email", "ada@example.com",
        "--description", "A robot", "--library-name", "robot_lib",
        "--dependencies", "rclpy", "std_msgs",
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert f"destination directory: {tmp_path / 'src'}" in lines
    assert "maintainer: ['Ada <ada@example.com>']" in lines
    assert "dependencies: ['rclpy', 'std_msgs']" in lines
    assert "library_name: robot_lib" in lines
    assert "creating src/robot_pkg/robot_pkg/robot_lib/__init__.py" in lines
    manifest = parse_package(str(tmp_path / "src" / "robot_pkg" / "package.xml"))
    assert [str(dep) for dep in manifest.build_depends] == ["rclpy", "std_msgs"]
    assert [str(dep) for dep in manifest.exec_depends] == ["rclpy", "std_msgs"]
    assert manifest.maintainers[0].email == "ada@example.com"
    assert manifest.description == "A robot" and manifest.licenses == ["MIT"]
    license_text = (tmp_path / "src" / "robot_pkg" / "LICENSE").read_text()
    assert license_text == (Path(ros2cmd.__file__).parent / "licenses" / "MIT.txt").read_text()


def test_create_refuses_what_ros2pkg_refuses(tmp_path):
    (tmp_path / "my_package").mkdir()
    line = fails("ros2", "pkg", "create", "--destination-directory", str(tmp_path), "my_package")
    assert line.startswith("error: Aborted! The directory already exists: ")
    assert "can't be named 'test'" in fails(
        "ros2", "pkg", "create", "--build-type", "ament_python", "--destination-directory",
        str(tmp_path), "test",
    )  # fmt: skip
    usage = tool("ros2", "pkg", "create", "--build-type", "make", "x", cwd=str(tmp_path))
    assert usage.returncode == 2 and "invalid choice: 'make'" in usage.stderr
    assert sorted(path.name for path in tmp_path.iterdir()) == ["my_package"]
    unknown = create(tmp_path, "other_pkg", "--license", "Custom")
    assert unknown.returncode == 0
    assert "[WARNING]: Unknown license 'Custom'." in unknown.stdout
    assert not (tmp_path / "other_pkg" / "LICENSE").exists()


def _setup_keywords(setup_py: Path) -> dict[str, object]:
    """The literal keyword values of setup.py's setup(...) call, as Python reads them."""
    tree = ast.parse(setup_py.read_text())
    call = next(
        node
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and getattr(node.func, "id", "") == "setup"
    )
    return {
        keyword.arg: ast.literal_eval(keyword.value)
        for keyword in call.keywords
        if isinstance(keyword.value, ast.Constant)
    }


def test_create_escapes_every_value_it_writes(tmp_path):
    """ros2pkg's templates paste the values in as they are: `--description
    "</description><evil/>"` makes a package.xml no XML reader takes. Here each value is
    escaped for its file, and reads back as typed."""
    description = "</description><evil/> & a 'quote' \\ \"too\""
    name = 'O\'Brien & <Co> "Ltd"'
    license_ = "Apache-2.0 </license>"
    for build_type in ("ament_python", "ament_cmake"):
        package = f"n5_{build_type}"
        result = create(
            tmp_path, package, "--build-type", build_type, "--description", description,
            "--maintainer-name", name, "--maintainer-email", "ob@example.com",
            "--license", license_, "--node-name", "node",
        )  # fmt: skip
        assert result.returncode == 0, result.stderr
        manifest = parse_package(str(tmp_path / package / "package.xml"))  # as colcon reads
        read = ElementTree.parse(tmp_path / package / "package.xml").getroot()
        assert read.findtext("description") == description  # catkin_pkg keeps it as XML
        assert manifest.maintainers[0].name == name
        assert manifest.licenses == [license_]
        assert "<evil/>" not in (tmp_path / package / "package.xml").read_text()
    keywords = _setup_keywords(tmp_path / "n5_ament_python" / "setup.py")
    assert keywords["description"] == description
    assert keywords["maintainer"] == name
    assert keywords["license"] == license_


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ("--description", "two\nlines"),
            "error: --description cannot be written into package.xml: it holds the character "
            "U+000A (a control character, or bytes that are not UTF-8)",
        ),
        (
            ("--dependencies", "rclcpp) execute_process(COMMAND touch pwned"),
            "error: --dependencies 'rclcpp) execute_process(COMMAND touch pwned' is not a "
            "package name: letters, digits and '_', '-', '.', '+', starting with a letter or "
            "digit",
        ),
        (
            ("--maintainer-email", 'ob"@example.com'),
            'error: cannot create the package: Invalid email "ob"@example.com" for person "ada"',
        ),
        (
            ("--description", ""),
            "error: cannot create the package: Package description must not be empty",
        ),
        (
            ("--dependencies", "n6"),
            'error: cannot create the package: The package "n6" must not "build_depend" on a '
            "package with the same name as this package",
        ),
    ],
)
def test_create_refuses_what_cannot_be_written_safely(tmp_path, args, message):
    """One line, and nothing written: not a package colcon would build wrong, or fail on."""
    assert fails(
        "ros2", "pkg", "create", "--destination-directory", str(tmp_path),
        "--maintainer-name", "ada", "n6", *args,
    ) == message  # fmt: skip
    assert list(tmp_path.iterdir()) == []
