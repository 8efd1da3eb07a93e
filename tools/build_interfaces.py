"""Generate and install the interface packages in interfaces/ into this virtual environment.

Each folder of interfaces/ with a package.xml is one ROS 2 interface package
(ros_tutorials_interfaces, turtlesim; example_interfaces and action_tutorials_interfaces as
ROS 2 Jazzy ships them, unchanged, for the tutorials' code). This runs the real rosidl tool
chain from the ROS 2 Jazzy wheels through CMake on each, the way colcon would, and installs into
sys.prefix: the Python package lands in site-packages and the type-support libraries in
sys.prefix/lib, where the wheels' loader already looks. The build trees (build/interfaces/PKG)
are kept, so a changed definition rebuilds only what changed. It builds with Ninja when the
set-up installed it, and compiles each type-support library as one unit
(interfaces/cmake/unity_build.cmake, through interfaces/cmake/colcon_toolchain.cmake, which the
learner's colcon builds get too): half the CPU time, the same libraries (README: "What the
interface build costs").

    .venv/bin/python tools/build_interfaces.py
    .venv/bin/python tools/build_interfaces.py --sources DIR --prefix DIR --build DIR

The options build another folder of interface packages into another prefix (the test of
"Your own message" builds a copy there, leaving this environment as it is); the
dependencies (builtin_interfaces, the generators) still come from this environment.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ROOT / "interfaces"
BUILD = ROOT / "build" / "interfaces"
# What the learner's `colcon build` gets from the activated environment too (the wheels'
# exported targets repaired, unity builds, no linters); see the file.
TOOLCHAIN = SOURCES / "cmake" / "colcon_toolchain.cmake"


def interface_packages(sources: Path = SOURCES) -> list[Path]:
    """The interface packages in interfaces/ (folders holding a package.xml), by name."""
    return sorted(path.parent for path in sources.glob("*/package.xml"))


def dependencies(source: Path) -> set[str]:
    """The packages a package's package.xml names as dependencies of any kind."""
    root = ElementTree.parse(source / "package.xml").getroot()
    return {
        element.text.strip() for element in root if element.tag.endswith("depend") and element.text
    }


def find_cmake() -> str:
    """Prefer the CMake installed into the venv (from PyPI), then the system's."""
    venv_cmake = Path(sys.prefix) / "bin" / "cmake"
    if venv_cmake.exists():
        return str(venv_cmake)
    found = shutil.which("cmake")
    if found is None:
        sys.exit("build_interfaces: CMake not found; run 'make setup' or install CMake >= 3.22")
    return found


def cmake_generator() -> list[str]:
    """Ninja (the ninja wheel, installed by the set-up) when there is one, else CMake's default.

    Ninja runs the same commands as the Makefiles without their recursive make, dependency
    scanning (cmake -E cmake_depends) and progress reports.
    """
    venv_ninja = Path(sys.prefix) / "bin" / "ninja"
    ninja = str(venv_ninja) if venv_ninja.exists() else shutil.which("ninja")
    return ["-G", "Ninja", f"-DCMAKE_MAKE_PROGRAM={ninja}"] if ninja else []


def configured_generator(build: Path) -> str | None:
    """The CMake generator a build tree was configured with, if it was."""
    cache = build / "CMakeCache.txt"
    if cache.is_file():
        for line in cache.read_text().splitlines():
            if line.startswith("CMAKE_GENERATOR:INTERNAL="):
                return line.partition("=")[2]
    return None


def clear(build: Path, keep: Path) -> None:
    """Empty a build tree, keeping one file (the log being written)."""
    for child in build.iterdir():
        if child.is_dir():
            shutil.rmtree(child)
        elif child != keep:
            child.unlink()


def listed_interfaces(build: Path, name: str) -> set[str]:
    """The interface files the package's last configure listed (its ament index entry)."""
    index = build / "ament_cmake_index" / "share" / "ament_index" / "resource_index"
    entry = index / "rosidl_interfaces" / name
    return set(entry.read_text().split()) if entry.is_file() else set()


def installed_files(build: Path) -> set[str]:
    manifest = build / "install_manifest.txt"
    return set(manifest.read_text().splitlines()) if manifest.is_file() else set()


def build_package(
    source: Path, cmake: str, env: dict[str, str], prefix: Path, build_root: Path = BUILD
) -> bool:
    """Configure, build and install one interface package; False (log printed) on failure.

    A message removed from the package is removed from the prefix too: rosidl does not
    regenerate for a removal, so the build tree is started afresh, and files the previous
    install put in the prefix that this one no longer does are deleted.
    """
    build = build_root / source.name
    build.mkdir(parents=True, exist_ok=True)
    generator = cmake_generator()
    configure = [
        cmake,
        *generator,
        "-S",
        str(source),
        "-B",
        str(build),
        f"-DCMAKE_INSTALL_PREFIX={prefix}",
        f"-DCMAKE_PREFIX_PATH={env['CMAKE_PREFIX_PATH'].replace(os.pathsep, ';')}",
        f"-DPython3_EXECUTABLE={sys.executable}",
        f"-DCMAKE_TOOLCHAIN_FILE={TOOLCHAIN}",
        "-DBUILD_TESTING=OFF",
    ]
    log_path = build / "build.log"
    before = listed_interfaces(build, source.name)
    installed_before = installed_files(build)
    with log_path.open("w") as log:
        # A tree configured by another generator (Makefiles before the set-up had Ninja)
        # cannot be reconfigured by this one: start it afresh.
        wanted = "Ninja" if generator else "Unix Makefiles"
        if configured_generator(build) not in (None, wanted):
            log.write(f"configured for {configured_generator(build)}, not {wanted}: afresh\n")
            clear(build, log_path)

        def step(command: list[str]) -> bool:
            log.write(f"$ {' '.join(command)}\n")
            log.flush()
            if subprocess.run(command, env=env, stdout=log, stderr=subprocess.STDOUT).returncode:
                print(log_path.read_text()[-4000:], file=sys.stderr)
                print(
                    f"build_interfaces: {source.name}: step failed: {' '.join(command[:2])}; "
                    f"full log in {log_path}",
                    file=sys.stderr,
                )
                return False
            return True

        if not step(configure):
            return False
        removed = before - listed_interfaces(build, source.name)
        if removed:
            log.write(f"removed {' '.join(sorted(removed))}: building afresh\n")
            clear(build, log_path)
            if not step(configure):
                return False
        build_step = [cmake, "--build", str(build), "--parallel", str(os.cpu_count() or 2)]
        if not (step(build_step) and step([cmake, "--install", str(build)])):
            return False
    for stale in installed_before - installed_files(build):
        path = Path(stale)
        # share/PKG/package.xml, once tools/register_packages.py made it a link to the source,
        # is the source itself to CMake: it installs nothing there and leaves it out of the
        # manifest. That file is not stale.
        if path.resolve().is_relative_to(source.resolve()):
            continue
        if path.is_relative_to(prefix) and path.is_file():
            path.unlink()
            for compiled in path.parent.glob(f"__pycache__/{path.stem}.*.pyc"):
                compiled.unlink()
    return True


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Generate and install interface packages.")
    parser.add_argument("--sources", type=Path, default=SOURCES, help="default: interfaces/")
    parser.add_argument("--prefix", type=Path, default=Path(sys.prefix), help="default: the venv")
    parser.add_argument("--build", type=Path, default=BUILD, help="default: build/interfaces/")
    options = parser.parse_args(argv)
    prefix = options.prefix.absolute()
    # ament's resource index and CMake's package search start at the install prefix, then
    # look in this environment (the same place unless --prefix says otherwise).
    search = os.pathsep.join(dict.fromkeys([str(prefix), sys.prefix]))
    env = dict(os.environ)
    env["AMENT_PREFIX_PATH"] = search
    env["CMAKE_PREFIX_PATH"] = search
    env["PATH"] = f"{Path(sys.prefix) / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    cmake = find_cmake()
    remaining = interface_packages(options.sources)
    names = {source.name for source in remaining}
    built: set[str] = set()
    fixed = (cmake, env, prefix, options.build.absolute())  # build_package's other arguments
    # Two packages at a time, each one's dependencies among these first: rosidl's generators
    # and CMake's configure step are one process each, which leaves a core idle.
    with ThreadPoolExecutor(max_workers=2) as pool:
        while remaining:
            ready = [s for s in remaining if dependencies(s) & names <= built]
            if not ready:
                print(
                    "build_interfaces: the packages depend on each other in a circle",
                    file=sys.stderr,
                )
                return 1
            results = pool.map(build_package, ready, *[[x] * len(ready) for x in fixed])
            for source, result in zip(ready, list(results), strict=True):
                if not result:
                    return 1
                print(f"{source.name} generated and installed into {prefix}")
                built.add(source.name)
            remaining = [source for source in remaining if source not in ready]
    return 0


if __name__ == "__main__":
    sys.exit(main())
