"""`ros2 pkg xml PACKAGE [-t TAG]`: its package.xml (or one tag's text)."""

from __future__ import annotations

import argparse

from ros2cmd import completion
from ros2cmd.errors import ToolError
from ros2cmd.pkg.api import package_prefix

HELP = "Output the XML of the package manifest or a specific tag"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("package_name", help="The package name")
    completion.attach(parser, package_name=completion.package_names)
    parser.add_argument("-t", "--tag", help="The XML tag to output (e.g. 'version')")


def main(_graph: None, args: argparse.Namespace) -> None:
    import xml.etree.ElementTree as ElementTree

    name, tag = args.package_name, args.tag
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
