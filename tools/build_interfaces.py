"""Build the interface packages in interfaces/ into this virtual environment with colcon.

Each folder of interfaces/ with a package.xml is one ROS 2 interface package
(ros_tutorials_interfaces, turtlesim; example_interfaces and action_tutorials_interfaces as
ROS 2 Jazzy ships them, unchanged, for the tutorials' code). They are built the way a learner
builds their own: the real `colcon build`, the same toolchain file
(interfaces/cmake/colcon_toolchain.cmake: the wheels' exported targets repaired, unity builds of
the type-support libraries) and the same colcon defaults (a failure is one line), here with
`--merge-install` into sys.prefix: the Python packages land in site-packages and the
type-support libraries in sys.prefix/lib, where the wheels' loader already looks. The build
trees (build/interfaces/PKG) are kept, so a changed definition rebuilds only what changed;
colcon's logs are in build/log/. It builds with Ninja when the set-up installed it.

What this adds to colcon:
- a message removed from a package is removed from the prefix too: rosidl does not regenerate
  for a removal, so that package is built again from a fresh tree, and the files its previous
  install put in the prefix that this one no longer does are deleted;
- the prefix keeps its own setup files (tools/ros_environment.py: sourcing them activates this
  environment); the ones colcon writes at the top of an install base are taken away again.

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
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCES = ROOT / "interfaces"
BUILD = ROOT / "build" / "interfaces"
# What the learner's `colcon build` gets from the activated environment too (the wheels'
# exported targets repaired, unity builds, no linters); see the file.
TOOLCHAIN = SOURCES / "cmake" / "colcon_toolchain.cmake"
# colcon's defaults in the activated environment (a failed package is one line); used here
# too, and not the user's own ~/.colcon/defaults.yaml, so the set-up builds the same everywhere.
COLCON_DEFAULTS = ROOT / "ros_tutorials_common" / "config" / "colcon_defaults.yaml"
# What colcon writes at the top of a merged install base, whatever its shell extensions.
COLCON_PREFIX_FILES = ("local_setup.*", "setup.*", "_local_setup_util*", "COLCON_IGNORE")
COLCON_PREFIX_FILES += (".colcon_install_layout",)


def interface_packages(sources: Path = SOURCES) -> list[Path]:
    """The interface packages in interfaces/ (folders holding a package.xml), by name."""
    return sorted(path.parent for path in sources.glob("*/package.xml"))


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


def clear(build: Path) -> None:
    """Empty a build tree (colcon's files in it too: it is configured again)."""
    for child in build.iterdir():
        if child.is_dir():
            shutil.rmtree(child)
        else:
            child.unlink()


def listed_interfaces(build: Path, name: str) -> set[str]:
    """The interface files the package's last configure listed (its ament index entry)."""
    index = build / "ament_cmake_index" / "share" / "ament_index" / "resource_index"
    entry = index / "rosidl_interfaces" / name
    return set(entry.read_text().split()) if entry.is_file() else set()


def installed_files(build: Path) -> set[str]:
    manifest = build / "install_manifest.txt"
    return set(manifest.read_text().splitlines()) if manifest.is_file() else set()


def colcon_files(prefix: Path) -> dict[str, bytes]:
    """The files colcon writes at the top of an install base that PREFIX has now."""
    found = (path for pattern in COLCON_PREFIX_FILES for path in prefix.glob(pattern))
    return {path.name: path.read_bytes() for path in found if path.is_file()}


def restore(prefix: Path, before: dict[str, bytes]) -> None:
    """Put the prefix's own top-level files back as they were before colcon ran."""
    for name, content in colcon_files(prefix).items():
        if name not in before:
            (prefix / name).unlink()
        elif before[name] != content:
            (prefix / name).write_bytes(before[name])


def remove_stale(source: Path, build: Path, prefix: Path, installed_before: set[str]) -> None:
    """Delete what the package's previous install put in PREFIX that this one did not."""
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


def colcon_build(command: list[str], packages: list[str], env: dict[str, str]) -> int:
    selected = ["--packages-select", *packages] if packages else []
    # The arguments after --cmake-args (one of them starts with a dash) come last.
    at = command.index("--cmake-args")
    return subprocess.run([*command[:at], *selected, *command[at:]], env=env).returncode


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Build the interface packages with colcon.")
    parser.add_argument("--sources", type=Path, default=SOURCES, help="default: interfaces/")
    parser.add_argument("--prefix", type=Path, default=Path(sys.prefix), help="default: the venv")
    parser.add_argument("--build", type=Path, default=BUILD, help="default: build/interfaces/")
    options = parser.parse_args(argv)
    prefix, build_base = options.prefix.absolute(), options.build.absolute()
    prefix.mkdir(parents=True, exist_ok=True)
    # The underlay is this environment (the dependencies: builtin_interfaces, the
    # generators), as in a learner's activated shell; colcon adds the packages it builds.
    env = dict(os.environ)
    env["AMENT_PREFIX_PATH"] = sys.prefix
    env["CMAKE_PREFIX_PATH"] = sys.prefix
    env["PATH"] = f"{Path(sys.prefix) / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    env["CMAKE_TOOLCHAIN_FILE"] = str(TOOLCHAIN)
    env["COLCON_DEFAULTS_FILE"] = str(COLCON_DEFAULTS)
    # colcon gives make (and Ninja) `-j2 -l2` unless MAKEFLAGS has a -j: the load limit would
    # build one file at a time on a machine busy with anything else. Two jobs per package.
    jobs = str(os.cpu_count() or 2)
    env["MAKEFLAGS"] = f"-j{jobs}"
    env["CMAKE_BUILD_PARALLEL_LEVEL"] = jobs
    sources = interface_packages(options.sources)
    generator = cmake_generator()
    wanted = "Ninja" if generator else "Unix Makefiles"
    listed, installed = {}, {}
    for source in sources:
        build = build_base / source.name
        # A tree configured by another generator (Makefiles before the set-up had Ninja)
        # cannot be reconfigured by this one: start it afresh.
        if configured_generator(build) not in (None, wanted):
            clear(build)
        listed[source.name] = listed_interfaces(build, source.name)
        installed[source.name] = installed_files(build)
    colcon = [
        str(Path(sys.prefix) / "bin" / "colcon"),
        "--log-base",
        str(build_base.parent / "log"),
    ]
    colcon += ["build", "--merge-install", "--base-paths", str(options.sources.absolute())]
    colcon += ["--build-base", str(build_base), "--install-base", str(prefix)]
    colcon += ["--cmake-args", *generator, f"-DPython3_EXECUTABLE={sys.executable}"]
    kept = colcon_files(prefix)
    try:
        returncode = colcon_build(colcon, [], env)
        # A package whose configure lists fewer interfaces than before: afresh, once more.
        shrunk = [
            source
            for source in sources
            if listed[source.name] - listed_interfaces(build_base / source.name, source.name)
        ]
        for source in shrunk:
            print(f"{source.name}: an interface was removed, building it afresh", flush=True)
            clear(build_base / source.name)
        if shrunk and returncode == 0:
            returncode = colcon_build(colcon, [source.name for source in shrunk], env)
    finally:
        restore(prefix, kept)
    if returncode == 0:
        for source in sources:
            build = build_base / source.name
            remove_stale(source, build, prefix, installed[source.name])
    return returncode


if __name__ == "__main__":
    sys.exit(main())
