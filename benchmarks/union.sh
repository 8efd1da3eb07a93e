#!/bin/sh
# The baseline of the launch benchmark: union.launch's four nodes started from a plain shell,
# each with the same ROS arguments the launcher gives them, and each in a session of its own
# as the launcher starts them (with the kernel's autogroup scheduling, a session is what CPU
# is shared between on a busy machine: in one session the four would share one share).
# Ctrl-C stops them all: with SIGTERM, because a non-interactive shell starts background jobs
# with SIGINT ignored.
py=${PYTHON:-python3}
pids=""
for ns in ns1 ns2; do
  for node in publisher subscriber; do
    setsid "$py" -m ros_tutorials_topic.$node --ros-args -r __node:=topic_$node -r __ns:=/$ns &
    pids="$pids $!"
  done
done
trap 'kill -TERM $pids; wait' INT TERM
wait
