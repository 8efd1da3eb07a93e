"""tf2's exceptions, by the names tf2_py gives them (``tf2_py.LookupException``, ...).

TransformException is the base of all; tf2_ros re-exports them (``from tf2_ros import
LookupException``), which is how the tutorials' listener catches ``TransformException``.
tf2's C++ core has Backward/Forward/NoData extrapolation errors too; tf2_py raises all three
as ExtrapolationException, so this does.
"""

from __future__ import annotations


class TransformException(Exception):
    """Any tf2 error."""


class ConnectivityException(TransformException):
    """The two frames are in trees that do not connect."""


class LookupException(TransformException):
    """A frame does not exist, or the tree has a loop."""


class ExtrapolationException(TransformException):
    """The time asked for is outside the data of a frame on the way."""


class InvalidArgumentException(TransformException):
    """A frame id that tf2 refuses: empty, or starting with '/'."""


class TimeoutException(TransformException):
    """A wait for a transform ran out of time."""
