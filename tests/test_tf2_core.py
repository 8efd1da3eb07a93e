"""tf2's core (tf2_py.BufferCore) against tf2's own test cases (geometry2, jazzy: tf2/test,
tf2_py/test) and against hand computations: chains, interpolation and slerp, time travel,
Time() as the latest common time, the exceptions and their messages, the 10 s cache, bad data
refused with tf2's line and no exception, memory bounded by the cache."""

from __future__ import annotations

import math

import pytest
from geometry_msgs.msg import TransformStamped
from rclpy.duration import Duration
from rclpy.time import Time

from tf2_py import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from tf2_py.time_cache import TimeCache, slerp


def stamped(parent: str, child: str, seconds: float = 0.0, xyz=(0.0, 0.0, 0.0), xyzw=None):
    message = TransformStamped()
    message.header.frame_id = parent
    message.child_frame_id = child
    message.header.stamp = Time(nanoseconds=round(seconds * 1e9)).to_msg()
    t, r = message.transform.translation, message.transform.rotation
    t.x, t.y, t.z = (float(v) for v in xyz)
    r.x, r.y, r.z, r.w = (0.0, 0.0, 0.0, 1.0) if xyzw is None else (float(v) for v in xyzw)
    return message


def yaw(angle: float) -> tuple[float, float, float, float]:
    return (0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2))


def at(seconds: float) -> Time:
    return Time(nanoseconds=round(seconds * 1e9))


def translation(message: TransformStamped) -> tuple[float, float, float]:
    t = message.transform.translation
    return (t.x, t.y, t.z)


def rotation(message: TransformStamped) -> tuple[float, float, float, float]:
    r = message.transform.rotation
    return (r.x, r.y, r.z, r.w)


# -- tf2/test/simple_tf2_core.cpp, tf2_py/test/test_buffer_core.py ----------------------------


def test_set_transform_refuses_what_tf2_refuses(capfd):
    core = BufferCore()
    core.set_transform(TransformStamped(), "authority1")  # no frames, w = 0
    core.set_transform(stamped("foo", "child", 1, xyzw=(0, 0, 0, 0)), "authority1")
    assert core._getFrameStrings() == []
    err = capfd.readouterr().err
    assert 'TF_SELF_TRANSFORM: Ignoring transform from authority "authority1"' in err
    assert "TF_NO_CHILD_FRAME_ID" in err and "TF_NO_FRAME_ID" in err
    assert (
        'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "child" from '
        'authority "authority1" because of an invalid quaternion in the transform '
        "(0.000000 0.000000 0.000000 0.000000)"
    ) in err
    assert core.set_transform(stamped("foo", "child", 1), "authority1") is None  # tf2_py's
    assert core._frameExists("child") and core._frameExists("foo")


def test_lookup_exceptions_and_their_messages():
    core = BufferCore()
    with pytest.raises(LookupException):
        core.lookup_transform_core("a", "b", at(1))
    assert core.can_transform_core("a", "b", at(1))[0] is False
    core.set_transform(stamped("foo", "child", 1), "authority1")
    with pytest.raises(LookupException) as error:
        core.lookup_transform_core("foo", "bar", at(1))
    message = '"bar" passed to lookupTransform argument source_frame does not exist. '
    assert str(error.value) == message
    with pytest.raises(LookupException) as error:
        core.lookup_transform_core("turtle2", "foo", Time())
    assert str(error.value) == (
        '"turtle2" passed to lookupTransform argument target_frame does not exist. '
    )
    assert core.can_transform_core("foo", "bar", at(1)) == (
        False,
        'Invalid frame ID "bar" passed to canTransform argument source_frame - '
        "frame does not exist",
    )
    with pytest.raises(InvalidArgumentException, match="in tf2 frame_ids cannot be empty"):
        core.lookup_transform_core("", "foo", Time())
    with pytest.raises(InvalidArgumentException, match="cannot start with a '/'"):
        core.lookup_transform_core("/foo", "child", Time())
    assert issubclass(LookupException, TransformException)


def test_extrapolation_backward_and_forward():
    core = BufferCore()
    core.set_transform(stamped("foo", "bar", 2), "authority1")
    core.lookup_transform_core("foo", "bar", at(2))
    with pytest.raises(ExtrapolationException) as error:
        core.lookup_transform_core("foo", "bar", at(4))
    assert str(error.value) == (
        "Lookup would require extrapolation at time 4.000000, but only time 2.000000 is in the "
        "buffer, when looking up transform from frame [bar] to frame [foo]"
    )
    core.set_transform(stamped("foo", "bar", 3), "authority1")
    with pytest.raises(ExtrapolationException) as error:
        core.lookup_transform_core("foo", "bar", at(1))
    assert str(error.value) == (
        "Lookup would require extrapolation into the past.  Requested time 1.000000 but the "
        "earliest data is at time 2.000000, when looking up transform from frame [bar] to "
        "frame [foo]"
    )
    with pytest.raises(ExtrapolationException) as error:
        core.lookup_transform_core("foo", "bar", at(4))
    assert str(error.value) == (
        "Lookup would require extrapolation into the future.  Requested time 4.000000 but the "
        "latest data is at time 3.000000, when looking up transform from frame [bar] to "
        "frame [foo]"
    )
    # tf2_py's test_can_transform_core_fail/_pass: the message says which way.
    possible, message = core.can_transform_core("bar", "foo", at(3.5))
    assert not possible and "extrapolation into the future" in message
    assert core.can_transform_core("bar", "foo", at(2.5)) == (True, "")


def test_static_transforms_hold_at_every_time_and_survive_clear():
    core = BufferCore()
    core.set_transform(stamped("foo", "bar", 1), "authority1")
    core.clear()
    core.set_transform_static(stamped("foo", "bar", 1), "authority1")
    assert core.can_transform_core("foo", "bar", at(2))[0]
    looked = core.lookup_transform_core("foo", "bar", at(2))
    assert looked.header.stamp == at(2).to_msg()
    core.clear()
    assert core.can_transform_core("foo", "bar", at(1000))[0]
    # A dynamic frame loses its data on clear(): tf2_py's test_clear.
    core.set_transform(stamped("bar", "baz", 0), "unittest")
    assert core.can_transform_core("baz", "bar", Time())[0]
    core.clear()
    assert not core.can_transform_core("baz", "bar", Time())[0]


def test_lookup_returns_the_transform_as_set():
    core = BufferCore()
    sent = stamped("bar", "foo", 0, xyz=(2, 0, 0))
    core.set_transform(sent, "unittest")
    assert core.lookup_transform_core(target_frame="bar", source_frame="foo", time=Time()) == sent


def test_latest_common_time():
    core = BufferCore()
    for seconds in (0, 1, 0.5):
        core.set_transform(stamped("bar", "foo", seconds, xyz=(2, 0, 0)), "unittest")
    assert core.get_latest_common_time("bar", "foo") == Time(seconds=1)
    # Two branches: the oldest of the newest stamps on the way wins.
    core.set_transform(stamped("bar", "baz", 0.25), "unittest")
    core.set_transform(stamped("bar", "baz", 0.75), "unittest")
    assert core.get_latest_common_time("foo", "baz") == Time(seconds=0.75)
    assert core.lookup_transform_core("foo", "baz", Time()).header.stamp == at(0.75).to_msg()
    with pytest.raises(TransformException):
        core.get_latest_common_time("foo", "nothing")


# -- chains and interpolation, by hand --------------------------------------------------------


def tree() -> BufferCore:
    """world -> base (x+1, yaw 90 degrees) -> arm (x+2); world -> cam (y+3)."""
    core = BufferCore()
    for seconds in (1, 2):
        core.set_transform(stamped("world", "base", seconds, (1, 0, 0), yaw(math.pi / 2)), "t")
        core.set_transform(stamped("base", "arm", seconds, (2, 0, 0)), "t")
        core.set_transform(stamped("world", "cam", seconds, (0, 3, 0)), "t")
    return core


def test_a_chain_through_the_common_parent():
    core = tree()
    # arm's origin in world: base's yaw turns arm's x+2 into y+2, then base's x+1.
    assert translation(core.lookup_transform_core("world", "arm", Time())) == pytest.approx(
        (1, 2, 0)
    )
    # and in cam: 3 less in y.
    looked = core.lookup_transform_core("cam", "arm", Time())
    assert translation(looked) == pytest.approx((1, -1, 0))
    assert rotation(looked) == pytest.approx(yaw(math.pi / 2))
    # The inverse: world's origin seen from arm.
    back = core.lookup_transform_core("arm", "world", Time())
    assert translation(back) == pytest.approx((-2, 1, 0))
    assert rotation(back) == pytest.approx(yaw(-math.pi / 2))
    # The chain as tf2's walk prunes it (what tf2_monitor prints): the page's "Chain is:
    # turtle1" for two turtles under world.
    assert core._chain("cam", Time(), "arm", Time(), "cam") == ["arm", "cam"]
    assert core._chain("cam", Time(), "base", Time(), "cam") == ["cam"]


def test_interpolation_is_linear_in_translation_and_slerp_in_rotation():
    core = BufferCore()
    core.set_transform(stamped("world", "turtle", 10, (0, 0, 0), yaw(0.0)), "t")
    core.set_transform(stamped("world", "turtle", 12, (4, -2, 1), yaw(math.pi / 2)), "t")
    looked = core.lookup_transform_core("world", "turtle", at(10.5))
    assert translation(looked) == pytest.approx((1, -0.5, 0.25))
    assert rotation(looked) == pytest.approx(yaw(math.pi / 8))  # a quarter of the angle
    assert looked.header.stamp == at(10.5).to_msg()
    # The shorter way round, whichever sign the second quaternion has.
    flipped = tuple(-v for v in yaw(math.pi / 2))
    assert slerp(yaw(0.0), flipped, 0.5) == pytest.approx(yaw(math.pi / 4))


def test_time_travel_through_a_fixed_frame():
    # The "Time travel" page: where was turtle2 five seconds ago, seen from turtle1 now.
    core = BufferCore()
    core.set_transform(stamped("world", "turtle1", 0, (0, 0, 0)), "t")
    core.set_transform(stamped("world", "turtle1", 10, (5, 0, 0)), "t")
    core.set_transform(stamped("world", "turtle2", 0, (0, 1, 0)), "t")
    core.set_transform(stamped("world", "turtle2", 10, (0, 11, 0)), "t")
    looked = core.lookup_transform_full_core("turtle1", at(10), "turtle2", at(5), "world")
    # turtle2 at 5 s: (0, 6, 0) in world; turtle1 at 10 s: (5, 0, 0).
    assert translation(looked) == pytest.approx((-5, 6, 0))
    assert looked.header.stamp == at(10).to_msg()
    assert core.can_transform_full_core("turtle1", at(10), "turtle2", at(5), "world") == (True, "")
    possible, message = core.can_transform_full_core("turtle1", at(10), "turtle2", at(20), "world")
    assert not possible and "extrapolation into the future" in message


def test_unconnected_trees_and_loops():
    core = BufferCore()
    core.set_transform(stamped("a", "b", 1), "t")
    core.set_transform(stamped("c", "d", 1), "t")
    with pytest.raises(ConnectivityException) as error:
        core.lookup_transform_core("b", "d", Time())
    assert str(error.value) == (
        "Could not find a connection between 'b' and 'd' because they are not part of the same "
        "tree.Tf has two or more unconnected trees."
    )
    # A loop: x -> y -> z -> x. A lookup fails with tf2's message, nothing hangs.
    loop = BufferCore()
    for parent, child in (("x", "y"), ("y", "z"), ("z", "x")):
        loop.set_transform(stamped(parent, child, 1), "t")
    loop.set_transform(stamped("w", "v", 1), "t")
    with pytest.raises(LookupException) as error:
        loop.lookup_transform_core("v", "y", at(1))
    assert str(error.value).startswith("The tf tree is invalid because it contains a loop.\n")
    assert "Frame y exists with parent x." in str(error.value)


def test_a_frame_with_a_new_parent_uses_the_data_for_the_time():
    core = BufferCore()
    core.set_transform(stamped("a", "child", 1, (1, 0, 0)), "t")
    core.set_transform(stamped("b", "child", 2, (2, 0, 0)), "t")
    core.set_transform_static(stamped("root", "a", 0), "t")
    core.set_transform_static(stamped("root", "b", 0, (0, 10, 0)), "t")
    # Between 1 s and 2 s the older data holds (no interpolation across parents).
    assert translation(core.lookup_transform_core("root", "child", at(1.5))) == pytest.approx(
        (1, 0, 0)
    )
    assert translation(core.lookup_transform_core("root", "child", at(2))) == pytest.approx(
        (2, 10, 0)
    )
    assert "Frame child exists with parent b." in core.all_frames_as_string()


# -- the cache -------------------------------------------------------------------------------


def test_the_default_cache_keeps_ten_seconds():
    core = BufferCore()
    for second in range(31):
        core.set_transform(stamped("world", "turtle", second, (second, 0, 0)), "t")
    # As tf2, an insert first drops what is older than 10 s before the newest data so far.
    assert core.can_transform_core("world", "turtle", at(19.5))[0]
    possible, message = core.can_transform_core("world", "turtle", at(18.5))
    assert not possible and "earliest data is at time 19.000000" in message
    short = BufferCore(Duration(seconds=2))
    for second in range(10):
        short.set_transform(stamped("world", "turtle", second), "t")
    assert not short.can_transform_core("world", "turtle", at(5.5))[0]
    assert short.can_transform_core("world", "turtle", at(6))[0]


def test_old_data_is_refused_with_tf2s_warning(capfd):
    core = BufferCore()
    core.set_transform(stamped("world", "turtle", 100), "broadcaster")
    core.set_transform(stamped("world", "turtle", 50), "broadcaster")
    err = capfd.readouterr().err
    assert (
        "TF_OLD_DATA ignoring data from the past for frame turtle at time 50.000000 according "
        "to authority broadcaster"
    ) in err


def test_a_full_cache_keeps_its_window_as_old_entries_are_dropped():
    """At 100 Hz into a 1 s cache, over many times its length: every insert after the first
    second drops one entry, the pruned ones are removed in bulk, and the data reads back."""
    cache = TimeCache(max_storage=10**9)
    for step in range(5_000):
        cache.insert(step * 10**7, (1, (float(step), 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
        assert len(cache._stamps) <= 2 * len(cache) + 64
    assert len(cache) == 102  # 1 s before the previous newest, and the newest
    assert cache.get_data(0) == (4999 * 10**7, (1, (4999.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
    assert cache.get_data(4900 * 10**7 + 5 * 10**6)[1][1] == (4900.5, 0.0, 0.0)
    assert cache.oldest_stamp() == 4898 * 10**7


def test_memory_is_bounded_by_the_cache_length():
    cache = TimeCache(max_storage=10 * 10**9)
    entry = (1, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    for step in range(200_000):  # 10 kHz for 20 s
        cache.insert(step * 100_000, entry)
    assert len(cache) == 100_002  # 10 s before the previous newest, and the newest
    assert len(cache._stamps) <= 2 * len(cache)  # pruned entries are dropped in bulk
    core = BufferCore()
    for number in range(10_000):
        core.set_transform(stamped("world", f"frame{number}", 1), "t")
    assert len(core._getFrameStrings()) == 10_001
    assert translation(core.lookup_transform_core("frame9999", "frame0", Time())) == (0, 0, 0)


def test_nan_and_unnormalised_quaternions_warn_once_and_raise_nothing(capfd):
    core = BufferCore()
    for _ in range(100):
        core.set_transform(stamped("world", "bad", 1, (math.nan, 0, 0)), "t")
        core.set_transform(stamped("world", "skew", 1, xyzw=(0, 0, 0, 2)), "t")
    err = capfd.readouterr().err
    assert err.count('TF_NAN_INPUT: Ignoring transform for child_frame_id "bad"') == 1
    assert err.count("TF_DENORMALIZED_QUATERNION") == 1
    assert not core._frameExists("bad")
    # A quaternion near unit length is accepted and normalised.
    core.set_transform(stamped("world", "good", 1, xyzw=(0, 0, 0, 1.004)), "t")
    assert rotation(core.lookup_transform_core("world", "good", Time())) == (0, 0, 0, 1)


def test_all_frames_as_yaml():
    core = BufferCore()
    assert core.all_frames_as_yaml() == "[]"
    core.set_transform(stamped("world", "turtle1", 1), "broadcaster")
    core.set_transform(stamped("world", "turtle1", 2), "broadcaster")
    core.set_transform_static(stamped("world", "cam", 0), "static")
    assert core.all_frames_as_yaml() == (
        "turtle1: \n  parent: 'world'\n  broadcaster: 'broadcaster'\n  rate: 2.000\n"
        "  most_recent_transform: 2.000000\n  oldest_transform: 1.000000\n"
        "  buffer_length: 1.000\n"
        "cam: \n  parent: 'world'\n  broadcaster: 'static'\n  rate: 10000.000\n"
        "  most_recent_transform: 0.000000\n  oldest_transform: 0.000000\n"
        "  buffer_length: 0.000\n"
    )


# -- tf2/test/cache_unittest.cpp ---------------------------------------------------------------


def entry(parent: int, x: float = 0.0):
    return (parent, (x, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))


def test_cache_repeatability_in_either_insert_order():
    for order in (range(1, 100), range(99, 0, -1)):
        cache = TimeCache(max_storage=10 * 10**9)
        for step in order:
            cache.insert(step, entry(step, x=float(step)))
        for step in range(1, 100):
            stamp, (parent, translation, _) = cache.get_data(step)
            assert (stamp, parent, translation[0]) == (step, step, float(step))


def test_cache_zero_at_front_and_duplicate_entries():
    cache = TimeCache(max_storage=10 * 10**9)
    for step in range(1, 101):
        cache.insert(step, entry(step))
    assert cache.get_data(0) == (100, entry(100))  # 0: the newest
    cache.insert(101, entry(100))
    assert cache.get_data(0) == (101, entry(100))
    duplicates = TimeCache(max_storage=10 * 10**9)
    duplicates.insert(1, entry(3))
    duplicates.insert(1, entry(3))  # the very same: kept once
    assert len(duplicates) == 1


def test_cache_does_not_interpolate_across_a_new_parent():
    cache = TimeCache(max_storage=10 * 10**9)
    cache.insert(555, entry(4, x=1.5))
    cache.insert(655, entry(5, x=7.25))
    for offset in range(100):
        _, (parent, translation, _) = cache.get_data(555 + offset)
        assert (parent, translation[0]) == (4, 1.5)


def test_a_transformstamped_reads_as_any_object_with_its_fields():
    """rosidl's TransformStamped is read from its fields' slots, anything else through its
    attributes: the two give the same transform, and the slots are where rosidl keeps them."""
    from types import SimpleNamespace as Fields

    from tf2_py import buffer_core

    assert buffer_core._SLOTTED  # else every listener's callback takes the slower path
    message = stamped("/world", "/arm", 1.5, xyz=(1.0, -2.0, 3.0), xyzw=(0.0, 0.0, 0.6, 0.8))
    t, r = message.transform.translation, message.transform.rotation
    duck = Fields(
        header=Fields(stamp=Fields(sec=1, nanosec=500_000_000), frame_id="/world"),
        child_frame_id="/arm",
        transform=Fields(
            translation=Fields(x=t.x, y=t.y, z=t.z), rotation=Fields(x=r.x, y=r.y, z=r.z, w=r.w)
        ),
    )
    core = BufferCore()
    assert core._parsed(message, "a") == core._parsed(duck, "a")
    assert core._parsed(message, "a") == (
        "world", "arm", 1_500_000_000, (1.0, -2.0, 3.0), (0.0, 0.0, 0.6, 0.8)
    )  # fmt: skip
