"""launch_yaml.Entity: launch_xml's Entity over the same parsed elements (launch_foundation/parse.py
reads a YAML launch file into them, with their lines)."""

from launch_xml.entity import Entity as _XMLEntity


class Entity(_XMLEntity):
    pass
