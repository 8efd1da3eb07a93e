"""Register this project's packages in the ament index of this virtual environment.

colcon installs a ROS 2 Python package as: the ament index marker
share/ament_index/resource_index/packages/PKG, and share/PKG/ with its package.xml and data
(launch/, config/, urdf/, meshes/, rviz/). This does the same for every folder
ros_tutorials_*/ that has a package.xml (and for the stand-ins: every other top-level folder
with one, tf2_ros/ ...), the way `colcon build --symlink-install` does: share/PKG/package.xml
and its data folders are links to the source, so an edited or new launch file is used at once.
The Python code itself is installed by pip (editable), not copied to share/.

The interface packages in interfaces/ are installed by tools/build_interfaces.py (colcon copies
their files); their share/PKG/package.xml is replaced by a link to the source too, so
`rospack find` leads to the folder where a learner adds a .msg
(ros_tutorials_common/packages.py package_folder()). Entries this script made for packages
that no longer exist are removed.

xacro comes from PyPI as a Python distribution only (its `xacro` command), with no index entry.
It is registered as a ROS installation has it: the marker, share/xacro/package.xml, and the
command as lib/xacro/xacro (`ros2 run xacro xacro`) and share/xacro/xacro (ROS 1's
`$(find xacro)/xacro`), both links to the installed script.

    .venv/bin/python tools/register_packages.py [--prefix DIR]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import shutil
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
INTERFACES = ROOT / "interfaces"
# What the packages' setup.py would list in data_files: launch files, parameters, and the URDF
# pages' models, meshes and 3D-view configurations (urdf_tutorial, turtle_tf2_py's rviz/).
DATA_FOLDERS = ("launch", "config", "urdf", "meshes", "rviz")
INDEX = Path("share", "ament_index", "resource_index", "packages")
# ROS 2 Python packages PyPI lacks, which this project provides (ament_copyright, rosbag2_py,
# tf2_ros, ...): every other top-level folder with a package.xml. Their executables are their
# modules with a main() (ros_tutorials_common/packages.py), as the tutorial packages' are.
STAND_INS = sorted(
    path for path in ROOT.glob("*/package.xml") if not path.parent.name.startswith("ros_tutorials_")
)


def manifest_name(manifest: Path) -> str:
    """The <name> of a package.xml; it must match its folder, as colcon requires."""
    try:
        name = ElementTree.parse(manifest).getroot().findtext("name", "").strip()
    except ElementTree.ParseError as error:
        sys.exit(f"register_packages: {manifest}: not valid XML: {error}")
    if name != manifest.parent.name:
        sys.exit(f"register_packages: {manifest}: <name> {name!r} is not the folder's name")
    return name


def link(path: Path, target: Path) -> None:
    """Make PATH a symbolic link to TARGET, whatever was there."""
    if path.is_symlink() or path.is_file():
        path.unlink()
    elif path.is_dir():
        shutil.rmtree(path)
    path.symlink_to(target)


def register(prefix: Path, source: Path) -> None:
    share = prefix / "share" / source.name
    share.mkdir(parents=True, exist_ok=True)
    link(share / "package.xml", source / "package.xml")
    for folder in DATA_FOLDERS:
        if (source / folder).is_dir():
            link(share / folder, source / folder)
        elif (share / folder).is_symlink():
            (share / folder).unlink()
    (prefix / INDEX).mkdir(parents=True, exist_ok=True)
    (prefix / INDEX / source.name).touch()  # the marker's content is empty, as colcon's


XACRO_MANIFEST = """<?xml version="1.0"?>
<package format="3">
  <name>xacro</name>
  <version>{version}</version>
  <description>Xacro (XML Macros): the xacro distribution from PyPI</description>
  <maintainer email="rhaschke@techfak.uni-bielefeld.de">Robert Haschke</maintainer>
  <license>BSD-3-Clause</license>
  <export><build_type>ament_python</build_type></export>
</package>
"""


def register_xacro(prefix: Path) -> bool:
    """Put the PyPI xacro in the ament index; False if it is not installed here."""
    script = prefix / "bin" / "xacro"
    try:
        version = importlib.metadata.version("xacro")
    except importlib.metadata.PackageNotFoundError:
        return False
    if not script.is_file():
        return False
    share = prefix / "share" / "xacro"
    share.mkdir(parents=True, exist_ok=True)
    (share / "package.xml").write_text(XACRO_MANIFEST.format(version=version))
    link(share / "xacro", script)
    (prefix / "lib" / "xacro").mkdir(parents=True, exist_ok=True)
    link(prefix / "lib" / "xacro" / "xacro", script)
    (prefix / INDEX).mkdir(parents=True, exist_ok=True)
    (prefix / INDEX / "xacro").touch()
    return True


def remove_stale(prefix: Path) -> None:
    """Unregister packages whose share/PKG/package.xml links into this project to nothing."""
    index = prefix / INDEX
    for marker in sorted(index.iterdir()) if index.is_dir() else []:
        share = prefix / "share" / marker.name
        manifest = share / "package.xml"
        target = manifest.readlink() if manifest.is_symlink() else None
        if target is not None and target.is_relative_to(ROOT) and not target.is_file():
            for entry in share.iterdir():
                if entry.is_symlink():
                    entry.unlink()
            if not any(share.iterdir()):
                share.rmdir()
            marker.unlink()
            print(f"{marker.name} removed from the ament index in {prefix}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--prefix", type=Path, default=Path(sys.prefix), help="default: the venv")
    prefix = parser.parse_args(argv).prefix.absolute()
    remove_stale(prefix)
    for manifest in sorted([*ROOT.glob("ros_tutorials_*/package.xml"), *STAND_INS]):
        name = manifest_name(manifest)
        register(prefix, manifest.parent)
        print(f"{name} registered in the ament index in {prefix}")
    for manifest in sorted(INTERFACES.glob("*/package.xml")):
        installed = prefix / "share" / manifest_name(manifest) / "package.xml"
        if installed.exists():  # built by tools/build_interfaces.py
            link(installed, manifest)
    if register_xacro(prefix):
        print(f"xacro registered in the ament index in {prefix}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
