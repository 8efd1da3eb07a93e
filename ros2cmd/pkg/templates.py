"""The files `ros2 pkg create` writes, as ros2pkg's templates write them (package.xml,
setup.py, setup.cfg, the linter tests, the node; CMakeLists.txt and the C++ sources for
ament_cmake), every value escaped for the file it goes into (XML in package.xml, a Python
string in setup.py)."""

from __future__ import annotations

from dataclasses import dataclass, field


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
    from xml.sax.saxutils import escape, quoteattr  # urllib, http, ssl: not to build the parser

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
